#pragma once
// Helpers shared by the dynamics tests: reference solutions and error measures. Not a test file itself.
#include <cmath>
#include <memory>
#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::test {

using dynamics::IntegratorOptions;
using dynamics::RigidBody;
using dynamics::State;
using dynamics::TorqueModel;

/// Advances `s` to t_end with `n` equal steps of the integrator.
inline State run_fixed(dynamics::Integrator& integrator, State s, double t_end, long long n) {
  const double h = (t_end - s.t) / static_cast<double>(n);
  for (long long i = 0; i < n; ++i)
    integrator.step(s, h);
  return s;
}

/// Advances `s` to exactly t_end with an adaptive integrator.
inline State run_adaptive(dynamics::Integrator& integrator, State s, double t_end, double h0) {
  double h = h0;
  while (s.t < t_end) {
    const double remaining = t_end - s.t;
    const bool last = h >= remaining;
    const auto r = integrator.step(s, last ? remaining : h);
    if (last && r.dt_taken == remaining) s.t = t_end;
    h = r.dt_next;
  }
  return s;
}

/// A high-precision reference: dop853 at rtol = atol = 1e-14 (error ~1e-13 over a few periods).
inline State reference(const RigidBody& body, std::shared_ptr<const TorqueModel> torque, const State& s0,
                       double t_end) {
  IntegratorOptions o;
  o.rtol = 1e-14;
  o.atol = 1e-14;
  o.dt = 0.05;
  dynamics::Dop853Integrator ref(body, std::move(torque), o);
  return run_adaptive(ref, s0, t_end, o.dt);
}

/// max(|Δω| / |ω_ref|, angle between the attitudes): a dimensionless error of a state.
inline double state_error(const State& a, const State& ref) {
  const double dw = (a.omega_body - ref.omega_body).norm() / std::max(ref.omega_body.norm(), 1e-300);
  return std::max(dw, so3::angle_between(a.R, ref.R));
}

/// The closed form of the axisymmetric free body J = diag(A, A, C) (Vallée & Dumitriu 2002, eq. 4.2, with
/// the conventions of ERRATA.md): R(t) = exp[t j(L_space/A)] R0 exp[−t ν j(e3)], ν = (C − A) ω3 / A, and
/// ω(t) = ω0 rotated by ν t about e3.
inline State axisymmetric_exact(double A, double C, const State& s0, double t) {
  const Vec3 L_space = s0.R * Vec3(A * s0.omega_body.x(), A * s0.omega_body.y(), C * s0.omega_body.z());
  const double nu = (C - A) * s0.omega_body.z() / A;
  State s;
  s.t = s0.t + t;
  s.R = so3::exp(t * L_space / A) * s0.R * so3::exp(Vec3(0, 0, -nu * t));
  s.omega_body = so3::exp(Vec3(0, 0, nu * t)) * s0.omega_body;
  return s;
}

/// Measured order log2(e(h) / e(h/2)).
inline double measured_order(double e_h, double e_half) {
  return std::log2(e_h / e_half);
}

}  // namespace poinsot::test
