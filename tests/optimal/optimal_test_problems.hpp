#pragma once
// Reference problems of the optimal/ tests: Betts' asymmetric spacecraft and the spherical body.
#include <cmath>
#include <numbers>

#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal::testing {

/// Betts (Practical Methods for Optimal Control, 2nd ed., example 6.12; PSOPT "reorientation"):
/// J = diag(5621, 4547, 2364) kg·m², |u_i| ≤ 50 N·m, |ω_i| ≤ 0.5 rad/s, rest → rest, 150° about body x,
/// minimum time. Published optimum t* = 28.6304077 s.
inline ReorientationProblem betts_problem() {
  ReorientationProblem p;
  p.inertia_body = Vec3(5621.0, 4547.0, 2364.0).asDiagonal();
  p.torque_max = Vec3::Constant(50.0);
  p.rate_max = 0.5;
  const double half = 0.5 * 150.0 * std::numbers::pi / 180.0;
  p.attitude_final = Quat(std::cos(half), std::sin(half), 0.0, 0.0);
  p.objective = Objective::minimum_time;
  return p;
}
inline constexpr double kBettsPublishedTime = 28.6304077;  // s

/// The sphere J = j I rest to rest through Θ about the unit axis n at minimum energy in the fixed time T.
inline ReorientationProblem sphere_energy_problem(double j, double theta, const Vec3& axis, double T) {
  ReorientationProblem p;
  p.inertia_body = j * Mat3::Identity();
  p.torque_max = Vec3::Constant(1e3);
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, axis.normalized()));
  p.objective = Objective::minimum_energy;
  p.final_time = T;
  return p;
}

/// The direct solution that seeds the shooting in the sphere tests: 10 initial intervals, refined to
/// `mesh_tolerance`.
inline DirectSolution sphere_direct_seed(const ReorientationProblem& p, double mesh_tolerance = 1e-6) {
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = mesh_tolerance;
  return solve_direct(p, opt);
}

/// Brody's tennis racket (J = diag(0.00121, 0.01638, 0.01748) kg·m², examples/tennis_racket.toml) spinning at
/// w about its intermediate axis y, at the start and at T, and ending Δ ahead of the free spin: R_f =
/// exp(j((wT + Δ) e_y)), minimum energy at fixed T (torque bound 1 N·m, far above the optimum's). The spin
/// about y is an equilibrium of the torque-free motion and a torque along y keeps ω on y, so the phase
/// advance is the sphere's problem about y: u_y = 6 J_y Δ/T² (1 − 2t/T), cost 12 J_y² Δ²/T³. Transverse
/// perturbations grow like e^{λt}, λ = w √((J_y − J_x)(J_z − J_y)/(J_x J_z)) = 0.888 w.
inline ReorientationProblem racket_spin_phase_problem(double w, double T, double delta) {
  ReorientationProblem p;
  p.inertia_body = Vec3(0.00121, 0.01638, 0.01748).asDiagonal();
  p.torque_max = Vec3::Constant(1.0);
  p.omega_initial = p.omega_final = Vec3(0.0, w, 0.0);
  p.attitude_final = Quat(Eigen::AngleAxisd(w * T + delta, Vec3::UnitY()));
  p.objective = Objective::minimum_energy;
  p.final_time = T;
  return p;
}

}  // namespace poinsot::optimal::testing
