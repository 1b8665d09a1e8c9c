#pragma once
// Internal to the io layer: the kinematic tree of a robot description file (URDF, MJCF or SDF) as the file
// states it, read by robot_urdf_joints.cpp, robot_mjcf_joints.cpp and robot_sdf_joints.cpp and turned into a
// multibody system by robot_system.cpp (io/robot/robot_system.hpp). Links are those of RobotModel::links, by
// index.
//
// Every joint is written in its child link's frame, whatever the format: the child's frame at the reference
// configuration (all joint coordinates 0) has the pose `parent_child` in its parent's frame, and the joint's
// elementary motions ("degrees of freedom", several for an MJCF body with several joints) are applied after
// it, each about an anchor and along an axis given in the child's frame:
//
//     T_parent_child(q) = parent_child · M_1(q_1) · M_2(q_2) · ...
//     hinge:  M = (Rot(a, q), p − Rot(a, q) p)      (a rotation by q rad about the axis a through p)
//     slide:  M = (I, a q)                          (a translation by q m along a)
//     ball:   M = (Rot(Q), p − Rot(Q) p)            (Q a unit quaternion w x y z)
//
// which is how MuJoCo composes the joints of a body (each in the frame left by the previous ones), how URDF
// moves a child about its joint frame (the child's frame, anchor at its origin), and how SDF moves a child
// about the joint's pose in the child frame.
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "xml_source.hpp"

namespace poinsot::io::detail {

/// A rigid transform: x_outer = R x_inner + p.
struct RigidPose {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
  RigidPose operator*(const RigidPose& inner) const { return {R * inner.R, R * inner.p + p}; }
  Vec3 operator*(const Vec3& x) const { return R * x + p; }
  RigidPose inverse() const { return {R.transpose(), -(R.transpose() * p)}; }
};

/// One elementary motion of a joint (see above).
struct RobotDof {
  enum class Kind { hinge, slide, ball };
  Kind kind = Kind::hinge;
  std::string name;                  ///< the file's joint name (an MJCF body's joints each have their own)
  int line = 0;                      ///< line of its element
  Vec3 axis_child = Vec3::UnitZ();   ///< unit axis, child frame (hinge, slide)
  Vec3 anchor_child = Vec3::Zero();  ///< m, child frame
  /// The coordinate (rad or m) at which the child has its pose in the file (MJCF `ref`, else 0): the
  /// joint positions given by name are in the file's coordinates, and the motion above is by q − reference.
  double reference = 0.0;
  /// A hinge's or slide's spring-damper, as the file states it (MJCF stiffness, damping, springref; URDF
  /// <dynamics damping>; SDF <axis><dynamics>): Q = −stiffness (q − spring_reference) − damping q̇, in N·m
  /// and rad for a hinge, N and m for a slide.
  double stiffness = 0.0;
  double damping = 0.0;
  double spring_reference = 0.0;
};

/// How a link is attached to its parent.
enum class RobotJointKind {
  fixed,  ///< no motion (URDF fixed, SDF fixed, an MJCF body without joints)
  free,   ///< six degrees of freedom (URDF floating, MJCF free, an SDF link without a joint)
  dofs,   ///< the elementary motions `dofs`
};

/// The joint that attaches `child` to `parent`.
struct RobotJointSpec {
  std::string name;     ///< the joint's name (an MJCF body: its first joint's, or the body's)
  std::string element;  ///< "<joint name=...>" for messages
  int line = 0;
  RobotJointKind kind = RobotJointKind::fixed;
  int parent = -1;             ///< link index, or -1: the world
  int child = 0;               ///< link index
  RigidPose parent_child;      ///< the child's frame in the parent's (space for the world), at q = 0
  std::vector<RobotDof> dofs;  ///< kind dofs: in order of application
};

/// A loop-closing joint (MJCF <equality><connect> or <weld>).
struct RobotLoopSpec {
  std::string name;
  std::string element;
  int line = 0;
  bool weld = false;            ///< weld (relative pose frozen) or connect (a ball joint)
  int body1 = 0;                ///< link index
  int body2 = -1;               ///< link index, or -1: the world
  Vec3 anchor1 = Vec3::Zero();  ///< m, body1's frame
};

/// The kinematic tree of a file.
struct RobotTree {
  /// Per link (RobotModel::links order): the joint that has it as child, or -1 (a root: see root_kind).
  std::vector<int> joint_of_link;
  std::vector<RobotJointSpec> joints;
  std::vector<RobotLoopSpec> loops;
  /// Root links (no joint): their pose in space at q = 0; MJCF and SDF give one for every link.
  std::vector<RigidPose> root_pose;  ///< per link; used only for roots
  bool has_gravity = false;
  Vec3 gravity = Vec3(0.0, 0.0, -9.81);  ///< m/s², when the file gives one (has_gravity)
  /// What the file states that the multibody model does not include, one line each ("<element> line N: ...").
  std::vector<std::string> not_modelled;
  /// Per link, MJCF: the inertia from the bodies' geoms when the file asks for it (no <inertial>, or
  /// <compiler inertiafromgeom="true">); empty otherwise.
  std::vector<bool> inertia_from_geoms;
};

/// Readers of the tree; each throws InvalidInput (one line, `SOURCE:LINE: <element> ...`) for what it cannot
/// model: a joint whose parent or child is missing, a link that is the child of two joints (a loop in a
/// URDF), a joint type it does not support, an axis of zero length.
RobotTree read_urdf_tree(const XmlSource& xml, const RobotModel& model);
RobotTree read_mjcf_tree(const XmlSource& xml, const RobotModel& model);
RobotTree read_sdf_tree(const XmlSource& xml, const RobotModel& model);

/// The unit vector of the three numbers `v` written by `e` (attribute or element `what`); throws
/// `SOURCE:LINE: <e> what="...": zero length; expected a non-zero axis` when |v| = 0.
Vec3 unit_axis_of(const XmlSource& xml, const tinyxml2::XMLElement& e, const char* what, const Vec3& v);

/// "<joint name="NAME">" for messages.
std::string element_label(const tinyxml2::XMLElement& e);

}  // namespace poinsot::io::detail
