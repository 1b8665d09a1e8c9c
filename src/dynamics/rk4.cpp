#include "poinsot/dynamics/rk4.hpp"

#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::dynamics {

struct Rk4Integrator::Impl {
  detail::EulerRhs f;
  detail::Vec7 y;  // (q, ω), q of unit norm
  detail::ResumeCheck resume;
};

Rk4Integrator::Rk4Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                             const IntegratorOptions& options)
    : impl_(
          std::make_unique<Impl>(Impl{detail::EulerRhs(body, std::move(torque)), detail::Vec7::Zero(), {}})),
      dt_(options.dt) {
  require_positive("rk4: dt", options.dt, "s");
}

Rk4Integrator::~Rk4Integrator() = default;

StepResult Rk4Integrator::step(State& state, double dt) {
  Impl& m = *impl_;
  detail::Vec7& y = m.y;
  if (!m.resume.matches(state)) {
    const Quat q = so3::quaternion_from_rotation(state.R);
    y << q.w(), q.x(), q.y(), q.z(), state.omega_body;
  }
  const double t = state.t;
  const double h = dt;
  const detail::Vec7 k1 = m.f(t, y);
  const detail::Vec7 k2 = m.f(t + 0.5 * h, y + (0.5 * h) * k1);
  const detail::Vec7 k3 = m.f(t + 0.5 * h, y + (0.5 * h) * k2);
  const detail::Vec7 k4 = m.f(t + h, y + h * k3);
  y += (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
  y.head<4>() /= y.head<4>().norm();  // renormalise: R(q) is then orthogonal to round-off
  state.t = t + h;
  state.R = Quat(y[0], y[1], y[2], y[3]).toRotationMatrix();
  state.omega_body = y.tail<3>();
  m.resume.remember(state);
  return {h, dt_, 0};
}

}  // namespace poinsot::dynamics
