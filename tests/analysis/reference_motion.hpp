#pragma once
// A reference integrator for the analysis tests, independent of the dynamics layer's integrators: classical
// RK4 on the twelve numbers (R, ω) of `Ṙ = R j(ω)`, `J ω̇ = τ − ω × Jω`, with no projection. Its global error
// is O(h⁴); with h = 1e-3 s over a few seconds and |ω| ~ 1 rad/s it is ~1e-13, far below the tolerances of
// the tests that use it (each states its own margin).
#include <algorithm>
#include <cmath>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::test {

struct Derivative {
  Mat3 dR;
  Vec3 dw;
};

inline Derivative rhs(const dynamics::RigidBody& body, const dynamics::TorqueModel* torque, double t,
                      const Mat3& R, const Vec3& w) {
  Vec3 f = -w.cross(body.inertia() * w);
  if (torque != nullptr) f += torque->torque_body(t, R, w);
  return {R * so3::hat(w), body.inertia().ldlt().solve(f)};
}

/// One RK4 step of size h (s).
inline dynamics::State rk4_step(const dynamics::RigidBody& body, const dynamics::TorqueModel* torque,
                                const dynamics::State& s, double h) {
  const Derivative k1 = rhs(body, torque, s.time, s.R_space_body, s.omega_body);
  const Derivative k2 =
      rhs(body, torque, s.time + h / 2, s.R_space_body + h / 2 * k1.dR, s.omega_body + h / 2 * k1.dw);
  const Derivative k3 =
      rhs(body, torque, s.time + h / 2, s.R_space_body + h / 2 * k2.dR, s.omega_body + h / 2 * k2.dw);
  const Derivative k4 = rhs(body, torque, s.time + h, s.R_space_body + h * k3.dR, s.omega_body + h * k3.dw);
  dynamics::State out;
  out.time = s.time + h;
  out.R_space_body = s.R_space_body + h / 6 * (k1.dR + 2 * k2.dR + 2 * k3.dR + k4.dR);
  out.omega_body = s.omega_body + h / 6 * (k1.dw + 2 * k2.dw + 2 * k3.dw + k4.dw);
  return out;
}

/// Integrates from s to time t_end with steps of at most h.
inline dynamics::State advance(const dynamics::RigidBody& body, const dynamics::TorqueModel* torque,
                               dynamics::State s, double t_end, double h = 1e-3) {
  const double span = t_end - s.time;
  const long n = std::max(1L, std::lround(std::ceil(std::abs(span) / h - 1e-9)));
  const double step = span / static_cast<double>(n);
  for (long i = 0; i < n; ++i)
    s = rk4_step(body, torque, s, step);
  s.time = t_end;
  return s;
}

}  // namespace poinsot::test
