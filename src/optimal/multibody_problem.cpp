// Validation of a multibody optimal-control problem (multibody_problem.hpp).
#include "poinsot/optimal/multibody_problem.hpp"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "multibody_final_conditions.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/observables.hpp"

namespace poinsot::optimal {

int control_count(const MultibodyProblem& problem) {
  int n = 0;
  for (const Actuator& a : problem.actuators)
    n += a.controls();
  return n;
}

namespace {

void check_state(const MultibodyProblem& p, const multibody::State& s, const std::string& what) {
  try {
    multibody::check_consistent(p.system, s);
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("optimal control: {}: {}", what, e.what()));
  }
  const double L = p.system.length_scale();
  for (const multibody::Joint& j : p.system.joints()) {
    const auto& a = multibody::side_state(s.bodies, j.body_a);
    const auto& b = multibody::side_state(s.bodies, j.body_b);
    const multibody::JointVector gdot = multibody::joint_velocity(j, a, b);
    double speed = 1.0;
    for (const auto& bs : s.bodies)
      speed = std::max({speed, bs.v_space.norm() / L, bs.omega_body.norm()});
    if (multibody::joint_residual(j, gdot, L) > 1e-9 * speed) {
      throw InvalidInput(
          fmt::format("optimal control: {}: joint '{}' has a velocity across it of {:.3g} (relative); "
                      "expected velocities "
                      "that keep the joint (at most 1e-9)",
                      what, j.name, multibody::joint_residual(j, gdot, L) / speed));
    }
    if (j.type == multibody::JointType::hinge) {
      const Vec3 ua = j.hinge_axis_a();
      if ((a.R_space_body * ua).dot(b.R_space_body * j.u_b[0]) < 0.0) {
        throw InvalidInput(
            fmt::format("optimal control: {}: hinge '{}' has axis_a opposite to axis_b; expected "
                        "the two axes to point the same way",
                        what, j.name));
      }
    }
  }
}

/// The final time (and its bounds and the energy weight for minimum time), the intervals and the mesh. Throws
/// InvalidInput.
void check_times_and_mesh(const MultibodyProblem& p) {
  if (!(p.final_time > 0.0) || !std::isfinite(p.final_time)) {
    throw InvalidInput(
        fmt::format("optimal control: final_time: got {} s; expected a finite number > 0", p.final_time));
  }
  if (p.objective == MultibodyObjective::minimum_time) {
    if (!(p.final_time_min > 0.0 && p.final_time_min <= p.final_time && p.final_time <= p.final_time_max &&
          std::isfinite(p.final_time_max))) {
      throw InvalidInput(fmt::format(
          "optimal control: final_time: got the bounds [{}, {}] s and the guess {} s; expected 0 < "
          "final_time_min ≤ final_time ≤ final_time_max < ∞ (minimum_time)",
          p.final_time_min, p.final_time_max, p.final_time));
    }
    if (!(p.energy_weight >= 0.0) || !std::isfinite(p.energy_weight)) {
      throw InvalidInput(
          fmt::format("optimal control: energy_weight: got {}; expected a finite number ≥ 0 (minimum_time)",
                      p.energy_weight));
    }
  }
  if (p.intervals < 2 || p.intervals > 2000) {
    throw InvalidInput(
        fmt::format("optimal control: intervals: got {}; expected an integer from 2 to 2000", p.intervals));
  }
  if (!p.mesh.empty()) {
    double sum = 0.0, smallest = 1.0;
    for (const double d : p.mesh) {
      sum += d;
      smallest = std::min(smallest, d);
    }
    if (p.mesh.size() != static_cast<std::size_t>(p.intervals) || !(smallest > 0.0) ||
        !(std::abs(sum - 1.0) <= 1e-12)) {
      throw InvalidInput(fmt::format(
          "optimal control: mesh: got {} fractions, the smallest {}, summing to {}; expected intervals = {} "
          "fractions > 0 summing to 1",
          p.mesh.size(), smallest, sum, p.intervals));
    }
  }
}

/// The system: no springs, no joint springs, no prismatic joint, no universal joint with offset axes (the
/// transcriptions have none of them).
/// Throws InvalidInput.
void check_system_supported(const MultibodyProblem& p) {
  if (!p.system.springs().empty()) {
    throw InvalidInput(
        fmt::format("optimal control: spring '{}': springs are not supported by the optimal "
                    "control transcriptions; expected none",
                    p.system.springs()[0].name));
  }
  if (!p.system.joint_springs().empty()) {
    throw InvalidInput(fmt::format(
        "optimal control: joint '{}': joint springs and dampers are not supported by the optimal control "
        "transcriptions; expected none",
        p.system.joints()[static_cast<std::size_t>(p.system.joint_springs()[0].joint)].name));
  }
  for (const multibody::Joint& j : p.system.joints()) {
    if (j.axis_offset != 0.0) {
      throw InvalidInput(
          fmt::format("optimal control: joint '{}': a universal joint whose axes do not meet (axis offset {} "
                      "m) is not supported by the optimal control transcriptions; expected axes that meet",
                      j.name, j.axis_offset));
    }
    if (j.sliding) {
      throw InvalidInput(
          fmt::format("optimal control: joint '{}': prismatic joints are not supported by the "
                      "optimal control transcriptions; expected ball, hinge, weld or universal",
                      j.name));
    }
  }
}

/// At least one actuator; each bound > 0 (finite for minimum time) on a joint of its kind or a body. Throws
/// InvalidInput.
void check_actuators(const MultibodyProblem& p) {
  if (p.actuators.empty()) {
    throw InvalidInput(
        "optimal control: actuators: none given; expected at least one hinge or body torque (an unactuated "
        "system cannot be steered)");
  }
  for (std::size_t i = 0; i < p.actuators.size(); ++i) {
    const Actuator& a = p.actuators[i];
    const std::string what = fmt::format("optimal control: actuators[{}]", i);
    if (!(a.torque_max > 0.0)) {
      throw InvalidInput(
          fmt::format("{}: torque_max: got {} N·m; expected a number > 0", what, a.torque_max));
    }
    if (p.objective == MultibodyObjective::minimum_time && !std::isfinite(a.torque_max)) {
      throw InvalidInput(fmt::format(
          "{}: torque_max: got {} N·m; expected a finite bound (minimum_time: unbounded torques reach the "
          "target in no time)",
          what, a.torque_max));
    }
    if (a.kind == ActuatorKind::hinge_torque || a.kind == ActuatorKind::ball_torque) {
      const bool hinge = a.kind == ActuatorKind::hinge_torque;
      const auto type = hinge ? multibody::JointType::hinge : multibody::JointType::ball;
      if (a.index < 0 || a.index >= p.system.joint_count() ||
          p.system.joints()[static_cast<std::size_t>(a.index)].type != type) {
        throw InvalidInput(fmt::format("{}: joint: got index {}; expected a {} joint", what, a.index,
                                       hinge ? "hinge" : "ball"));
      }
    } else if (a.index < 0 || a.index >= p.system.body_count()) {
      throw InvalidInput(
          fmt::format("{}: body: got index {}; expected 0 to {}", what, a.index, p.system.body_count() - 1));
    }
  }
}

/// Each rate bound on a hinge, > 0, and met by both boundary states. Throws InvalidInput.
void check_rate_bounds(const MultibodyProblem& p) {
  for (std::size_t i = 0; i < p.rate_bounds.size(); ++i) {
    const RateBound& b = p.rate_bounds[i];
    const std::string what = fmt::format("optimal control: rate_bounds[{}]", i);
    if (b.joint < 0 || b.joint >= p.system.joint_count() ||
        p.system.joints()[static_cast<std::size_t>(b.joint)].type != multibody::JointType::hinge) {
      throw InvalidInput(fmt::format("{}: joint: got index {}; expected a hinge joint", what, b.joint));
    }
    if (!(b.rate_max > 0.0))
      throw InvalidInput(fmt::format("{}: rate_max: got {} rad/s; expected a number > 0", what, b.rate_max));
    for (const auto& [state, name] :
         {std::pair{&p.initial_state, "initial"}, std::pair{&p.final_state, "final"}}) {
      const double rate = hinge_rate(p.system, *state, b.joint);
      if (std::abs(rate) > b.rate_max) {
        throw InvalidInput(
            fmt::format("{}: rate_max: the {} state's rate {} rad/s exceeds the bound {} rad/s; "
                        "expected boundary states within the bound",
                        what, name, rate, b.rate_max));
      }
    }
  }
}

/// Each free final hinge a hinge whose body_a hangs from it alone. Throws InvalidInput.
void check_free_final_hinges(const MultibodyProblem& p) {
  for (std::size_t k = 0; k < p.free_final_hinges.size(); ++k) {
    const int ji = p.free_final_hinges[k];
    const std::string what = fmt::format("optimal control: free_final_hinges[{}]", k);
    if (ji < 0 || ji >= p.system.joint_count() ||
        p.system.joints()[static_cast<std::size_t>(ji)].type != multibody::JointType::hinge) {
      throw InvalidInput(fmt::format("{}: got joint index {}; expected a hinge joint", what, ji));
    }
    const int body = p.system.joints()[static_cast<std::size_t>(ji)].body_a;
    for (int other = 0; other < p.system.joint_count(); ++other) {
      const multibody::Joint& j = p.system.joints()[static_cast<std::size_t>(other)];
      if (other != ji && (j.body_a == body || j.body_b == body)) {
        throw InvalidInput(
            fmt::format("{}: hinge '{}': its body_a is also in joint '{}'; expected a hinge whose body_a "
                        "hangs from it alone",
                        what, p.system.joints()[static_cast<std::size_t>(ji)].name, j.name));
      }
    }
  }
}

/// Each no-twist condition on a ball joint, with a unit axis and a rotation, met by both boundary states.
/// Throws InvalidInput.
void check_no_twist(const MultibodyProblem& p) {
  for (std::size_t i = 0; i < p.no_twist.size(); ++i) {
    const NoTwist& c = p.no_twist[i];
    const std::string what = fmt::format("optimal control: no_twist[{}]", i);
    if (c.joint < 0 || c.joint >= p.system.joint_count() ||
        p.system.joints()[static_cast<std::size_t>(c.joint)].type != multibody::JointType::ball) {
      throw InvalidInput(fmt::format("{}: joint: got index {}; expected a ball joint", what, c.joint));
    }
    if (!(std::abs(c.axis_a.norm() - 1.0) <= 1e-9))
      throw InvalidInput(
          fmt::format("{}: axis_a: got norm {}; expected a unit vector", what, c.axis_a.norm()));
    const double orthogonality = (c.straight.transpose() * c.straight - Mat3::Identity()).norm();
    if (!(orthogonality <= 1e-9) || !(c.straight.determinant() > 0.0)) {
      throw InvalidInput(fmt::format("{}: straight: got ‖CᵀC − I‖ = {:.3g}, det {:.3g}; expected a rotation",
                                     what, orthogonality, c.straight.determinant()));
    }
    for (const auto& [state, name] :
         {std::pair{&p.initial_state, "initial"}, std::pair{&p.final_state, "final"}}) {
      const double twist = twist_residual(p.system, *state, c);
      if (!(std::abs(twist) <= 1e-9)) {
        throw InvalidInput(
            fmt::format("{}: the {} state has the twist {:.3g}; expected boundary states without twist", what,
                        name, twist));
      }
    }
  }
}

/// A free-floating system with internal torques only: zero linear momentum for minimum time, and the same
/// momenta (P, H, M x_com − t P) in both boundary states. Throws InvalidInput.
void check_momenta(const MultibodyProblem& p) {
  if (detail::conserves_momenta(p) && p.objective == MultibodyObjective::minimum_time) {
    const double P = multibody::linear_momentum(p.system, p.initial_state).norm();
    double scale = 0.0;
    for (const multibody::Body& b : p.system.bodies())
      scale += b.mass * p.system.length_scale() / p.final_time;
    if (P > 1e-9 * scale) {
      throw InvalidInput(fmt::format(
          "optimal control: initial state: a free-floating system with linear momentum {:.3g} kg·m/s; "
          "expected 0 for minimum_time (its centre of mass at T would depend on T)",
          P));
    }
  }
  if (detail::conserves_momenta(p)) {
    // Free floating with internal torques only: P, H and M x_com − t P cannot change.
    const Eigen::VectorXd q0 = detail::conserved_quantities(p.system, p.initial_state, 0.0);
    const Eigen::VectorXd qf = detail::conserved_quantities(p.system, p.final_state, p.final_time);
    double scale = 0.0;
    for (const multibody::Body& b : p.system.bodies())
      scale += b.mass * p.system.length_scale();
    scale = std::max({scale, q0.cwiseAbs().maxCoeff(), qf.cwiseAbs().maxCoeff()});
    const double gap = (qf - q0).cwiseAbs().maxCoeff();
    if (gap > 1e-9 * scale) {
      throw InvalidInput(fmt::format(
          "optimal control: final state: its momenta (P, H, M x_com − t P) differ from the initial "
          "state's by {:.3g}; expected equal (a free-floating system with hinge motors only "
          "conserves them)",
          gap));
    }
  }
}

}  // namespace

