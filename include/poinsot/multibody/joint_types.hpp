#pragma once
/// @file joint_types.hpp
/// The table of joint types: for each, the name used by scenario files, the CLI and Python, its rows (the
/// constraint equations are in constraints.hpp), the relative degrees of freedom it leaves, the axes it takes
/// and a one-line description. Scenario parsing, error messages and documentation lists derive from it.

#include <span>
#include <string>
#include <string_view>

#include "poinsot/multibody/model.hpp"

namespace poinsot::multibody {

/// How a joint type uses the two axis keys `axis_a` (body a frame) and `axis_b` (body b frame).
enum class JointAxes {
  none,      ///< no axis (ball, weld)
  parallel,  ///< axis_a required, axis_b kept parallel to it (default: axis_a as placed at t = 0)
  crossed,   ///< axis_a and axis_b both required, kept perpendicular (the cross-pin axes)
  sliding,   ///< axis_a required: the sliding direction, fixed in both bodies
};

struct JointTypeInfo {
  JointType type;
  std::string_view name;         ///< "ball", "hinge", ...: the scenario key `type` and Python's name
  int rows;                      ///< constraint rows
  JointAxes axes;                ///< which axis keys it takes
  bool fixed_relative_rotation;  ///< the relative rotation R_bᵀR_a is frozen at its value at t = 0
  std::string_view description;  ///< one line: what it keeps and what it leaves free
};

/// Every joint type, in a fixed order.
std::span<const JointTypeInfo> joint_types();
/// The entry of `type`.
const JointTypeInfo& joint_type_info(JointType type);
/// The entry named `name`, or null.
const JointTypeInfo* find_joint_type(std::string_view name);
/// The names for messages: "\"ball\", \"hinge\", \"weld\", \"universal\" or \"prismatic\"".
std::string joint_type_names();

}  // namespace poinsot::multibody
