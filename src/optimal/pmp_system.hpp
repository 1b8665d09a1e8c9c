#pragma once
/// @file pmp_system.hpp (internal)
/// The canonical system of the minimum principle in (R, ω, P, p_ω) (indirect_shooting.hpp), packed in one
/// array for the Runge–Kutta–Fehlberg integrator: y = (R column-major 9, ω 3, P column-major 9, p_ω 3, ∫L 1).
#include <algorithm>
#include <array>
#include <cmath>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/problem.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::optimal::detail {

using PmpState = std::array<double, 25>;

struct PmpView {
  Mat3 R, P;
  Vec3 omega, p_omega;
  double cost = 0.0;
};

inline PmpView unpack(const PmpState& y) {
  PmpView v;
  v.R = Eigen::Map<const Mat3>(y.data());
  v.omega = Eigen::Map<const Vec3>(y.data() + 9);
  v.P = Eigen::Map<const Mat3>(y.data() + 12);
  v.p_omega = Eigen::Map<const Vec3>(y.data() + 21);
  v.cost = y[24];
  return v;
}

inline PmpState pack(const Mat3& R, const Vec3& omega, const Mat3& P, const Vec3& p_omega, double cost) {
  PmpState y;
  Eigen::Map<Mat3>(y.data()) = R;
  Eigen::Map<Vec3>(y.data() + 9) = omega;
  Eigen::Map<Mat3>(y.data() + 12) = P;
  Eigen::Map<Vec3>(y.data() + 21) = p_omega;
  y[24] = cost;
  return y;
}

/// p_θ = vee(RᵀP − PᵀR).
inline Vec3 attitude_costate_body(const Mat3& R, const Mat3& P) {
  const Mat3 M = R.transpose() * P;
  return so3::vee(M - M.transpose());
}

/// C(σ) = ∂σ̈/∂u = j(σ) J⁻¹ − J⁻¹ j(σ): how the torque enters the second derivative of the switching vector
/// σ = J⁻¹p_ω off the boundary arcs (arc_shooting.hpp). Its diagonal C_ii = 2 σ·(J⁻¹e_i × e_i) fixes the
/// singular control of axis i and must not be positive along a singular arc (Kelley's condition).
inline Mat3 switching_torque_gain(const Mat3& J_inv, const Vec3& sigma) {
  return so3::hat(sigma) * J_inv - J_inv * so3::hat(sigma);
}

/// Whether body axis i is a principal axis of J (J⁻¹e_i ∥ e_i, to 1e-12 of J⁻¹'s largest entry): there C_ii
/// vanishes for every σ, so u_i does not enter σ̈_i, and a singular arc of u_i is of order two.
inline bool principal_axis(const Mat3& J_inv, int i) {
  const double scale = J_inv.cwiseAbs().maxCoeff();
  for (int j = 0; j < 3; ++j)
    if (j != i && std::abs(J_inv(i, j)) > 1e-12 * scale) return false;
  return true;
}

/// The running cost L(u) of the objective (1 + ε‖u‖² includes the time term of the free-time objectives).
inline double running_cost(const ReorientationProblem& p, const Vec3& u) {
  switch (p.objective) {
    case Objective::minimum_time:
      return 1.0;
    case Objective::minimum_energy:
      return u.squaredNorm();
    case Objective::minimum_time_regularised:
      return 1.0 + p.energy_weight * u.squaredNorm();
  }
  return 0.0;
}

/// H = L(u) + p_θᵀω + p_ωᵀ J⁻¹(u − ω × Jω).
inline double hamiltonian(const ReorientationProblem& p, const Mat3& J_inv, const PmpView& v, const Vec3& u) {
  const Mat3& J = p.inertia_body;
  return running_cost(p, u) + attitude_costate_body(v.R, v.P).dot(v.omega) +
         v.p_omega.dot(J_inv * (u - v.omega.cross(J * v.omega)));
}

/// ẏ for the control u.
inline void pmp_rhs(const ReorientationProblem& p, const Mat3& J_inv, const PmpState& y, PmpState& dy,
                    const Vec3& u) {
  const PmpView v = unpack(y);
  const Mat3& J = p.inertia_body;
  const Mat3 W = so3::hat(v.omega);
  const Vec3 Jw = J * v.omega;
  const Vec3 p_theta = attitude_costate_body(v.R, v.P);
  Eigen::Map<Mat3>(dy.data()) = v.R * W;
  Eigen::Map<Vec3>(dy.data() + 9) = J_inv * (u - v.omega.cross(Jw));
  Eigen::Map<Mat3>(dy.data() + 12) = v.P * W;
  Eigen::Map<Vec3>(dy.data() + 21) = -p_theta + (W * J - so3::hat(Jw)).transpose() * (J_inv * v.p_omega);
  dy[24] = running_cost(p, u);
}

/// How finely an extremal's output samples resolve a smooth torque (minimum energy, regularised, norm-bound
/// minimum time beside its turn rule, or held on a boundary arc or singular arc; constant on bang arcs) for
/// the replay (control_replay.hpp: the cubic through four samples, which errs by up to 3h⁴‖u⁽⁴⁾‖/128
/// between the middle two). An output interval (a, b) whose second difference ‖u_a − 2u_m + u_b‖ (m its
/// midpoint; about h²‖ü‖/4) exceeds this fraction of the largest ‖u‖ sampled so far is halved and integrated
/// again, at most kMaxSampleHalvings times. 1e-4 left a singular arc of 2.9 s replayed 2.6e-7 rad off (a
/// quarter of the threshold), 1e-5 3e-8 rad.
inline constexpr double kMaxSmoothSampleCurvature = 1e-5;
inline constexpr int kMaxSampleHalvings = 30;

/// The halving rule of kMaxSmoothSampleCurvature along one integration, which keeps the largest ‖u‖ seen.
class SmoothSampleRule {
 public:
  /// Whether the output interval with torques u_a, u_m (its midpoint) and u_b is to be halved; their norms
  /// join the scale first.
  bool curves(const Vec3& u_a, const Vec3& u_m, const Vec3& u_b) {
    largest_ = std::max({largest_, u_a.norm(), u_m.norm(), u_b.norm()});
    return (u_a - 2.0 * u_m + u_b).norm() > kMaxSmoothSampleCurvature * largest_;
  }

 private:
  double largest_ = 0.0;
};

}  // namespace poinsot::optimal::detail
