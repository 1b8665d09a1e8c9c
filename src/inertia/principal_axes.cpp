#include "poinsot/inertia/principal_axes.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::inertia {
namespace {

constexpr int kMaxSweeps = 50;  // 3×3 Jacobi converges quadratically; about 4 to 6 sweeps in practice

/// The sign rule for one axis: the component of largest magnitude is positive; components within 1e-12
/// (relative) of the largest count as equal and the first of them decides.
Vec3 sign_fixed(const Vec3& v) {
  const double largest = v.cwiseAbs().maxCoeff();
  for (int k = 0; k < 3; ++k) {
    if (std::abs(v[k]) >= largest * (1.0 - 1e-12)) return v[k] < 0.0 ? Vec3(-v) : v;
  }
  return v;
}

/// A unit vector ⟂ to the unit vector u: the projection of the coordinate axis with the smallest |u_k| (the
/// first on ties), normalised.
Vec3 perpendicular_to(const Vec3& u) {
  int k = 0;
  for (int i = 1; i < 3; ++i)
    if (std::abs(u[i]) < std::abs(u[k])) k = i;
  Vec3 w = Vec3::Unit(k) - u[k] * u;
  return w.normalized();
}

}  // namespace

std::string to_string(Symmetry s) {
  switch (s) {
    case Symmetry::asymmetric:
      return "asymmetric";
    case Symmetry::prolate:
      return "prolate";
    case Symmetry::oblate:
      return "oblate";
    case Symmetry::spherical:
      return "spherical";
  }
  return "asymmetric";
}

void jacobi_eigen(const Mat3& S, Vec3& eigenvalues, Mat3& eigenvectors) {
  require_finite("inertia: tensor (kg·m²)", S);
  Mat3 a = 0.5 * (S + S.transpose());
  Mat3 v = Mat3::Identity();
  constexpr std::array<std::array<int, 2>, 3> kPairs{{{0, 1}, {0, 2}, {1, 2}}};
  for (int sweep = 0; sweep < kMaxSweeps; ++sweep) {
    if (a(0, 1) == 0.0 && a(0, 2) == 0.0 && a(1, 2) == 0.0) break;
    for (const auto& pq : kPairs) {
      const int p = pq[0];
      const int q = pq[1];
      const int r = 3 - p - q;
      const double apq = a(p, q);
      if (apq == 0.0) continue;
      // After a few sweeps an entry below the rounding level of both diagonal entries is set to zero
      // (Numerical Recipes §11.1): rotating by it would change nothing representable.
      const double g = 100.0 * std::abs(apq);
      if (sweep > 3 && std::abs(a(p, p)) + g == std::abs(a(p, p)) &&
          std::abs(a(q, q)) + g == std::abs(a(q, q))) {
        a(p, q) = a(q, p) = 0.0;
        continue;
      }
      // Rotation angle (Rutishauser): θ = (a_qq − a_pp)/(2 a_pq), t = tan φ the smaller root of
      // t² + 2tθ − 1 = 0. θ = 0 (equal diagonal) gives t = 1 exactly, the rotation by π/4.
      const double theta = (a(q, q) - a(p, p)) / (2.0 * apq);
      double t;
      if (std::abs(theta) > 1e150) {
        t = 0.5 / theta;
      } else {
        t = (theta >= 0.0 ? 1.0 : -1.0) / (std::abs(theta) + std::sqrt(theta * theta + 1.0));
      }
      const double c = 1.0 / std::sqrt(t * t + 1.0);
      const double s = t * c;
      const double app = a(p, p) - t * apq;
      const double aqq = a(q, q) + t * apq;
      const double arp = a(r, p);
      const double arq = a(r, q);
      a(p, p) = app;
      a(q, q) = aqq;
      a(p, q) = a(q, p) = 0.0;
      a(r, p) = a(p, r) = c * arp - s * arq;
      a(r, q) = a(q, r) = s * arp + c * arq;
      for (int k = 0; k < 3; ++k) {
        const double vkp = v(k, p);
        const double vkq = v(k, q);
        v(k, p) = c * vkp - s * vkq;
        v(k, q) = s * vkp + c * vkq;
      }
    }
  }
  eigenvalues = a.diagonal();
  eigenvectors = v;
}

Symmetry classify(const Vec3& m, double rel_tol) {
  if (!(rel_tol >= 0.0) || !std::isfinite(rel_tol)) {
    throw InvalidInput(
        fmt::format("inertia: symmetry tolerance {}; expected a finite number >= 0", format_number(rel_tol)));
  }
  require_finite("inertia: principal moments (kg·m²)", m);
  const double scale = std::max({std::abs(m[0]), std::abs(m[1]), std::abs(m[2])});
  const double tol = rel_tol * scale;
  if (m[2] - m[0] <= tol) return Symmetry::spherical;
  if (m[1] - m[0] <= tol) return Symmetry::oblate;
  if (m[2] - m[1] <= tol) return Symmetry::prolate;
  return Symmetry::asymmetric;
}

PrincipalAxes principal_axes(const Mat3& J, double rel_tol) {
  require_finite("inertia: tensor (kg·m²)", J);
  const double largest = J.cwiseAbs().maxCoeff();
  const double asym = (J - J.transpose()).cwiseAbs().maxCoeff();
  if (asym > 1e-12 * largest) {
    throw InvalidInput(
        fmt::format("inertia: tensor {} kg·m² is not symmetric (largest |J_ij − J_ji| = {}); "
                    "expected J = Jᵀ to 1e-12 of its largest entry",
                    format_matrix(J), format_number(asym, 3)));
  }
  Vec3 lambda;
  Mat3 v;
  jacobi_eigen(J, lambda, v);

  std::array<int, 3> order{0, 1, 2};
  std::stable_sort(order.begin(), order.end(), [&](int i, int k) { return lambda[i] < lambda[k]; });
  PrincipalAxes out;
  for (int k = 0; k < 3; ++k) {
    out.moments[k] = lambda[order[static_cast<std::size_t>(k)]];
    out.axes.col(k) = v.col(order[static_cast<std::size_t>(k)]);
  }
  out.symmetry = classify(out.moments, rel_tol);
  switch (out.symmetry) {
    case Symmetry::spherical:
      out.axes.setIdentity();
      return out;
    case Symmetry::oblate: {  // I1 = I2 < I3: the unique axis is a3
      const Vec3 u = out.axes.col(2).normalized();
      const Vec3 w = perpendicular_to(u);
      out.axes.col(0) = w;
      out.axes.col(1) = u.cross(w);
      break;
    }
    case Symmetry::prolate: {  // I1 < I2 = I3: the unique axis is a1
      const Vec3 u = out.axes.col(0).normalized();
      const Vec3 w = perpendicular_to(u);
      out.axes.col(0) = u;
      out.axes.col(1) = w;
      break;
    }
    case Symmetry::asymmetric:
      break;
  }
  out.axes.col(0) = sign_fixed(out.axes.col(0));
  out.axes.col(1) = sign_fixed(out.axes.col(1));
  out.axes.col(2) = out.axes.col(0).cross(out.axes.col(1)).normalized();
  return out;
}

}  // namespace poinsot::inertia