void validate(const MultibodyProblem& p) {
  check_times_and_mesh(p);
  check_system_supported(p);
  check_actuators(p);
  check_state(p, p.initial_state, "initial state");
  check_state(p, p.final_state, "final state");
  check_rate_bounds(p);
  check_free_final_hinges(p);
  check_no_twist(p);
  check_momenta(p);
}

double twist_residual(const multibody::System& system, const multibody::State& state,
                      const NoTwist& condition) {
  const multibody::Joint& j = system.joints()[static_cast<std::size_t>(condition.joint)];
  const Mat3 M = condition.straight.transpose() *
                 multibody::side_state(state.bodies, j.body_a).R_space_body.transpose() *
                 multibody::side_state(state.bodies, j.body_b).R_space_body;
  const Mat3 W = M - M.transpose();
  return condition.axis_a.dot(Vec3(W(2, 1), W(0, 2), W(1, 0)));
}

namespace {

/// The index of the joint named `name` whose type is one of `types` (called `kind` in the message;
/// multibody_problem.hpp).
int named_joint_index(const multibody::System& system, const std::string& name,
                      std::initializer_list<multibody::JointType> types, std::string_view kind) {
  std::string names;
  for (std::size_t j = 0; j < system.joints().size(); ++j) {
    const multibody::Joint& joint = system.joints()[j];
    if (std::find(types.begin(), types.end(), joint.type) == types.end()) continue;
    if (joint.name == name) return static_cast<int>(j);
    names += (names.empty() ? "\"" : ", \"") + joint.name + "\"";
  }
  throw InvalidInput(fmt::format("got \"{}\", expected the name of a {} joint ({})", name, kind,
                                 names.empty() ? "the system has none" : names));
}

}  // namespace

int hinge_index(const multibody::System& system, const std::string& name) {
  return named_joint_index(system, name, {multibody::JointType::hinge}, "hinge");
}

int ball_index(const multibody::System& system, const std::string& name) {
  return named_joint_index(system, name, {multibody::JointType::ball}, "ball");
}

Actuator joint_motor(const multibody::System& system, const std::string& name, double torque_max) {
  const int j = named_joint_index(system, name, {multibody::JointType::hinge, multibody::JointType::ball},
                                  "hinge or ball");
  const bool hinge = system.joints()[static_cast<std::size_t>(j)].type == multibody::JointType::hinge;
  return {hinge ? ActuatorKind::hinge_torque : ActuatorKind::ball_torque, j, torque_max};
}

double hinge_rate(const multibody::System& system, const multibody::State& state, int joint) {
  const multibody::Joint& j = system.joints()[static_cast<std::size_t>(joint)];
  const auto& a = multibody::side_state(state.bodies, j.body_a);
  const auto& b = multibody::side_state(state.bodies, j.body_b);
  const Vec3 axis_a = j.hinge_axis_a();
  return axis_a.dot(a.omega_body - a.R_space_body.transpose() * b.R_space_body * b.omega_body);
}

}  // namespace poinsot::optimal
