// Re-simulation of an optimal control history by the multibody projected RK4 (multibody_direct.hpp).
#include <algorithm>
#include <cmath>
#include <vector>

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
      const Vec3 axis_a = j.hinge_axis_a();
      const Vec3 axis_b = j.u_b[0];
      system.add_torque({j.body_a, u(k) * axis_a, true});
      if (j.body_b != multibody::kWorld) system.add_torque({j.body_b, -u(k) * axis_b, true});
    } else if (a.kind == ActuatorKind::ball_torque) {
      const multibody::Joint& j = system.joints()[static_cast<std::size_t>(a.index)];
      system.add_torque({j.body_a, u.segment<3>(k), false});
      if (j.body_b != multibody::kWorld) system.add_torque({j.body_b, -u.segment<3>(k), false});
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
  const double dt = optimum.time.back() / steps;  // the optimum's T (free under minimum_time)
  MultibodyReplay out;
  multibody::State state = problem.initial_state;
  state.time = 0.0;
  const Vec3 P0 = multibody::linear_momentum(problem.system, state);
  const Vec3 H0 = multibody::angular_momentum(problem.system, state);
  for (int n = 0; n < steps; ++n) {
    const double t = n * dt;
    multibody::ProjectedRk4 rk4(detail::system_with_controls(problem, control_at(optimum, t + 0.5 * dt)), dt);
    rk4.step(state);
    state.time = t + dt;
    const multibody::ConstraintViolation cv = multibody::constraint_violation(problem.system, state);
    out.max_joint_gap = std::max(out.max_joint_gap, cv.joint_gap);
    out.max_orthogonality = std::max(out.max_orthogonality, cv.orthogonality);
    out.max_momentum_change =
        std::max({out.max_momentum_change, (multibody::linear_momentum(problem.system, state) - P0).norm(),
                  (multibody::angular_momentum(problem.system, state) - H0).norm()});
  }
  // A free final hinge's body_a is compared up to its turn about the hinge axis: the axis's direction, its
  // angular velocity in space and the joint point (its own x, R and ω depend on the free angle).
  std::vector<int> free_axle(state.bodies.size(), -1);
  for (const int j : problem.free_final_hinges)
    free_axle[static_cast<std::size_t>(problem.system.joints()[static_cast<std::size_t>(j)].body_a)] = j;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    const multibody::BodyState& b = state.bodies[i];
    const multibody::BodyState& f = problem.final_state.bodies[i];
    if (free_axle[i] >= 0) {
      const multibody::Joint& j = problem.system.joints()[static_cast<std::size_t>(free_axle[i])];
      const Vec3 axis = j.hinge_axis_a();
      const Vec3 ab = b.R_space_body * axis, af = f.R_space_body * axis;
      out.attitude_error = std::max(out.attitude_error, std::atan2(ab.cross(af).norm(), ab.dot(af)));
      out.position_error =
          std::max(out.position_error,
                   (b.x_space + b.R_space_body * j.point_a - f.x_space - f.R_space_body * j.point_a).norm());
      const Vec3 wb = b.R_space_body * b.omega_body, wf = f.R_space_body * f.omega_body;
      const Vec3 vb = b.v_space + wb.cross(b.R_space_body * j.point_a);
      const Vec3 vf = f.v_space + wf.cross(f.R_space_body * j.point_a);
      out.velocity_error = std::max({out.velocity_error, (wb - wf).norm(), (vb - vf).norm()});
      continue;
    }
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
