#include "poinsot/dynamics/dlm.hpp"

#include <cmath>

#include <fmt/format.h>

#include "closing_kick.hpp"
#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/sin_cos.hpp"

namespace poinsot::dynamics {

struct DlmIntegrator::Impl {
  Mat3 P;           // principal axes (columns) in the body frame, det = +1
  bool P_identity;  // the body frame is the principal frame: no change of frame
  Vec3 inv_I;       // 1 / principal moments, 1/(kg·m²)
  Mat3 Rp;          // R P: principal frame → space
  Vec3 Pi;          // body momentum in the principal frame, kg·m²/s
  std::shared_ptr<const TorqueModel> torque;
  bool torque_free;
  bool omega_dependent;
  int max_iterations;
  double tolerance;
  detail::ResumeCheck resume;
  int steps_since_projection = 0;

  // The exact flow of H_i = Π_i²/(2 I_i) for a time h: planar rotations by θ = h Π_i / I_i.
  void rotate(int i, double h) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    const double theta = h * Pi[i] * inv_I[i];
    double s, cm1;  // sin θ, cos θ − 1
    sin_cosm1(theta, s, cm1);
    // As increments, so that only the sums round (sin_cos.hpp): the rounding is then unbiased and the
    // invariants |Π|, L_space and RᵀR = I random-walk (Brouwer's law) instead of drifting.
    const double pj = Pi[j];
    const double pk = Pi[k];
    Pi[j] = pj + (cm1 * pj + s * pk);
    Pi[k] = pk + (cm1 * pk - s * pj);
    const Vec3 rj = Rp.col(j);
    const Vec3 rk = Rp.col(k);
    Rp.col(j) = rj + (cm1 * rj + s * rk);
    Rp.col(k) = rk + (cm1 * rk - s * rj);
  }
  void free_flow(double h) {
    rotate(0, 0.5 * h);
    rotate(1, 0.5 * h);
    rotate(2, h);
    rotate(1, 0.5 * h);
    rotate(0, 0.5 * h);
  }
  Mat3 R_body() const { return P_identity ? Rp : Mat3(Rp * P.transpose()); }
  Vec3 omega_body(const Vec3& pi) const {
    const Vec3 w = pi.cwiseProduct(inv_I);
    return P_identity ? w : Vec3(P * w);
  }
  Vec3 torque_principal(double t, const Mat3& R, const Vec3& pi) const {
    const Vec3 tau = torque->torque_body(t, R, omega_body(pi));
    return P_identity ? tau : Vec3(P.transpose() * tau);
  }
};

DlmIntegrator::DlmIntegrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                             const IntegratorOptions& options)
    : dt_(options.dt) {
  require_positive("dlm: dt", options.dt, "s");
  const bool free = !torque || torque->is_zero();
  const bool omega_dep = !free && torque->depends_on_omega();
  impl_ = std::make_unique<Impl>(Impl{body.principal_axes(),
                                      body.principal_axes() == Mat3::Identity(),
                                      body.principal_moments().cwiseInverse(),
                                      Mat3::Identity(),
                                      Vec3::Zero(),
                                      std::move(torque),
                                      free,
                                      omega_dep,
                                      options.newton_max_iterations,
                                      options.newton_tolerance,
                                      {}});
}

DlmIntegrator::~DlmIntegrator() = default;

StepResult DlmIntegrator::step(State& state, double dt) {
  Impl& m = *impl_;
  if (!m.resume.matches(state)) {
    m.Rp = m.P_identity ? state.R_space_body : Mat3(state.R_space_body * m.P);
    const Vec3 w = m.P_identity ? state.omega_body : Vec3(m.P.transpose() * state.omega_body);
    m.Pi = w.cwiseQuotient(m.inv_I);
  }
  const double t = state.time;
  const double h = dt;
  if (m.torque_free) {
    m.free_flow(h);
  } else {
    m.Pi += (0.5 * h) * m.torque_principal(t, state.R_space_body, m.Pi);  // opening kick
    m.free_flow(h);
    const Mat3 R1 = m.R_body();
    const Vec3 pi_free = m.Pi;
    m.Pi = pi_free + (0.5 * h) * m.torque_principal(t + h, R1, pi_free);  // closing kick
    if (m.omega_dependent) {  // implicit: Π = Π_free + (h/2) τ(t + h, R, ω(Π))
      m.Pi = detail::iterate_closing_kick(DlmIntegrator::kName, pi_free, m.Pi, h, t + h, m.tolerance,
                                          m.max_iterations,
                                          [&](const Vec3& pi) { return m.torque_principal(t + h, R1, pi); });
    }
  }
  if (++m.steps_since_projection >= detail::kReorthogonalizeEvery) {
    detail::reorthogonalize(m.Rp);
    m.steps_since_projection = 0;
  }
  state.time = t + h;
  state.R_space_body = m.R_body();
  state.omega_body = m.omega_body(m.Pi);
  m.resume.remember(state);
  return {h, dt_, 0};
}

}  // namespace poinsot::dynamics
