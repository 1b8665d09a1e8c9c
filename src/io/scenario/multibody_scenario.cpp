// Multibody scenario files: TOML → validated multibody::Scenario (see multibody_scenario.hpp).
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/work_limits.hpp"

#include <cmath>
#include <filesystem>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/joint_types.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot/so3/rotation_check.hpp"
#include "scenario_body.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

using detail::Section;
using detail::Source;
using multibody::kWorld;

}  // namespace

const toml::array* detail::table_array(const Section& section, std::string_view key) {
  const toml::node* n = section.node(key);
  if (n == nullptr) return nullptr;
  const toml::array* a = n->as_array();
  if (a == nullptr || (!a->empty() && !a->is_array_of_tables()))
    section.fail(key, fmt::format("got {}, expected an array of tables [[{}]]", detail::describe(*n), key));
  return a;
}

Mat3 detail::read_rotation(const Source& src, const Section& b) {
  if (b.has("quaternion") && b.has("rotation"))
    b.fail("quaternion", "given with rotation; expected one of them (the body's orientation)");
  if (const auto q = b.numbers("quaternion", 4)) {
    const Quat quat((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
    if (!(quat.norm() > 1e-12))
      b.fail("quaternion", "got a zero quaternion, expected [w, x, y, z] with a non-zero norm");
    return so3::rotation_from_quaternion(quat);
  }
  const toml::node* n = b.node("rotation");
  if (n == nullptr) return Mat3::Identity();
  if (const toml::table* t = n->as_table()) {
    const Section r(src, t, b.name() + ".rotation", {"axis", "angle"}, n);
    r.require("axis", "[x, y, z] (any non-zero length)");
    r.require("angle", "a number (rad)");
    const Vec3 axis = *r.vec3("axis");
    if (!(axis.norm() > 0.0))
      r.fail("axis", fmt::format("got {}, expected a non-zero vector", format_vector(axis)));
    return so3::rotation_from_axis_angle(axis.normalized(), *r.number("angle"));
  }
  const Mat3 M = *b.mat3("rotation");
  if (!so3::is_rotation(M, so3::kRotationInputTolerance)) {
    b.fail("rotation", fmt::format("got {}, expected {{ axis = [x, y, z], angle = a }} or a rotation matrix "
                                   "(RᵀR = I to {}, det R = +1)",
                                   format_matrix(M), format_number(so3::kRotationInputTolerance)));
  }
  return so3::project_to_so3(M);
}

namespace {

using detail::read_rotation;

/// The joint types that take an axis (axis_a, or with `second` axis_b), for messages: "hinge, universal or
/// prismatic joints".
std::string axis_joint_names(bool second = false) {
  std::vector<std::string_view> names;
  for (const multibody::JointTypeInfo& info : multibody::joint_types()) {
    if (info.axes == multibody::JointAxes::none) continue;
    if (second && info.axes == multibody::JointAxes::sliding) continue;
    names.push_back(info.name);
  }
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (k > 0) out += k + 1 == names.size() ? " or " : ", ";
    out += names[k];
  }
  return out + " joints";
}

/// The array of tables `key` of the top level, or null.
const toml::array* entries(const Section& top, const toml::table& /*root*/, std::string_view key) {
  return detail::table_array(top, key);
}

/// What the reader keeps of each body besides the model: the centre of mass in the body's frame.
struct Reader {
  const Source& src;
  multibody::Scenario& sc;
  std::vector<Vec3> com;  ///< per body, m, body frame

  const multibody::BodyState& side(int index) const {
    return multibody::side_state(sc.initial.bodies, index);
  }
  /// A point of a body, given in its frame, relative to its centre of mass; a point of the world as is.
  Vec3 to_model(int body, const Vec3& p) const {
    return body == kWorld ? p : Vec3(p - com[static_cast<std::size_t>(body)]);
  }
  /// The point `key` of `body` for the model; omitted, the body's centre of mass (the origin of space for
  /// the world).
  Vec3 point(const Section& f, std::string_view key, int body) const {
    const auto p = f.vec3(key);
    return p ? to_model(body, *p) : Vec3::Zero();
  }
  int body_ref(const Section& f, std::string_view key, bool world_allowed,
               const std::string& fallback) const {
    if (!f.has(key) && fallback.empty()) f.require(key, "the name of a body");
    const std::string name = f.string(key).value_or(fallback);
    int index = kWorld;
    try {
      index = sc.system.body_index(name);
    } catch (const InvalidInput&) {
      f.fail(key, fmt::format("got \"{}\", expected {}the name of a body", name,
                              world_allowed ? "\"world\" or " : ""));
    }
    if (index == kWorld && !world_allowed)
      f.fail(key, "got \"world\", expected a body (the world can only be body_b)");
    return index;
  }
};

void read_bodies(Reader& r, const Section& top, const toml::table& root, std::string_view base_dir) {
  const toml::array* bodies = entries(top, root, "bodies");
  if (bodies == nullptr || bodies->empty())
    top.require("bodies", "a [[bodies]] array with at least one body");
  for (std::size_t i = 0; i < bodies->size(); ++i) {
    const Section f(r.src, (*bodies)[i].as_table(), fmt::format("bodies[{}]", i),
                    {"name", "mass", "principal_moments", "inertia", "poinsot", "shape", "mesh", "composite",
                     "position", "rotation", "quaternion", "velocity", "omega_body"},
                    &(*bodies)[i]);
    const std::string name = f.string("name").value_or(fmt::format("body{}", i));
    const detail::BodyInertia b = detail::read_body_inertia(r.src, f, base_dir, 'x');
    const bool explicit_tensor = b.how == "principal_moments" || b.how == "inertia" || b.how == "poinsot";
    if (!b.mass) f.require("mass", fmt::format("the body's mass (kg) with {}", b.how));
    if (!(*b.mass > 0.0)) {
      f.fail(explicit_tensor ? "mass" : b.how,
             fmt::format("got {} kg, expected a number > 0", format_number(*b.mass)));
    }
    located(f, b.how, [&] { return r.sc.system.add_body(name, *b.mass, b.poinsot_com); });
    multibody::BodyState s;
    s.R_space_body = read_rotation(r.src, f);
    s.x_space = f.vec3("position").value_or(Vec3::Zero()) + s.R_space_body * b.com;
    s.v_space = f.vec3("velocity").value_or(Vec3::Zero());
    s.omega_body = f.vec3("omega_body").value_or(Vec3::Zero());
    r.sc.initial.bodies.push_back(s);
    r.com.push_back(b.com);
    std::string description = b.description;
    if (b.com != Vec3::Zero())
      description += "; positions and points in this frame, the trajectory follows the centre of mass";
    r.sc.body_descriptions.push_back(description);
    r.sc.body_surfaces.push_back(b.surface);
  }
}

void read_joints(Reader& r, const Section& top, const toml::table& root) {
  const toml::array* joints = entries(top, root, "joints");
  if (joints == nullptr) return;
  for (std::size_t j = 0; j < joints->size(); ++j) {
    const Section f(r.src, (*joints)[j].as_table(), fmt::format("joints[{}]", j),
                    {"name", "type", "body_a", "point_a", "body_b", "point_b", "axis_a", "axis_b",
                     "axis_offset", "stiffness", "damping", "rest_position"},
                    &(*joints)[j]);
    const std::string name = f.string("name").value_or(fmt::format("joint{}", j));
    f.require("type", multibody::joint_type_names());
    const std::string type = *f.string("type");
    const multibody::JointTypeInfo* info = multibody::find_joint_type(type);
    if (info == nullptr)
      f.fail("type", fmt::format("got \"{}\", expected {}", type, multibody::joint_type_names()));
    using multibody::JointAxes;
    const JointAxes axes = info->axes;
    if (axes == JointAxes::none && f.has("axis_a"))
      f.fail("axis_a", fmt::format("given for a {} joint; only {} take an axis", type, axis_joint_names()));
    if ((axes == JointAxes::none || axes == JointAxes::sliding) && f.has("axis_b"))
      f.fail("axis_b",
             fmt::format("given for a {} joint; only {} take axis_b", type, axis_joint_names(true)));
    if (axes != JointAxes::crossed && f.has("axis_offset"))
      f.fail("axis_offset",
             fmt::format("given for a {} joint; only universal joints take an axis offset", type));
    const double axis_offset = f.number("axis_offset").value_or(0.0);
    const int a = r.body_ref(f, "body_a", false, "");
    const int b = r.body_ref(f, "body_b", true, "world");
    const multibody::BodyState& sa = r.side(a);
    const multibody::BodyState& sb = r.side(b);
    const Vec3 pa = r.point(f, "point_a", a);
    // Default far point: where the near point is at t = 0 (less the axis offset along the common normal of
    // the cross pins), in b's frame (from its centre of mass).
    Vec3 pb_space = sa.x_space + sa.R_space_body * pa - sb.x_space;
    if (axis_offset != 0.0) {
      const Vec3 n = (sa.R_space_body * f.vec3("axis_a").value_or(Vec3::Zero()).normalized())
                         .cross(sb.R_space_body * f.vec3("axis_b").value_or(Vec3::Zero()).normalized());
      pb_space -= axis_offset * n;
    }
    const Vec3 pb =
        f.has("point_b") ? r.to_model(b, *f.vec3("point_b")) : Vec3(sb.R_space_body.transpose() * pb_space);
    // The relative rotation at t = 0, frozen by welds and prismatic joints.
    const Mat3 R_b_a = sb.R_space_body.transpose() * sa.R_space_body;
    if (axes != JointAxes::none)
      f.require("axis_a", fmt::format("[x, y, z]: the {} axis in body a's frame", type));
    if (axes == JointAxes::crossed)
      f.require("axis_b",
                "[x, y, z]: the cross-pin axis in body b's frame, perpendicular to axis_a at t = 0");
    const Vec3 axis_a = f.vec3("axis_a").value_or(Vec3::Zero());
    const bool has_coordinate =
        info->type == multibody::JointType::hinge || info->type == multibody::JointType::prismatic;
    for (const char* key : {"stiffness", "damping", "rest_position"}) {
      if (!has_coordinate && f.has(key))
        f.fail(key, fmt::format("given for a {} joint; only hinge and prismatic joints take a spring", type));
    }
    const int joint = located(f, "type", [&] {
      switch (info->type) {
        case multibody::JointType::ball:
          return r.sc.system.add_ball(name, a, pa, b, pb);
        case multibody::JointType::weld:
          return r.sc.system.add_weld(name, a, pa, b, pb, R_b_a);
        case multibody::JointType::hinge:
          return r.sc.system.add_hinge(
              name, a, pa, axis_a, b, pb,
              f.vec3("axis_b").value_or(Vec3(sb.R_space_body.transpose() * (sa.R_space_body * axis_a))));
        case multibody::JointType::universal:
          return r.sc.system.add_universal(name, a, pa, axis_a, b, pb, *f.vec3("axis_b"), axis_offset);
        case multibody::JointType::prismatic:
          return r.sc.system.add_prismatic(name, a, pa, axis_a, b, pb, R_b_a);
      }
      return -1;
    });
    // A spring-damper on the joint's coordinate: a hinge's angle from its relative rotation at t = 0, a
    // prismatic joint's displacement of point_a from point_b along the axis.
    if (f.has("stiffness") || f.has("damping")) {
      multibody::JointSpring s;
      s.joint = joint;
      s.stiffness = f.number("stiffness").value_or(0.0);
      s.damping = f.number("damping").value_or(0.0);
      s.rest_position = f.number("rest_position").value_or(0.0);
      s.R_b_a_zero = R_b_a;
      located(f, f.has("stiffness") ? "stiffness" : "damping",
              [&] { return r.sc.system.add_joint_spring(s); });
    } else if (f.has("rest_position")) {
      f.fail("rest_position", "given without stiffness; expected stiffness (and damping) with it");
    }
  }
}

void read_loads(Reader& r, const Section& top, const toml::table& root) {
  if (const toml::array* springs = entries(top, root, "springs")) {
    for (std::size_t k = 0; k < springs->size(); ++k) {
      const Section f(
          r.src, (*springs)[k].as_table(), fmt::format("springs[{}]", k),
          {"name", "body_a", "point_a", "body_b", "point_b", "stiffness", "damping", "rest_length"},
          &(*springs)[k]);
      multibody::Spring s;
      s.name = f.string("name").value_or(fmt::format("spring{}", k));
      s.body_a = r.body_ref(f, "body_a", false, "");
      s.body_b = r.body_ref(f, "body_b", true, "world");
      s.point_a = r.point(f, "point_a", s.body_a);
      s.point_b = r.point(f, "point_b", s.body_b);
      s.stiffness = f.number("stiffness").value_or(0.0);
      s.damping = f.number("damping").value_or(0.0);
      s.rest_length = f.number("rest_length").value_or(0.0);
      located(f, "stiffness", [&] { return r.sc.system.add_spring(s); });
    }
  }
  if (const toml::array* forces = entries(top, root, "forces")) {
    for (std::size_t k = 0; k < forces->size(); ++k) {
      const Section f(r.src, (*forces)[k].as_table(), fmt::format("forces[{}]", k),
                      {"body", "force", "point"}, &(*forces)[k]);
      const int body = r.body_ref(f, "body", false, "");
      f.require("force", "[x, y, z] (N, space frame)");
      const multibody::ConstantForce force{body, *f.vec3("force"), r.point(f, "point", body)};
      located(f, "force", [&] {
        r.sc.system.add_force(force);
        return 0;
      });
    }
  }
  if (const toml::array* torques = entries(top, root, "torques")) {
    for (std::size_t k = 0; k < torques->size(); ++k) {
      const Section f(r.src, (*torques)[k].as_table(), fmt::format("torques[{}]", k),
                      {"body", "torque", "frame"}, &(*torques)[k]);
      const int body = r.body_ref(f, "body", false, "");
      f.require("torque", "[x, y, z] (N·m)");
      const std::string frame = f.string("frame").value_or("space");
      if (frame != "space" && frame != "body")
        f.fail("frame", fmt::format("got \"{}\", expected \"space\" or \"body\"", frame));
      const multibody::ConstantTorque torque{body, *f.vec3("torque"), frame == "body"};
      located(f, "torque", [&] {
        r.sc.system.add_torque(torque);
        return 0;
      });
    }
  }
}

}  // namespace

namespace detail {

std::optional<Vec3> read_multibody_simulation(const Source& src, const Section& top,
                                              multibody::Scenario& sc) {
  const Section sim(src, top.table("simulation"), "simulation",
                    {"dt", "duration", "output_every", "gravity", "method", "order"});
  const auto positive = [&](std::string_view key, double fallback) {
    const double x = sim.number(key).value_or(fallback);
    if (!(x > 0.0)) sim.fail(key, fmt::format("got {} s, expected a number > 0", format_number(x)));
    return x;
  };
  sc.dt = positive("dt", sc.dt);
  sc.duration = sim.number("duration").value_or(sc.duration);
  if (!(sc.duration >= 0.0))
    sim.fail("duration", fmt::format("got {} s, expected a number >= 0", format_number(sc.duration)));
  const double every = sim.number("output_every").value_or(sc.output_every);
  if (!(every >= 1.0 && every <= 1e9) || every != std::floor(every))
    sim.fail("output_every", fmt::format("got {}, expected an integer >= 1 (steps)", format_number(every)));
  sc.output_every = static_cast<int>(every);
  const std::string where = detail::location(src, sim.node("duration")) + "[simulation] duration";
  check_step_count(sc.duration / sc.dt, where, "duration / dt");
  check_sample_count(sc.duration / sc.dt / sc.output_every, where, "duration / dt / output_every");
  if (const auto method = sim.string("method")) {
    try {
      sc.method = multibody::parse_multibody_method(*method, sim.label("method"));
    } catch (const InvalidInput& e) {
      throw InvalidInput(detail::location(src, sim.node("method")) + e.what());
    }
  }
  const multibody::MultibodyMethodInfo& info = multibody::multibody_method_info(sc.method);
  sc.order = info.order;
  if (info.max_order == info.order && sim.number("order")) {
    sim.fail("order", fmt::format("applies to method = \"{}\" only (the {} is of order {})",
                                  multibody::multibody_method_name(multibody::MultibodyMethod::rattle),
                                  info.label, info.order));
  }
  const double order = sim.number("order").value_or(sc.order);
  if (order != 2.0 && order != 4.0) {
    sim.fail("order", fmt::format("got {}, expected 2 (RATTLE) or 4 (its triple-jump composition)",
                                  format_number(order)));
  }
  sc.order = static_cast<int>(order);
  return sim.vec3("gravity");
}

multibody::Scenario multibody_scenario_from_table(const toml::table& root, std::string_view source,
                                                  std::string_view base_dir) {
  const Source src{std::string(source)};
  const Section top(src, &root, "top level",
                    {"title", "simulation", "bodies", "joints", "springs", "forces", "torques"});
  multibody::Scenario sc;
  sc.source = std::string(source);
  sc.title = top.string("title").value_or("");
  sc.system.set_gravity(read_multibody_simulation(src, top, sc).value_or(Vec3::Zero()));

  Reader r{src, sc, {}};
  read_bodies(r, top, root, base_dir);
  read_joints(r, top, root);
  read_loads(r, top, root);
  multibody::project_velocities(sc.system, sc.initial);
  return sc;
}

}  // namespace detail

multibody::Scenario parse_multibody_scenario(std::string_view text, std::string_view source,
                                             std::string_view base_dir) {
  return detail::multibody_scenario_from_table(detail::parse_toml(text, source), source, base_dir);
}

multibody::Scenario load_multibody_scenario(const std::string& path) {
  return parse_multibody_scenario(detail::read_scenario_file(path), path,
                                  std::filesystem::path(path).parent_path().string());
}

}  // namespace poinsot::io
