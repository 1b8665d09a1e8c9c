// The joints of a robot file's multibody scenario (robot_system_builder.hpp): each link's joint to its parent
// as a multibody joint (a weld, a hinge or prismatic joint with its spring-damper, a ball, a universal joint,
// or MJCF hinges of one body merged into one), and the loops that MJCF's <equality> closes.
#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "robot_system_builder.hpp"

namespace poinsot::io::detail {

using multibody::kWorld;

void RobotSystemBuilder::add_joints() {
  for (const int k : order) {
    const std::size_t u = static_cast<std::size_t>(k);
    const RobotJointSpec* j = spec_of(u);
    const LinkPlace& child = place[u];
    if (!child.own) continue;  // a frame of another body or of the world
    if (j != nullptr && j->kind == RobotJointKind::free) continue;
    if (j == nullptr && options.floating_base) continue;
    const int a = child.body;
    // The parent's body b and the child's frame in b's link frame, at the file's and the initial pose.
    const int b = j == nullptr || j->parent < 0 ? kWorld : place[static_cast<std::size_t>(j->parent)].body;
    const RigidPose b_frame = body_frame(b);
    const RigidPose b_child = b_frame.inverse() * pose[u];  // the child's frame in b's, now
    const Vec3 c_b = b == kWorld ? Vec3::Zero() : inertia[body_link(b)].props.com;
    const Vec3 c_a = inertia[u].props.com;
    const std::string name = j == nullptr ? model.links[u].name : j->name;
    const auto located = [&](auto&& f) {
      try {
        return f();
      } catch (const InvalidInput& e) {
        throw InvalidInput(fmt::format("{}: {}", j != nullptr ? where(*j) : where_link(u), e.what()));
      }
    };
    if (j == nullptr || j->kind == RobotJointKind::fixed) {
      located([&] { return sc.system.add_weld(name, a, -c_a, b, b_child.p - c_b, b_child.R); });
      continue;
    }
    add_moving_joint(*j, a, b, b_child, c_a, c_b);
  }
}

void RobotSystemBuilder::add_moving_joint(const RobotJointSpec& j, int a, int b, const RigidPose& b_child,
                                          const Vec3& c_a, const Vec3& c_b) {
  const auto located = [&](auto&& f) { return located_at(where(j), f); };
  // The frame before the joint's motions, in b's link frame: the anchors and the first axis are fixed in
  // it.
  const std::size_t parent_link = static_cast<std::size_t>(j.parent);
  const RigidPose b_before = j.parent < 0 ? j.parent_child : place[parent_link].in_body * j.parent_child;
  const auto& dofs = j.dofs;
  std::string name;
  for (const RobotDof& d : dofs)
    if (name.find(d.name) == std::string::npos) name += (name.empty() ? "" : "+") + d.name;
  const Vec3 anchor = dofs.front().anchor_child;
  const double scale = std::max(1.0, anchor.norm());
  const bool same_anchor = std::all_of(dofs.begin(), dofs.end(), [&](const RobotDof& d) {
    return (d.anchor_child - anchor).norm() <= 1e-12 * scale;
  });
  const bool all_hinges = std::all_of(dofs.begin(), dofs.end(),
                                      [](const RobotDof& d) { return d.kind == RobotDof::Kind::hinge; });
  const Vec3 pa = anchor - c_a;
  const Vec3 pb = b_before * anchor - c_b;
  // A hinge's or slide's spring-damper acts on its displacement from the file's configuration, where the
  // child's frame is b_before; a slide's points coincide at its initial displacement. Of two hinges merged
  // into a universal joint the first turns about the parent's axis (coordinate b), the second about the
  // child's (coordinate a); three hinges merged into a ball joint keep their order (first, second, third).
  const auto add_spring = [&](int joint, std::size_t dof = 0,
                              multibody::JointSpring::Coordinate angle =
                                  multibody::JointSpring::Coordinate::a) {
    const RobotDof& d = dofs[dof];
    if (d.stiffness == 0.0 && d.damping == 0.0) return;
    if (!options.joint_springs) {
      sc.not_modelled.push_back(fmt::format(
          "{}: the spring and damper of \"{}\" (left out: joint_springs = false)", where(j), d.name));
      return;
    }
    multibody::JointSpring s;
    s.joint = joint;
    s.coordinate = angle;
    s.stiffness = d.stiffness;
    s.damping = d.damping;
    s.rest_position = d.spring_reference - d.reference;
    s.R_b_a_zero = b_before.R;
    if (dofs.size() == 3) {
      for (std::size_t k = 0; k < 3; ++k)
        s.hinge_axes[k] = dofs[k].axis_child;
    }
    s.offset = coordinate(d, false)[0];
    located([&] { return sc.system.add_joint_spring(s); });
  };
  if (dofs.size() == 1 && dofs[0].kind == RobotDof::Kind::hinge) {
    add_spring(located([&] {
      return sc.system.add_hinge(name, a, pa, dofs[0].axis_child, b, pb, b_before.R * dofs[0].axis_child);
    }));
    return;
  }
  if (dofs.size() == 1 && dofs[0].kind == RobotDof::Kind::slide) {
    add_spring(located([&] {
      return sc.system.add_prismatic(name, a, pa, dofs[0].axis_child, b, b_child * anchor - c_b, b_child.R);
    }));
    return;
  }
  const bool universal =
      all_hinges && dofs.size() == 2 && std::abs(dofs[0].axis_child.dot(dofs[1].axis_child)) <= 1e-12;
  if (universal) {
    // The second hinge's anchor is fixed in the frame that the first turns: at the offset d from the first's
    // anchor, d = α e₁ + β e₂ + h e₂ × e₁ in the orthonormal frame of the axes (child frame, reference
    // pose). Point B on the first axis and point A on the second are then h apart along the common normal
    // e₂ × e₁ at every pose (model.hpp, add_universal); h = 0 when the axes meet.
    const Vec3& e1 = dofs[0].axis_child;
    const Vec3& e2 = dofs[1].axis_child;
    const Vec3 d = dofs[1].anchor_child - dofs[0].anchor_child;
    const Vec3 point_b = dofs[0].anchor_child + d.dot(e1) * e1;
    const Vec3 point_a = dofs[1].anchor_child - d.dot(e2) * e2;
    const double h = d.dot(e2.cross(e1));
    const int joint = located([&] {
      return sc.system.add_universal(name, a, point_a - c_a, e2, b, b_before * point_b - c_b, b_before.R * e1,
                                     std::abs(h) <= 1e-12 * scale ? 0.0 : h);
    });
    add_spring(joint, 0, multibody::JointSpring::Coordinate::b);
    add_spring(joint, 1, multibody::JointSpring::Coordinate::a);
    return;
  }
  const auto springs_not_modelled = [&](const char* why) {
    std::string sprung;
    for (const RobotDof& d : dofs) {
      if (d.stiffness != 0.0 || d.damping != 0.0) sprung += (sprung.empty() ? "\"" : ", \"") + d.name + "\"";
    }
    if (!sprung.empty())
      sc.not_modelled.push_back(fmt::format("{}: the springs and dampers of {} ({})", where(j), sprung, why));
  };
  if (dofs.size() == 1 && dofs[0].kind == RobotDof::Kind::ball) {
    springs_not_modelled("a ball joint's, on its quaternion");
    located([&] { return sc.system.add_ball(name, a, pa, b, pb); });
    return;
  }
  if (same_anchor && all_hinges && dofs.size() == 3) {
    const Vec3 &e1 = dofs[0].axis_child, &e2 = dofs[1].axis_child, &e3 = dofs[2].axis_child;
    if (std::abs(e1.dot(e2.cross(e3))) > 1e-9) {
      const int joint = located([&] { return sc.system.add_ball(name, a, pa, b, pb); });
      // The springs act on the three hinge angles where the second axis is perpendicular to the other two
      // and the third is not along the first (their angles are then defined everywhere but at the hinges'
      // gimbal lock; multibody::JointSpring).
      if (std::abs(e1.dot(e2)) <= 1e-12 && std::abs(e2.dot(e3)) <= 1e-12 &&
          std::abs(e1.dot(e2.cross(e3))) >= 1e-6) {
        add_spring(joint, 0, multibody::JointSpring::Coordinate::first);
        add_spring(joint, 1, multibody::JointSpring::Coordinate::second);
        add_spring(joint, 2, multibody::JointSpring::Coordinate::third);
      } else {
        springs_not_modelled(
            "three hinges merged into a ball joint whose second axis is not perpendicular "
            "to the first and the third");
      }
      return;
    }
  }
  std::string list;
  for (const RobotDof& d : dofs)
    list += fmt::format("{}{} \"{}\" ({})", list.empty() ? "" : ", ",
                        d.kind == RobotDof::Kind::hinge   ? "hinge"
                        : d.kind == RobotDof::Kind::slide ? "slide"
                                                          : "ball",
                        d.name, model.lines.label(d.line));
  throw InvalidInput(fmt::format(
      "{}: the joints {} of one body are not supported together{}; expected one hinge, slide or ball, two "
      "perpendicular hinges (a universal joint, its axes meeting or not) or three hinges about one point (a "
      "ball joint)",
      where(j), list, same_anchor ? "" : " (their anchors differ)"));
}

void RobotSystemBuilder::add_loops() {
  for (const detail::RobotLoopSpec& loop : tree.loops) {
    const std::size_t l1 = static_cast<std::size_t>(loop.body1);
    int b1 = place[l1].body;
    // body1's anchor in space at the file's configuration.
    const Vec3 anchor_space = pose0[l1] * loop.anchor1;
    int b2 = loop.body2 < 0 ? kWorld : place[static_cast<std::size_t>(loop.body2)].body;
    const auto frame0 = [&](int b) { return body_frame0(b); };
    const auto com = [&](int b) { return b == kWorld ? Vec3::Zero() : inertia[body_link(b)].props.com; };
    if (b1 == kWorld) std::swap(b1, b2);
    if (b1 == kWorld || b1 == b2) {
      throw InvalidInput(
          fmt::format("{}: both sides are fixed to the same body; expected two bodies that move relative "
                      "to each other",
                      line_of(model.lines, loop.line, loop.element)));
    }
    const Vec3 pa = frame0(b1).inverse() * anchor_space - com(b1);
    const Vec3 pb = frame0(b2).inverse() * anchor_space - com(b2);
    try {
      if (loop.weld) {
        const Mat3 R_b_a = frame0(b2).R.transpose() * frame0(b1).R;
        sc.system.add_weld(loop.name, b1, pa, b2, pb, R_b_a);
      } else {
        sc.system.add_ball(loop.name, b1, pa, b2, pb);
      }
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("{}: {}", line_of(model.lines, loop.line, loop.element), e.what()));
    }
  }
  if (!tree.loops.empty()) {
    sc.not_modelled.push_back(
        "<equality> softness (solref, solimp): the loops are closed exactly, as joints");
  }
}

}  // namespace poinsot::io::detail
