// The multibody model: validation of bodies, joints and loads (model.hpp).
#include "poinsot/multibody/model.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/multibody/joint_types.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::multibody {
namespace {

// A unit vector perpendicular to the unit vector n (deterministic choice).
Vec3 any_perpendicular(const Vec3& n) {
  const Vec3 trial = std::abs(n.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  return n.cross(trial).normalized();
}

Vec3 unit_axis(const std::string& what, const Vec3& axis) {
  require_finite(what, axis);
  const double norm = axis.norm();
  if (!(norm > 0.0)) {
    throw InvalidInput(
        fmt::format("{}: axis {} is zero; expected a non-zero vector", what, format_vector(axis)));
  }
  return axis / norm;
}

// The three rows that freeze the relative rotation at R_b_a = R_bᵀR_a (weld, prismatic): R_a e_k = R_b (R_b_a
// e_k), so the pairs (e1, C e2), (e2, C e3), (e3, C e1) are perpendicular at the frozen rotation, and their
// three rows are independent there (their normals are ∓ the three axes).
void freeze_relative_rotation(const std::string& what, Joint& j, const Mat3& R_b_a) {
  require_finite(what + ": relative rotation", R_b_a);
  if (!so3::is_rotation(R_b_a)) {
    throw InvalidInput(fmt::format("{}: relative rotation {} is not a rotation; expected RᵀR = I, det R = +1",
                                   what, format_matrix(R_b_a)));
  }
  j.perpendicular_count = 3;
  for (int k = 0; k < 3; ++k) {
    j.p_a[static_cast<std::size_t>(k)] = Mat3::Identity().col(k);
    j.u_b[static_cast<std::size_t>(k)] = R_b_a.col((k + 1) % 3);
  }
}

/// A joint of `type` named `name` joining point_a of body_a to point_b of body_b (body frames, m), its rows
/// still to be filled by its add_* function.
Joint joint_between(const std::string& name, JointType type, int body_a, const Vec3& point_a, int body_b,
                    const Vec3& point_b) {
  Joint j;
  j.name = name;
  j.type = type;
  j.body_a = body_a;
  j.body_b = body_b;
  j.point_a = point_a;
  j.point_b = point_b;
  return j;
}

}  // namespace

int System::add_body(const std::string& name, double mass, const Mat3& poinsot_com_body) {
  const std::string what = fmt::format("multibody body '{}'", name);
  require_positive(what + ": mass", mass, "kg");
  require_finite(what + ": Poinsot tensor K", poinsot_com_body);
  const double scale = std::max(poinsot_com_body.cwiseAbs().maxCoeff(), 1e-300);
  if ((poinsot_com_body - poinsot_com_body.transpose()).cwiseAbs().maxCoeff() > 1e-12 * scale) {
    throw InvalidInput(fmt::format("{}: Poinsot tensor K {} kg·m² is not symmetric; expected K = Kᵀ", what,
                                   format_matrix(poinsot_com_body)));
  }
  const Mat3 K = 0.5 * (poinsot_com_body + poinsot_com_body.transpose());
  const Eigen::SelfAdjointEigenSolver<Mat3> eig_k(K);
  if (eig_k.eigenvalues().minCoeff() < -1e-12 * scale) {
    throw InvalidInput(
        fmt::format("{}: Poinsot tensor K has eigenvalue {} kg·m²; expected K positive semi-definite", what,
                    format_number(eig_k.eigenvalues().minCoeff())));
  }
  const Mat3 J = K.trace() * Mat3::Identity() - K;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig_j(J);
  if (!(eig_j.eigenvalues().minCoeff() > 1e-12 * scale)) {
    throw InvalidInput(
        fmt::format("{}: inertia J = tr(K)I − K has principal moment {} kg·m²; expected J positive definite "
                    "(an ideal thin "
                    "rod has no moment about its axis: give it a radius)",
                    what, format_number(eig_j.eigenvalues().minCoeff())));
  }
  for (const Body& b : bodies_) {
    if (b.name == name)
      throw InvalidInput(fmt::format("{}: name already used; expected unique body names", what));
  }
  if (name == "world") throw InvalidInput("multibody body: name 'world' is reserved for the fixed frame");
  Body body;
  body.name = name;
  body.mass = mass;
  body.poinsot = K;
  body.inertia = J;
  body.inertia_inverse = J.inverse();
  bodies_.push_back(body);
  return body_count() - 1;
}

int System::add_body_from_inertia(const std::string& name, double mass, const Mat3& inertia_com_body) {
  require_finite(fmt::format("multibody body '{}': inertia J", name), inertia_com_body);
  const Mat3 K = 0.5 * inertia_com_body.trace() * Mat3::Identity() - inertia_com_body;
  return add_body(name, mass, K);
}

void System::check_body_index(const std::string& what, int index, bool world_allowed) const {
  if ((index == kWorld && world_allowed) || (index >= 0 && index < body_count())) return;
  throw InvalidInput(fmt::format("{}: body index {} out of range; expected 0..{}{}", what, index,
                                 body_count() - 1, world_allowed ? " or the world (-1)" : ""));
}

int System::add_joint(Joint joint) {
  const std::string what = fmt::format("multibody joint '{}'", joint.name);
  check_body_index(what + ": body a", joint.body_a, false);
  check_body_index(what + ": body b", joint.body_b, true);
  if (joint.body_a == joint.body_b) {
    throw InvalidInput(
        fmt::format("{}: joins body {} to itself; expected two different bodies", what, joint.body_a));
  }
  require_finite(what + ": point a", joint.point_a);
  require_finite(what + ": point b", joint.point_b);
  joints_.push_back(joint);
  return joint_count() - 1;
}

int System::add_ball(const std::string& name, int body_a, const Vec3& point_a, int body_b,
                     const Vec3& point_b) {
  Joint j = joint_between(name, JointType::ball, body_a, point_a, body_b, point_b);
  return add_joint(j);
}

int System::add_hinge(const std::string& name, int body_a, const Vec3& point_a, const Vec3& axis_a,
                      int body_b, const Vec3& point_b, const Vec3& axis_b) {
  const std::string what = fmt::format("multibody joint '{}'", name);
  const Vec3 ua = unit_axis(what + ": axis a", axis_a);
  const Vec3 ub = unit_axis(what + ": axis b", axis_b);
  Joint j = joint_between(name, JointType::hinge, body_a, point_a, body_b, point_b);
  j.perpendicular_count = 2;
  j.p_a[0] = any_perpendicular(ua);
  j.p_a[1] = ua.cross(j.p_a[0]);
  j.u_b[0] = ub;
  j.u_b[1] = ub;
  return add_joint(j);
}

int System::add_weld(const std::string& name, int body_a, const Vec3& point_a, int body_b,
                     const Vec3& point_b, const Mat3& R_b_a) {
  Joint j = joint_between(name, JointType::weld, body_a, point_a, body_b, point_b);
  freeze_relative_rotation(fmt::format("multibody joint '{}'", name), j, R_b_a);
  return add_joint(j);
}

int System::add_universal(const std::string& name, int body_a, const Vec3& point_a, const Vec3& axis_a,
                          int body_b, const Vec3& point_b, const Vec3& axis_b, double axis_offset) {
  const std::string what = fmt::format("multibody joint '{}'", name);
  Joint j = joint_between(name, JointType::universal, body_a, point_a, body_b, point_b);
  j.perpendicular_count = 1;
  j.p_a[0] = unit_axis(what + ": axis a", axis_a);
  j.u_b[0] = unit_axis(what + ": axis b", axis_b);
  require_finite(what + ": axis offset", axis_offset);
  j.axis_offset = axis_offset;
  return add_joint(j);
}

int System::add_prismatic(const std::string& name, int body_a, const Vec3& point_a, const Vec3& axis_a,
                          int body_b, const Vec3& point_b, const Mat3& R_b_a) {
  const std::string what = fmt::format("multibody joint '{}'", name);
  const Vec3 axis = unit_axis(what + ": axis a", axis_a);
  Joint j = joint_between(name, JointType::prismatic, body_a, point_a, body_b, point_b);
  freeze_relative_rotation(what, j, R_b_a);
  // The sliding direction in b's frame, and two unit normals: the line rows (constraints.hpp).
  const Vec3 axis_b = R_b_a * axis;
  j.sliding = true;
  j.n_b[0] = any_perpendicular(axis_b);
  j.n_b[1] = axis_b.cross(j.n_b[0]).normalized();
  return add_joint(j);
}

int System::add_spring(const Spring& spring) {
  const std::string what = fmt::format("multibody spring '{}'", spring.name);
  check_body_index(what + ": body a", spring.body_a, false);
  check_body_index(what + ": body b", spring.body_b, true);
  require_non_negative(what + ": stiffness", spring.stiffness, "N/m");
  require_non_negative(what + ": damping", spring.damping, "N·s/m");
  require_non_negative(what + ": rest length", spring.rest_length, "m");
  require_finite(what + ": point a", spring.point_a);
  require_finite(what + ": point b", spring.point_b);
  springs_.push_back(spring);
  return static_cast<int>(springs_.size()) - 1;
}

const char* joint_spring_coordinate_name(JointSpring::Coordinate coordinate) {
  switch (coordinate) {
    case JointSpring::Coordinate::a:
      return "a";
    case JointSpring::Coordinate::b:
      return "b";
    case JointSpring::Coordinate::first:
      return "first";
    case JointSpring::Coordinate::second:
      return "second";
    case JointSpring::Coordinate::third:
      return "third";
  }
  return "?";
}

int System::add_joint_spring(const JointSpring& spring) {
  if (spring.joint < 0 || spring.joint >= joint_count()) {
    throw InvalidInput(fmt::format("multibody joint spring: joint {} does not exist; expected 0 to {}",
                                   spring.joint, joint_count() - 1));
  }
  const Joint& j = joints_[static_cast<std::size_t>(spring.joint)];
  const std::string what = fmt::format("multibody joint '{}': spring", j.name);
  if (j.type == JointType::weld) {
    throw InvalidInput(fmt::format(
        "{}: the joint is a weld; expected a hinge, a prismatic, a universal or a ball joint", what));
  }
  using C = JointSpring::Coordinate;
  const C c = spring.coordinate;
  const bool universal_angle = c == C::a || c == C::b;
  const bool ball_angle = c == C::first || c == C::second || c == C::third;
  if ((j.type == JointType::universal && !universal_angle) || (j.type == JointType::ball && !ball_angle) ||
      ((j.type == JointType::hinge || j.type == JointType::prismatic) && c != C::a)) {
    throw InvalidInput(fmt::format("{}: coordinate \"{}\" does not belong to a {} joint; expected {}", what,
                                   joint_spring_coordinate_name(c), joint_type_info(j.type).name,
                                   j.type == JointType::universal ? "\"a\" or \"b\""
                                   : j.type == JointType::ball    ? "\"first\", \"second\" or \"third\""
                                                                  : "\"a\", the joint's only coordinate"));
  }
  const bool hinge = j.type != JointType::prismatic;
  require_non_negative(what + ": stiffness", spring.stiffness, hinge ? "N·m/rad" : "N/m");
  require_non_negative(what + ": damping", spring.damping, hinge ? "N·m·s/rad" : "N·s/m");
  require_finite(what + ": rest position", spring.rest_position);
  require_finite(what + ": offset", spring.offset);
  if (j.type == JointType::universal) {
    require_finite(what + ": zero rotation", spring.R_b_a_zero);
    if (!so3::is_rotation(spring.R_b_a_zero) ||
        std::abs((spring.R_b_a_zero * j.p_a[0]).dot(j.u_b[0])) > 1e-6) {
      throw InvalidInput(
          fmt::format("{}: zero rotation {} does not carry the axis of body a perpendicular to the axis of "
                      "body b; expected a rotation R_b_a with (R_b_a·axis_a)·axis_b = 0",
                      what, format_matrix(spring.R_b_a_zero)));
    }
  } else if (j.type == JointType::ball) {
    require_finite(what + ": zero rotation", spring.R_b_a_zero);
    if (!so3::is_rotation(spring.R_b_a_zero)) {
      throw InvalidInput(fmt::format("{}: zero rotation {} is not a rotation; expected RᵀR = I, det R = +1",
                                     what, format_matrix(spring.R_b_a_zero)));
    }
    JointSpring unit = spring;
    for (std::size_t k = 0; k < 3; ++k)
      unit.hinge_axes[k] = unit_axis(fmt::format("{}: hinge axis {}", what, k + 1), spring.hinge_axes[k]);
    const auto& e = unit.hinge_axes;
    if (std::abs(e[0].dot(e[1])) > 1e-9 || std::abs(e[1].dot(e[2])) > 1e-9 ||
        std::abs(e[0].cross(e[1]).dot(e[2])) < 1e-6) {
      throw InvalidInput(fmt::format(
          "{}: hinge axes {}, {}, {} are not three hinges that a ball joint stands for; expected the second "
          "perpendicular to the first and the third, and the third not along the first",
          what, format_vector(e[0]), format_vector(e[1]), format_vector(e[2])));
    }
    joint_springs_.push_back(unit);
    return static_cast<int>(joint_springs_.size()) - 1;
  } else if (hinge) {
    require_finite(what + ": zero rotation", spring.R_b_a_zero);
    const Vec3 axis_a = j.hinge_axis_a();
    if (!so3::is_rotation(spring.R_b_a_zero) || (spring.R_b_a_zero * axis_a - j.u_b[0]).norm() > 1e-6) {
      throw InvalidInput(
          fmt::format("{}: zero rotation {} does not carry the axis of body a onto the axis of body b; "
                      "expected a rotation "
                      "R_b_a with R_b_a·axis_a = axis_b",
                      what, format_matrix(spring.R_b_a_zero)));
    }
  }
  joint_springs_.push_back(spring);
  return static_cast<int>(joint_springs_.size()) - 1;
}

void System::add_force(const ConstantForce& force) {
  check_body_index("multibody force: body", force.body, false);
  require_finite("multibody force: force", force.force_space);
  require_finite("multibody force: point", force.point_body);
  forces_.push_back(force);
}

void System::add_torque(const ConstantTorque& torque) {
  check_body_index("multibody torque: body", torque.body, false);
  require_finite("multibody torque: torque", torque.torque);
  torques_.push_back(torque);
}

void System::set_gravity(const Vec3& gravity_space) {
  require_finite("multibody: gravity", gravity_space);
  gravity_ = gravity_space;
}

int System::body_index(const std::string& name) const {
  if (name == "world") return kWorld;
  for (int i = 0; i < body_count(); ++i) {
    if (bodies_[static_cast<std::size_t>(i)].name == name) return i;
  }
  throw InvalidInput(fmt::format("multibody: body '{}' not found; expected 'world' or one of the {} bodies",
                                 name, body_count()));
}

int System::constraint_rows() const {
  int rows = 0;
  for (const Joint& j : joints_)
    rows += j.rows();
  return rows;
}

double System::length_scale() const {
  double scale = 1e-3;
  for (const Body& b : bodies_)
    scale = std::max(scale, std::sqrt(b.poinsot.trace() / b.mass));
  for (const Joint& j : joints_) {
    scale = std::max(scale, j.point_a.norm());
    if (j.body_b != kWorld) scale = std::max(scale, j.point_b.norm());
  }
  return scale;
}

}  // namespace poinsot::multibody
