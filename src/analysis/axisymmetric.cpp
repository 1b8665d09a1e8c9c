#include "poinsot/analysis/axisymmetric.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::analysis {

Mat3 AxisymmetricInertia::inertia() const {
  return A * Mat3::Identity() + (C - A) * k * k.transpose();
}

std::optional<AxisymmetricInertia> detect_axisymmetry(const dynamics::RigidBody& body,
                                                      double relative_tolerance) {
  const Vec3& m = body.principal_moments();  // ascending
  const Mat3& axes = body.principal_axes();
  const double tol = relative_tolerance * m[2];
  const bool low = m[1] - m[0] <= tol;
  const bool high = m[2] - m[1] <= tol;
  if (low && high) {
    const double mean = m.sum() / 3.0;
    return AxisymmetricInertia{mean, mean, axes.col(2)};
  }
  if (low) return AxisymmetricInertia{0.5 * (m[0] + m[1]), m[2], axes.col(2)};
  if (high) return AxisymmetricInertia{0.5 * (m[1] + m[2]), m[0], axes.col(0)};
  return std::nullopt;
}

AxisymmetricLambda::AxisymmetricLambda(const AxisymmetricInertia& inertia, const Vec3& omega0_body, double t0,
                                       double relative_tolerance)
    : inertia_(inertia), omega0_(omega0_body), t0_(t0) {
  require_positive("axisymmetric body: A (kg·m²)", inertia.A, "kg·m²");
  require_positive("axisymmetric body: C (kg·m²)", inertia.C, "kg·m²");
  require_finite("axisymmetric body: axis k", inertia.k);
  require_finite("axisymmetric body: omega0 (rad/s)", omega0_body);
  require_finite("axisymmetric body: t0 (s)", t0);
  const double A = inertia.A;
  const double C = inertia.C;
  if (C > 2.0 * A * (1.0 + relative_tolerance)) {
    throw InvalidInput(
        fmt::format("axisymmetric body: A = {} kg·m², C = {} kg·m² violate the triangle "
                    "inequality 2A >= C (short by {}); expected A - C/2 = <k, K k> >= 0",
                    format_number(A), format_number(C), format_number(C - 2.0 * A)));
  }
  const double knorm = inertia.k.norm();
  if (!(knorm > 0.0)) {
    throw InvalidInput("axisymmetric body: axis k = (0, 0, 0); expected a non-zero vector");
  }
  inertia_.k = inertia.k / knorm;
  const Vec3& k = inertia_.k;
  const Vec3& w0 = omega0_;

  mu_ = k.dot(w0);
  eta0_ = w0.squaredNorm();
  const Vec3 perp = w0 - mu_ * k;
  r_ = perp.norm();
  const double speed = std::sqrt(eta0_);
  if (r_ > relative_tolerance * speed && r_ > 0.0) {
    n_ = perp / r_;
  } else {
    // Any unit vector ⟂ k: the coordinate axis least aligned with k, orthogonalised.
    int i = 0;
    k.cwiseAbs().minCoeff(&i);
    Vec3 e = Vec3::Zero();
    e[i] = 1.0;
    n_ = (e - k.dot(e) * k).normalized();
  }

  const double h = A - 0.5 * C;  // ⟨k, K k⟩ ≥ 0 (C9)
  const double a = -0.5 * C * mu_ * mu_;
  const double b = C / A * h * r_ * mu_;
  const double d = -h * r_ * r_;
  c1_ = -h * r_ * r_ - 0.5 * C * mu_ * mu_;
  c2_ = -0.5 * C * h * (1.0 - C / A) * (1.0 - C / A) * r_ * r_ * mu_ * mu_;
  Delta_ = (a - d) * (a - d) + 4.0 * b * b;  // = c1² + 4c2, a sum of squares
  lambda1_ = 0.5 * (c1_ - std::sqrt(Delta_));
  lambda2_ = lambda1_ < 0.0 ? -c2_ / lambda1_ : 0.5 * (c1_ + std::sqrt(Delta_));
  lambda3_ = -0.5 * C * eta0_;

  const double scale_I = std::max(A, C);
  const double scale_w = speed;
  special_.zero_velocity = !(speed > 0.0);
  special_.ball = std::abs(A - C) <= relative_tolerance * scale_I;
  special_.flat = std::abs(h) <= relative_tolerance * scale_I;
  special_.axial_spin = r_ <= relative_tolerance * scale_w;
  special_.equatorial_spin = std::abs(mu_) <= relative_tolerance * scale_w;
  special_.zero_discriminant = std::sqrt(Delta_) <= relative_tolerance * std::max(std::abs(c1_), 1e-300);

  constant_ = constant_matrix_53();
}

Vec3 AxisymmetricLambda::eigenvalues_sorted() const {
  std::array<double, 3> v{lambda1_, lambda2_, lambda3_};
  std::sort(v.begin(), v.end());
  return Vec3(v[0], v[1], v[2]);
}

Mat3 AxisymmetricLambda::E(double t) const {
  return so3::exp(((t - t0_) * precession_rate()) * inertia_.k);
}

Vec3 AxisymmetricLambda::omega(double t) const {
  return E(t) * omega0_;
}

Vec3 AxisymmetricLambda::lambda3_eigenvector(double t) const {
  return inertia_.k.cross(omega(t));
}

Mat3 AxisymmetricLambda::constant_matrix_53() const {
  const double A = inertia_.A;
  const double C = inertia_.C;
  const Vec3& k = inertia_.k;
  const Vec3& w0 = omega0_;
  const Mat3 kk = k * k.transpose();
  const Mat3 zeta = w0 * k.transpose() + k * w0.transpose();  // ζ01 + ζ10 (C15)
  return -0.5 * C * eta0_ * Mat3::Identity() + 0.5 * C * w0 * w0.transpose() -
         0.5 * C / A * (C - A) * mu_ * zeta + (C - A) * (eta0_ + (C - A) / A * mu_ * mu_) * kk;
}

Mat3 AxisymmetricLambda::constant_matrix_54() const {
  const double A = inertia_.A;
  const double C = inertia_.C;
  const double h = A - 0.5 * C;
  const Vec3& k = inertia_.k;
  const Vec3 m = n_.cross(k);
  return -0.5 * C * eta0_ * m * m.transpose() - 0.5 * C * mu_ * mu_ * n_ * n_.transpose() +
         C / A * h * r_ * mu_ * (n_ * k.transpose() + k * n_.transpose()) - h * r_ * r_ * k * k.transpose();
}

Eigen::Matrix2d AxisymmetricLambda::reduced_matrix_55() const {
  const double A = inertia_.A;
  const double C = inertia_.C;
  const double h = A - 0.5 * C;
  const double b = C / A * h * r_ * mu_;
  Eigen::Matrix2d m;
  m << -0.5 * C * mu_ * mu_, b, b, -h * r_ * r_;
  return m;
}

Mat3 AxisymmetricLambda::lambda_at(double t) const {
  const Mat3 e = E(t);
  return e * constant_ * e.transpose();
}

}  // namespace poinsot::analysis
