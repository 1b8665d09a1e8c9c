#pragma once
/// @file robot_system.hpp
/// A robot description file — URDF, MJCF (MuJoCo) or SDF (Gazebo) — as a multibody system
/// (multibody/model.hpp) ready to run: one body per link that has mass, one joint of the multibody layer per
/// joint of the file, the initial state from joint coordinates given by the joints' names.
/// docs/robot_models.md ("Robot files as multibody systems") states the conventions; in short:
///
///  * Links: mass, centre of mass and tensor from the file (robot_model.hpp), or, with
///    RobotInertiaSource::geometry, the tensor of the link's geometry at the file's mass about the file's
///    centre of mass (as `poinsot inertia check --from-geometry`; a link without shapes keeps its tensor).
///    MJCF bodies without <inertial> (or all bodies with <compiler inertiafromgeom="true">) take it from
///    their geoms as MuJoCo does: each geom of uniform density (its `density`, 1000 kg/m³ by default) or of
///    its `mass`. SDF links without <inertial> take SDF's default (1 kg, J = I kg·m²). A link without mass
///    attached by a fixed joint is a frame of its parent (no body); one that moves is refused.
///  * Joints, each in its child link's frame: URDF revolute/continuous → hinge, prismatic → prismatic,
///    fixed → weld, floating → none (a free body); the root link is fixed to the world (`floating_base` frees
///    it). MJCF: hinge, slide → prismatic, ball, free → none; a body without joints is welded to its parent;
///    two perpendicular hinges → universal (with an axis offset when they turn about different points),
///    three hinges about one point → ball (the composition MuJoCo integrates); <equality><connect> → ball and
///    <weld> → weld joints closing loops, at the file's configuration. SDF: revolute/continuous, prismatic,
///    ball, fixed, universal (axis fixed in the parent, axis2 in the child); a link without a joint is free,
///    parent `world` is the world.
///  * A hinge's or slide's spring and damper → multibody::JointSpring (RobotSystemOptions::joint_springs).
///  * Not modelled (contacts, limits, friction, armature, actuators, tendons, transmissions, the springs of
///    MJCF ball joints and of three hinges whose second axis is not perpendicular to the others): listed one
///    line each in Scenario::not_modelled, which the run report prints.
/// Scenario::body_surfaces draws each body as its link's shapes and meshes. Bodies carry their link's name
/// and joints their file joint's name (two or three MJCF hinges merged into one joint: their names joined by
/// '+'), so reactions and Λ are reported per link.

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::io {

/// Where each link's inertia tensor comes from.
enum class RobotInertiaSource {
  file,      ///< the file's <inertial> (MJCF: its geoms where MuJoCo takes them)
  geometry,  ///< the link's geometry at the file's mass, about the file's centre of mass (a link without
             ///< shapes keeps the file's tensor)
};

/// The initial state and the choices a scenario makes about a robot file.
struct RobotSystemOptions {
  RobotInertiaSource inertia = RobotInertiaSource::file;
  bool floating_base = false;  ///< URDF: the root link is a free body instead of fixed to the world
  /// The files' joint springs and dampers on hinges and slides (multibody::JointSpring); false leaves them
  /// out and lists them as not modelled (as a peer with its passive forces switched off).
  bool joint_springs = true;
  std::optional<Vec3> gravity;  ///< m/s², space frame; default: the file's (MJCF <option>, SDF <world>),
                                ///< else (0, 0, −9.81)
  /// Joint positions by the file's joint names, in the file's coordinates: hinge rad, slide m (1 number), SDF
  /// universal (2: about axis, then axis2), ball (a unit quaternion w x y z of the child relative to its file
  /// pose). Default: the file's pose (an MJCF joint's `ref`, else 0).
  std::map<std::string, std::vector<double>> positions;
  /// Joint velocities: hinge rad/s, slide m/s (1), universal (2), ball (ω, rad/s, child frame: 3).
  std::map<std::string, std::vector<double>> velocities;
  /// The floating base (the URDF root with floating_base; the one free body of MJCF or SDF; a URDF floating
  /// joint's child starts at rest where its joint places it): the pose of its link frame in space (default:
  /// the file's), the velocity of the link frame's origin (m/s, space) and its angular velocity (rad/s, link
  /// frame).
  std::optional<Vec3> base_position;
  std::optional<Mat3> base_rotation;
  std::optional<Vec3> base_velocity;
  std::optional<Vec3> base_omega_body;
};

/// The multibody scenario of a robot model read by read_robot_model (its `text` is read again for the
/// joints): system, initial state (velocities projected onto the joints), gravity; dt, duration and method
/// keep multibody::Scenario's defaults. Throws InvalidInput, one line naming the element and its line: a
/// joint whose parent or child link is missing, a link that is the child of two joints or a cycle of joints
/// (a kinematic loop in a URDF), a link without mass that moves, an axis of zero length, a joint type or an
/// element it does not model (named), an invalid inertia; and, for the options, `positions.NAME: ...` naming
/// the joint, the values and what was expected.
multibody::Scenario robot_scenario(const RobotModel& model, const RobotSystemOptions& options = {});

/// Reads the file `path` (URDF, MJCF or SDF by its root element) and builds its scenario.
multibody::Scenario load_robot_scenario(const std::string& path, const RobotSystemOptions& options = {});

/// True when `path` names a robot file by its extension: .urdf, .xml, .sdf (case-insensitive).
bool is_robot_file(const std::string& path);

}  // namespace poinsot::io
