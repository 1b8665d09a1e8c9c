// Re-simulation of an optimal control history by the multibody projected RK4 (multibody_direct.hpp).
#include <algorithm>

#include "multibody_controls.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::optimal {
namespace detail {

multibody::System system_with_controls(const MultibodyProblem& problem, const Eigen::VectorXd& u) {
  multibody::System system = problem.system;
  int k = 0;
  for (const Actuator& a : problem.actuators) {
    if (a.kind == ActuatorKind::hinge_torque) {
      const multibody::Joint& j = system.joints()[static_cast<std::size_t>(a.index)];
      const Vec3 axis_a = j.p_a[0].cross(j.p_a[1]);
      const Vec3 axis_b = j.u_b[0];
      system.add_torque({j.body_a, u(k) * axis_a, true});
      if (j.body_b != multibody::kWorld) system.add_torque({j.body_b, -u(k) * axis_b, true});
    } else {
      system.add_torque({a.index, u.segment<3>(k), true});
    }
    k += a.controls();
  }
  return system;
}

}  // namespace detail

MultibodyReplay replay_controls(const MultibodyProblem& problem, const MultibodyOptimum& optimum,
                                int steps_per_interval) {
  if (steps_per_interval < 1) {
    throw InvalidInput("optimal control replay: steps_per_interval: expected an integer >= 1");
  }
  const int steps = problem.intervals * steps_per_interval;
  const double dt = problem.final_time / steps;
  MultibodyReplay out;
  multibody::State state = problem.initial_state;
  state.time = 0.0;
  for (int n = 0; n < steps; ++n) {
    const double t = n * dt;
    multibody::ProjectedRk4 rk4(detail::system_with_controls(problem, control_at(optimum, t + 0.5 * dt)), dt);
    rk4.step(state);
    state.time = t + dt;
    const multibody::ConstraintViolation cv = multibody::constraint_violation(problem.system, state);
    out.max_joint_gap = std::max(out.max_joint_gap, cv.joint_gap);
    out.max_orthogonality = std::max(out.max_orthogonality, cv.orthogonality);
  }
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    const multibody::BodyState& b = state.bodies[i];
    const multibody::BodyState& f = problem.final_state.bodies[i];
    out.attitude_error = std::max(out.attitude_error, so3::angle_between(b.R_space_body, f.R_space_body));
    out.position_error = std::max(out.position_error, (b.x_space - f.x_space).norm());
    out.velocity_error =
        std::max({out.velocity_error, (b.v_space - f.v_space).norm(), (b.omega_body - f.omega_body).norm()});
  }
  out.final_state = state;
  out.steps = steps;
  return out;
}

}  // namespace poinsot::optimal
