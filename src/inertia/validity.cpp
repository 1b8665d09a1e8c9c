#include "poinsot/inertia/validity.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/principal_axes.hpp"

namespace poinsot::inertia {
namespace {

/// Moments printed with 12 significant digits (enough to see a shortfall, short enough to read).
std::string moments_text(const Vec3& m) {
  return fmt::format("({}, {}, {})", format_number(m[0], 12), format_number(m[1], 12),
                     format_number(m[2], 12));
}

}  // namespace

InertiaCheck check_inertia(const Mat3& J, double rel_tol, std::string_view what) {
  if (!(rel_tol >= 0.0) || !std::isfinite(rel_tol)) {
    throw InvalidInput(fmt::format("{}: validity tolerance {}; expected a finite number >= 0", what,
                                   format_number(rel_tol)));
  }
  InertiaCheck out;
  if (!J.allFinite()) {
    out.valid = false;
    out.condition = "non-finite";
    out.amount = std::numeric_limits<double>::quiet_NaN();
    out.message = fmt::format("{}: tensor {} kg·m² has non-finite entries; expected finite numbers", what,
                              format_matrix(J));
    return out;
  }
  const double largest = J.cwiseAbs().maxCoeff();
  const double asym = (J - J.transpose()).cwiseAbs().maxCoeff();
  const Mat3 Js = 0.5 * (J + J.transpose());
  Vec3 lambda;
  Mat3 v;
  jacobi_eigen(Js, lambda, v);
  std::sort(lambda.data(), lambda.data() + 3);
  out.moments = lambda;
  if (asym > rel_tol * largest) {
    out.valid = false;
    out.condition = "not symmetric";
    out.amount = asym;
    out.message = fmt::format(
        "{}: tensor {} kg·m² is not symmetric (largest |J_ij − J_ji| = {} kg·m²); expected J = Jᵀ", what,
        format_matrix(J), format_number(asym, 6));
    return out;
  }
  const double tol = rel_tol * std::max(Js.trace(), 0.0);
  if (lambda[0] < -tol) {
    out.valid = false;
    out.condition = "negative moment";
    out.amount = -lambda[0];
    out.message = fmt::format(
        "{}: principal moments {} kg·m² include a negative moment I1 = {} (below 0 by {}); expected all >= 0",
        what, moments_text(lambda), format_number(lambda[0], 6), format_number(-lambda[0], 6));
    return out;
  }
  const double short_by = lambda[2] - lambda[0] - lambda[1];
  if (short_by > tol) {
    out.valid = false;
    out.condition = "triangle inequality";
    out.amount = short_by;
    out.message = fmt::format(
        "{}: principal moments {} kg·m² violate the triangle inequality I1 + I2 >= I3 (short by {})", what,
        moments_text(lambda), format_number(short_by, 6));
    return out;
  }
  return out;
}

void require_valid_inertia(const Mat3& J, std::string_view what, double rel_tol) {
  const InertiaCheck c = check_inertia(J, rel_tol, what);
  if (!c.valid) throw InvalidInput(c.message);
}

Vec3 project_moments_to_valid(const Vec3& lambda) {
  // Constraint k: n_k · μ >= 0 with n_k = (1,1,1) − 2 e_k (i.e. μ_i + μ_j − μ_k >= 0). The projection lies in
  // the relative interior of one face of the cone and is the orthogonal projection onto that face's span;
  // enumerate the 8 faces (active sets), keep the feasible candidates, return the nearest.
  const std::array<Vec3, 3> n{Vec3(-1, 1, 1), Vec3(1, -1, 1), Vec3(1, 1, -1)};
  const double scale = std::max(lambda.cwiseAbs().maxCoeff(), std::numeric_limits<double>::min());
  Vec3 best = Vec3::Zero();  // the apex (active set {0,1,2}) is always feasible
  double best_d = lambda.norm();
  for (unsigned mask = 0; mask < 7; ++mask) {
    Eigen::Matrix<double, 3, Eigen::Dynamic> N(3, 0);
    for (int k = 0; k < 3; ++k) {
      if (mask & (1u << k)) {
        N.conservativeResize(Eigen::NoChange, N.cols() + 1);
        N.col(N.cols() - 1) = n[static_cast<std::size_t>(k)];
      }
    }
    Vec3 mu = lambda;
    if (N.cols() > 0) {
      const Eigen::MatrixXd G = N.transpose() * N;
      mu = lambda - N * G.ldlt().solve(N.transpose() * lambda);
    }
    bool feasible = true;
    for (const Vec3& nk : n)
      feasible = feasible && nk.dot(mu) >= -1e-14 * scale;
    const double d = (mu - lambda).norm();
    if (feasible && d < best_d) {
      best = mu;
      best_d = d;
    }
  }
  // Remove the round-off of the projection: clamp tiny violations so that the result passes check_inertia.
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3;
    const int j = (k + 2) % 3;
    if (best[i] + best[j] < best[k]) best[k] = best[i] + best[j];
  }
  return best;
}

InertiaRepair repair_inertia(const Mat3& J) {
  if (!J.allFinite()) {
    throw InvalidInput(
        fmt::format("inertia: tensor {} kg·m² has non-finite entries; cannot repair it", format_matrix(J)));
  }
  const Mat3 Js = 0.5 * (J + J.transpose());
  Vec3 lambda;
  Mat3 q;
  jacobi_eigen(Js, lambda, q);
  const Vec3 mu = project_moments_to_valid(lambda);
  InertiaRepair out;
  out.inertia = q * mu.asDiagonal() * q.transpose();
  out.inertia = (0.5 * (out.inertia + out.inertia.transpose())).eval();
  if (check_inertia(J).valid) out.inertia = J;  // nothing to repair: return the input unchanged
  out.distance = (J - out.inertia).norm();
  out.moments_before = lambda;
  out.moments_after = mu;
  std::sort(out.moments_before.data(), out.moments_before.data() + 3);
  std::sort(out.moments_after.data(), out.moments_after.data() + 3);
  return out;
}

}  // namespace poinsot::inertia
