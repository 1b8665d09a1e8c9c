#include "poinsot/dynamics/rattle.hpp"

#include <cmath>

#include <fmt/format.h>

#include "closing_kick.hpp"
#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::dynamics {

using so3::hat;

struct RattleIntegrator::Impl {
  Mat3 J;
  Mat3 J_inv;
  Mat3 K;
  std::shared_ptr<const TorqueModel> torque;
  bool torque_free = true;
  bool omega_dependent = false;
  int max_iterations = 50;
  double tolerance = 1e-14;
  Mat3 R = Mat3::Identity();
  Vec3 Pi = Vec3::Zero();  // body momentum J ω, kg·m²/s
  detail::ResumeCheck resume;
  int steps_since_projection = 0;
  // The last step, for Λ and as the Newton predictor of the next one.
  Vec3 c = Vec3::Zero();
  double h = 0.0;
  Vec3 w_plus = Vec3::Zero();   // ω after the opening kick
  Vec3 w_minus = Vec3::Zero();  // ω before the closing kick
  Vec3 tau_mean = Vec3::Zero();
  bool has_step = false;

  Vec3 torque_at(double t, const Mat3& R_, const Vec3& pi) const {
    return torque->torque_body(t, R_, J_inv * pi);
  }

  // Solves h (1 + |c|²) Π = 2 (J c + c × J c) for c by Newton's method.
  Vec3 solve_cayley(double step, const Vec3& pi, double t) const {
    Vec3 x = (has_step && h == step) ? c : Vec3(0.5 * step * (J_inv * pi));
    for (int it = 0; it < max_iterations; ++it) {
      const Vec3 Jx = J * x;
      const Vec3 G = step * (1.0 + x.squaredNorm()) * pi - 2.0 * (Jx + x.cross(Jx));
      const Mat3 DG = 2.0 * step * pi * x.transpose() - 2.0 * (J + hat(x) * J - hat(Jx));
      const Vec3 dx = DG.inverse() * G;
      x -= dx;
      if (!x.allFinite()) break;
      if (dx.norm() <= tolerance * x.norm() || G.isZero(0.0)) return x;
    }
    throw ComputationFailed(fmt::format(
        "rattle: Newton's iteration for the Cayley vector did not converge at t = {} s in {} iterations "
        "(step {} s, |Π| = {:.6g} kg·m²/s); expected a step much smaller than a rotation period",
        t, max_iterations, step, pi.norm()));
  }
};

RattleIntegrator::RattleIntegrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                   const IntegratorOptions& options)
    : impl_(std::make_unique<Impl>()), dt_(options.dt) {
  require_positive("rattle: dt", options.dt, "s");
  require_positive("rattle: newton_tolerance", options.newton_tolerance);
  if (options.newton_max_iterations < 1) {
    throw InvalidInput(fmt::format("rattle: newton_max_iterations is {}; expected at least 1",
                                   options.newton_max_iterations));
  }
  Impl& m = *impl_;
  m.J = body.inertia();
  m.J_inv = body.inertia_inverse();
  m.K = body.poinsot();
  m.torque_free = !torque || torque->is_zero();
  m.omega_dependent = !m.torque_free && torque->depends_on_omega();
  m.torque = std::move(torque);
  m.max_iterations = options.newton_max_iterations;
  m.tolerance = options.newton_tolerance;
}

RattleIntegrator::~RattleIntegrator() = default;

StepResult RattleIntegrator::step(State& state, double dt) {
  Impl& m = *impl_;
  if (!m.resume.matches(state)) {
    m.R = state.R_space_body;
    m.Pi = m.J * state.omega_body;
  }
  const double t = state.time;
  const double h = dt;
  Vec3 tau0 = Vec3::Zero();
  if (!m.torque_free) {
    tau0 = m.torque_at(t, m.R, m.Pi);
    m.Pi += (0.5 * h) * tau0;  // opening kick
  }
  const Vec3 pi_plus = m.Pi;
  const Vec3 c = m.solve_cayley(h, pi_plus, t);
  // F = cay(c) = I + W, W = α(j(c) + j(c)²), α = 2/(1 + |c|²) (so3::cayley), applied as increments so that
  // only the sums R + R W and Π⁺ + Wᵀ Π⁺ round: the 1 on F's diagonal, rounded with the small terms, would
  // make the same rounding step after step and the invariants drift linearly instead of random-walking.
  const Mat3 Cc = hat(c);
  const Mat3 W = (2.0 / (1.0 + c.squaredNorm())) * (Cc + Cc * Cc);
  m.R += m.R * W;
  m.Pi = pi_plus + W.transpose() * pi_plus;
  const Vec3 pi_minus = m.Pi;
  Vec3 tau1 = Vec3::Zero();
  if (!m.torque_free) {
    tau1 = m.torque_at(t + h, m.R, pi_minus);
    m.Pi = pi_minus + (0.5 * h) * tau1;  // closing kick
    if (m.omega_dependent) {  // implicit: Π = Π₋ + (h/2) τ(t + h, R, ω(Π)); tau1 is the last τ evaluated
      m.Pi = detail::iterate_closing_kick(RattleIntegrator::kName, pi_minus, m.Pi, h, t + h, m.tolerance,
                                          m.max_iterations,
                                          [&](const Vec3& pi) { return tau1 = m.torque_at(t + h, m.R, pi); });
    }
  }
  if (++m.steps_since_projection >= detail::kReorthogonalizeEvery) {
    detail::reorthogonalize(m.R);
    m.steps_since_projection = 0;
  }
  m.c = c;
  m.h = h;
  m.w_plus = m.J_inv * pi_plus;
  m.w_minus = m.J_inv * pi_minus;
  m.tau_mean = 0.5 * (tau0 + tau1);
  m.has_step = true;
  state.time = t + h;
  state.R_space_body = m.R;
  state.omega_body = m.J_inv * m.Pi;
  m.resume.remember(state);
  return {h, dt_, 0};
}

bool RattleIntegrator::last_multiplier(Mat3& lambda_body) const {
  const Impl& m = *impl_;
  if (!m.has_step) return false;
  // Position multiplier Λ_k = (2/h²)[j(αc − hω⁺)K + α j(c)²K] and velocity multiplier
  // Λ'_{k+1} = (2/h²) sym[j(hω⁻ − αc)K + α j(c)²K], α = 2/(1 + |c|²); their mean, written without the
  // cancelling first-order terms.
  const double alpha = 2.0 / (1.0 + m.c.squaredNorm());
  const Mat3 C = hat(m.c);
  const Mat3 S = m.h * hat(m.w_minus - m.w_plus) * m.K + 2.0 * alpha * (C * C) * m.K;
  lambda_body = (0.5 / (m.h * m.h)) * (S + S.transpose()) + hat(m.J_inv * m.tau_mean) * m.K;
  return true;
}

}  // namespace poinsot::dynamics
