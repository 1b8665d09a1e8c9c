#pragma once
/// @file multibody_controls.hpp (internal)
/// The system of a multibody problem with the actuators' torques `u` (actuator order, N·m) added as constant
/// body-frame torques: a hinge motor u gives u·axis_a on body a and −u·axis_b on body b (the same couple in
/// space while the hinge holds), a body torque its three components. Used to re-simulate a control history
/// and to evaluate the exact multipliers at a state of the optimum.
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::detail {

multibody::System system_with_controls(const MultibodyProblem& problem, const Eigen::VectorXd& u);

}  // namespace poinsot::optimal::detail
