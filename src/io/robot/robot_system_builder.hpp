#pragma once
// Internal to io/robot: the builder of a robot file's multibody scenario (robot_system.hpp). Its steps: order
// the links (sort_links), read the initial joint coordinates (read_coordinates), pose the links (pose_links),
// make the bodies (place_links; robot_system.cpp), then the joints and the loops (robot_system_joints.cpp)
// and the drawn surfaces.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "robot_kinematics.hpp"

namespace poinsot::io::detail {

/// A link's place in the system: the body it belongs to (or the world) and its frame in that body's link
/// frame (the identity for a link that is its own body).
struct LinkPlace {
  int body = multibody::kWorld;
  RigidPose in_body;
  bool own = false;  ///< the link is the body (not a frame of another body or of the world)
};

/// The velocity field of a rigid motion: v(x) = v0 + ω × x (space frame).
struct Twist {
  Vec3 omega = Vec3::Zero();
  Vec3 v0 = Vec3::Zero();
  Vec3 at(const Vec3& x) const { return v0 + omega.cross(x); }
};

/// The mass properties of a link in its own frame, and how they were obtained.
struct LinkInertia {
  inertia::MassProperties props;
  std::string how;
};

/// "FILE:LINE: ELEMENT", the place of an element in messages (its own file's, for an MJCF <include>).
inline std::string line_of(const SourceLines& lines, int line, const std::string& element) {
  return fmt::format("{}: {}", lines.location(line), element);
}

/// Runs f(), prefixing the message of an InvalidInput it throws with `where`.
template <class F>
auto located_at(const std::string& where, F&& f) {
  try {
    return f();
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", where, e.what()));
  }
}

/// The state of the build: the file's tree, where each link ends up, and the scenario being made.
struct RobotSystemBuilder {
  const RobotModel& model;
  const RobotSystemOptions& options;
  RobotTree tree;
  multibody::Scenario sc;
  std::vector<LinkPlace> place;
  std::vector<LinkInertia> inertia;
  std::vector<RigidPose> pose;            ///< per link, space, at the initial coordinates
  std::vector<RigidPose> pose0;           ///< per link, space, at the file's configuration
  std::vector<Twist> twist;               ///< per link, at the initial coordinates
  std::vector<int> order;                 ///< links, parents first
  std::vector<std::size_t> link_of_body;  ///< per body, its link
  std::map<std::string, std::vector<const RobotDof*>> dofs_by_name;
  std::map<const RobotDof*, std::vector<double>> q, qd;  // per dof, the initial coordinates
  int floating_bases = 0;

  RobotSystemBuilder(const RobotModel& m, const RobotSystemOptions& o, RobotTree t)
      : model(m), options(o), tree(std::move(t)) {}

  const RobotJointSpec* spec_of(std::size_t k) const {
    const int j = tree.joint_of_link[k];
    return j < 0 ? nullptr : &tree.joints[static_cast<std::size_t>(j)];
  }

  std::string where(const RobotJointSpec& j) const { return line_of(model.lines, j.line, j.element); }

  std::string where_link(std::size_t k) const {
    return line_of(model.lines, model.links[k].line,
                   fmt::format("<{} name=\"{}\">", model.format == RobotFormat::mjcf ? "body" : "link",
                               model.links[k].name));
  }

  /// Parents before children; a cycle of joints is a kinematic loop.
  void sort_links();

  /// The options' joint positions and velocities by name, checked against the file's joints; a position is
  /// kept as the displacement from the file's pose.
  void read_coordinates();

  /// A joint's initial displacement (velocity false) or rate: the options' values, else the file's pose and
  /// rest.
  const double* coordinate(const RobotDof& d, bool velocity) const {
    static const double zero_q[4] = {1.0, 0.0, 0.0, 0.0};  // the identity quaternion for a ball
    static const double zeros[4] = {0.0, 0.0, 0.0, 0.0};
    const auto& map = velocity ? qd : q;
    const auto it = map.find(&d);
    if (it != map.end()) return it->second.data();
    return (!velocity && d.kind == RobotDof::Kind::ball) ? zero_q : zeros;
  }

  /// Poses (at the initial and at the file's coordinates) and twists of every link.
  void pose_links();

  /// The floating base: the URDF root with floating_base, or a free body of MJCF or SDF.
  void set_base(std::size_t u);

  /// Bodies: every link with mass, except those fixed to the world; links without mass attached by a fixed
  /// joint become frames of their parent's body (or of the world).
  void place_links();

  /// Link u as a body of the system, with its initial state.
  void add_body(std::size_t u);

  /// The body frame (from the centre of mass) coordinates of a point given in link k's frame.
  Vec3 body_point(std::size_t k, const Vec3& x_link) const {
    const LinkPlace& p = place[k];
    const Vec3 x = p.in_body * x_link;
    if (p.body == multibody::kWorld) return x;
    return x - inertia[body_link(p.body)].props.com;
  }

  /// The link of body b.
  std::size_t body_link(int b) const { return link_of_body[static_cast<std::size_t>(b)]; }

  /// Link k's frame in its body's link frame at the initial state (space for the world).
  RigidPose body_frame(int b) const {
    if (b == multibody::kWorld) return RigidPose{};
    return pose[body_link(b)];
  }

  /// The same at the file's configuration.
  RigidPose body_frame0(int b) const {
    if (b == multibody::kWorld) return RigidPose{};
    return pose0[body_link(b)];
  }

  /// Each body's joint to its parent: a weld for a fixed link, else add_moving_joint
  /// (robot_system_joints.cpp).
  void add_joints();

  /// The multibody joint of the file's moving joint j between body a (the child) and body b: a hinge or a
  /// prismatic joint (with its spring-damper), a ball, or MJCF hinges about one point merged into a universal
  /// or a ball joint; anything else is refused with one line naming the joints.
  void add_moving_joint(const RobotJointSpec& j, int a, int b, const RigidPose& b_child, const Vec3& c_a,
                        const Vec3& c_b);

  /// Each body's drawn surface (view.html): the shapes of its link and of the frames merged into it, about
  /// its centre of mass in its frame; meshes too.
  void add_surfaces();

  /// The loops that MJCF's <equality> closes: connect as a ball joint, weld as a weld.
  void add_loops();
};

}  // namespace poinsot::io::detail
