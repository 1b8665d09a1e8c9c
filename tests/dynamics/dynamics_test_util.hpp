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
#include "poinsot_test.hpp"

namespace poinsot::test {

using dynamics::IntegratorOptions;
using dynamics::RigidBody;
using dynamics::State;
using dynamics::TorqueModel;

/// The test body of the integrator tests: J = diag(1, 2, 3) kg·m², asymmetric, and a plane lamina (I3 = I1 +
/// I2, so K = diag(2, 1, 0) is singular).
inline const RigidBody kBody = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));

/// A generic tumbling state of kBody: R = exp(j(0.3, −0.2, 0.5)), ω = (1, 0.6, −0.8) rad/s, t = 0.
inline State tumbling() {
  State s;
  s.R_space_body = so3::exp(Vec3(0.3, -0.2, 0.5));
  s.omega_body = Vec3(1.0, 0.6, -0.8);
  return s;
}

/// Advances `s` to t_end with `n` equal steps of the integrator.
inline State run_fixed(dynamics::Integrator& integrator, State s, double t_end, long long n) {
  const double h = (t_end - s.time) / static_cast<double>(n);
  for (long long i = 0; i < n; ++i)
    integrator.step(s, h);
  return s;
}

/// Advances `s` to exactly t_end with an adaptive integrator.
inline State run_adaptive(dynamics::Integrator& integrator, State s, double t_end, double h0) {
  double h = h0;
  while (s.time < t_end) {
    const double remaining = t_end - s.time;
    const bool last = h >= remaining;
    const auto r = integrator.step(s, last ? remaining : h);
    if (last && r.dt_taken == remaining) s.time = t_end;
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
  return std::max(dw, so3::angle_between(a.R_space_body, ref.R_space_body));
}

/// The closed form of the axisymmetric free body J = diag(A, A, C) (Vallée & Dumitriu 2002, eq. 4.2, with
/// the conventions of docs/conventions.md): R(t) = exp[t j(L_space/A)] R0 exp[−t ν j(e3)], ν = (C − A) ω3 /
/// A, and ω(t) = ω0 rotated by ν t about e3.
inline State axisymmetric_exact(double A, double C, const State& s0, double t) {
  const Vec3 L_space =
      s0.R_space_body * Vec3(A * s0.omega_body.x(), A * s0.omega_body.y(), C * s0.omega_body.z());
  const double nu = (C - A) * s0.omega_body.z() / A;
  State s;
  s.time = s0.time + t;
  s.R_space_body = so3::exp(t * L_space / A) * s0.R_space_body * so3::exp(Vec3(0, 0, -nu * t));
  s.omega_body = so3::exp(Vec3(0, 0, nu * t)) * s0.omega_body;
  return s;
}

/// Measured order log2(e(h) / e(h/2)).
inline double measured_order(double e_h, double e_half) {
  return std::log2(e_h / e_half);
}

/// The measured order of the fixed-step method `Method` (constructed from body and torque) on [0, T]: n and
/// 2n steps against the dop853 reference.
template <class Method>
double order_against_reference(const RigidBody& body, std::shared_ptr<const TorqueModel> tau, const State& s0,
                               double T, long long n) {
  const State ref = reference(body, tau, s0, T);
  Method a(body, tau);
  Method b(body, tau);
  const double e1 = state_error(run_fixed(a, s0, T, n), ref);
  const double e2 = state_error(run_fixed(b, s0, T, 2 * n), ref);
  return measured_order(e1, e2);
}

/// Runs `Method` on kBody's tumbling motion in its principal frame and in a body frame rotated by Q, where
/// J = Q diag(1, 2, 3) Qᵀ is not diagonal (the general code path): R_b = R_p Qᵀ, ω_b = Q ω_p. The same method
/// in another frame must give the same motion to round-off (and to the eigen-decomposition's accuracy).
template <class Method>
void expect_same_motion_in_a_rotated_body_frame() {
  const Mat3 Q = so3::exp(Vec3(0.4, -0.7, 0.2));
  const RigidBody rotated = RigidBody::from_inertia(Q * Vec3(1.0, 2.0, 3.0).asDiagonal() * Q.transpose());
  const State p0 = tumbling();
  State b0 = p0;
  b0.R_space_body = p0.R_space_body * Q.transpose();
  b0.omega_body = Q * p0.omega_body;
  Method a(kBody, TorqueModel::none());
  Method b(rotated, TorqueModel::none());
  const State p = run_fixed(a, p0, 3.0, 300);
  const State q = run_fixed(b, b0, 3.0, 300);
  EXPECT_LT(max_abs_diff(q.R_space_body, Mat3(p.R_space_body * Q.transpose())), 1e-12);
  EXPECT_LT(max_abs_diff(q.omega_body, Vec3(Q * p.omega_body)), 1e-12);
}

/// The heavy symmetric top of the splitting/variational tests: J_com = diag(0.002, 0.002, 0.004) kg·m², 1 kg,
/// centre of mass 0.1 m up its axis, g = (0, 0, −9.81) m/s², tilted 60° and spun at 50 rad/s.
struct HeavyTopCase {
  RigidBody body =
      RigidBody::from_principal_moments(Vec3(0.002, 0.002, 0.004)).with_pivot(1.0, Vec3(0, 0, 0.1));
  Vec3 g = Vec3(0, 0, -9.81);
  std::shared_ptr<const TorqueModel> gravity = TorqueModel::gravity(body, g);
  State initial = State{0.0, so3::exp(Vec3(M_PI / 3, 0, 0)), Vec3(0, 0, 50.0)};
};

/// Relative total-energy errors of a run of n steps of h: the worst over the first tenth and over the whole
/// run, and the final state.
struct EnergyRun {
  double first_tenth_max = 0.0;
  double all_max = 0.0;
  State final_state;
};

template <class Method>
EnergyRun heavy_top_energy_run(const HeavyTopCase& top, int n, double h) {
  Method method(top.body, top.gravity);
  State s = top.initial;
  const double E0 = dynamics::total_energy(top.body, s, top.g);
  EnergyRun out;
  for (int i = 0; i < n; ++i) {
    method.step(s, h);
    const double e = std::abs(dynamics::total_energy(top.body, s, top.g) - E0) / std::abs(E0);
    if (i < n / 10) out.first_tenth_max = std::max(out.first_tenth_max, e);
    out.all_max = std::max(out.all_max, e);
  }
  out.final_state = s;
  return out;
}

}  // namespace poinsot::test
