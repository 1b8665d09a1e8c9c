#include "poinsot/analysis/closed_form.hpp"

#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::analysis {

InertiaInvariants inertia_invariants(const Mat3& J) {
  require_finite("closed form: inertia J (kg·m²)", J);
  const double det = J.determinant();
  if (!(std::abs(det) > 0.0)) {
    throw InvalidInput(
        fmt::format("closed form: inertia J = {} kg·m² is singular (det = {}); expected an "
                    "invertible inertia tensor",
                    format_matrix(J), format_number(det)));
  }
  const double tr = J.trace();
  return {1.0 / det, 0.5 * tr, 0.5 * (tr * tr - (J * J).trace())};
}

Mat3 cayley_hamilton_residual(const Mat3& J) {
  const InertiaInvariants t = inertia_invariants(J);
  const Mat3 J2 = J * J;
  return Mat3::Identity() / t.tau0 - t.tau2 * J + 2.0 * t.tau1 * J2 - J2 * J;
}

namespace {

// ξij = J^i ξ0 J^j = (J^i ω) ⊗ (J^j ω): with the vectors w_i = J^i ω every ξij is one outer product.
struct Xi {
  Vec3 w[4];
  explicit Xi(const Mat3& J, const Vec3& omega) {
    w[0] = omega;
    for (int i = 1; i < 4; ++i)
      w[i] = J * w[i - 1];
  }
  Mat3 operator()(int i, int j) const { return w[i] * w[j].transpose(); }
};

}  // namespace

Mat3 omega_dot_hat_lemma1(const Mat3& J, const Vec3& omega_body) {
  const InertiaInvariants t = inertia_invariants(J);
  const Xi xi(J, omega_body);
  return t.tau0 * (xi(1, 2) - xi(2, 1));
}

Mat3 lambda_closed_form(const Mat3& J, const Vec3& omega_body, ClosedForm form) {
  require_finite("closed form: omega_body (rad/s)", omega_body);
  const InertiaInvariants t = inertia_invariants(J);
  const Xi xi(J, omega_body);
  const double eta0 = omega_body.squaredNorm();
  const Mat3 I = Mat3::Identity();
  const Mat3 eta01 = eta0 * J;
  const Mat3 head = t.tau1 * (xi(0, 0) - eta0 * I);
  switch (form) {
    case ClosedForm::property2:
      return head + eta01 - (xi(0, 1) + xi(1, 0)) +
             t.tau0 * J * (xi(1, 1) - t.tau1 * (xi(0, 1) + xi(1, 0)) + t.tau2 * xi(0, 0)) * J;
    case ClosedForm::eq38:
      return head + t.tau0 * t.tau1 * (xi(1, 2) - xi(2, 1)) - xi(0, 1) + eta01 -
             t.tau0 * (xi(1, 3) - xi(2, 2));
    case ClosedForm::symmetric:
      return head + eta01 + t.tau0 * xi(2, 2) - t.tau0 * t.tau1 * (xi(1, 2) + xi(2, 1)) -
             (xi(0, 1) + xi(1, 0)) + t.tau0 * t.tau2 * xi(1, 1);
  }
  throw InvalidInput("closed form: unknown form");
}

}  // namespace poinsot::analysis
