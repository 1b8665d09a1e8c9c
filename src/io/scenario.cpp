// Scenario files: TOML → validated Scenario (see scenario.hpp and docs/scenario.md).
#include "poinsot/io/scenario.hpp"
#include "poinsot/io/work_limits.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "scenario_body.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

using detail::Section;
using detail::Source;

struct BodyPart {
  dynamics::RigidBody body;
  std::string description;
};

BodyPart read_body(const Source& src, const toml::table& root, std::string_view base_dir) {
  const Section s(src, root["body"].as_table(), "body",
                  {"principal_moments", "inertia", "poinsot", "shape", "mesh", "composite", "mass",
                   "pivot_to_com", "pivot"});
  const detail::BodyInertia b = detail::read_body_inertia(src, s, base_dir, 'z');
  const std::string& how = b.how;
  std::optional<dynamics::RigidBody> body = located(s, how, [&] {
    return how == "principal_moments" ? dynamics::RigidBody::from_principal_moments(b.inertia_com.diagonal())
                                      : dynamics::RigidBody::from_inertia(b.inertia_com);
  });
  std::string description = b.description;
  // An explicit tensor takes [body] mass only for a top; a shape, mesh or composite always has a mass.
  const bool explicit_tensor = how == "principal_moments" || how == "inertia" || how == "poinsot";
  if (s.has("pivot") && s.has("pivot_to_com")) {
    s.fail("pivot",
           "given with [body] pivot_to_com; expected one of them (pivot: the point, pivot_to_com: the "
           "vector from it to the centre of mass)");
  }
  std::optional<Vec3> d = s.vec3("pivot_to_com");
  if (const auto p = s.vec3("pivot")) d = Vec3(b.com - *p);
  const std::string_view pivot_key = s.has("pivot") ? "pivot" : "pivot_to_com";
  if (explicit_tensor && b.mass && !d)
    s.fail("mass", "given without a pivot; a top needs [body] mass and pivot_to_com (or neither)");
  if (d && !b.mass) {
    s.fail(pivot_key, "given without [body] mass; a top needs [body] mass and pivot_to_com (or neither)");
  }
  if (d) {
    const double m = *b.mass;
    if (!(m > 0.0))
      s.fail(explicit_tensor ? "mass" : how, fmt::format("got {} kg, expected > 0", format_number(m)));
    body = located(s, pivot_key, [&] { return body->with_pivot(m, *d); });
    description += fmt::format("; held at a fixed pivot, mass {} kg, pivot to centre of mass {} m",
                               format_number(m), format_vector(*d));
  }
  return {*body, description};
}

Mat3 read_orientation(const Source& src, const Section& initial) {
  const toml::table* t = initial.table("orientation");
  if (t == nullptr) return Mat3::Identity();
  const Section o(src, t, "initial.orientation", {"quaternion", "matrix", "axis_angle", "euler", "degrees"},
                  initial.node("orientation"));
  const auto how = o.exactly_one({"quaternion", "matrix", "axis_angle", "euler"}, "orientation");
  const double unit = o.boolean("degrees").value_or(false) ? std::numbers::pi / 180.0 : 1.0;
  if (how == "quaternion") {
    const auto q = *o.numbers(how, 4);
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(n > 1e-12)) o.fail(how, "got a zero quaternion, expected [w, x, y, z] with a non-zero norm");
    return so3::rotation_from_quaternion(Quat(q[0] / n, q[1] / n, q[2] / n, q[3] / n));
  }
  if (how == "matrix") {
    const Mat3 m = *o.mat3(how);
    if (so3::orthogonality_error(m) > 1e-6 || m.determinant() < 0.0) {
      o.fail(how, fmt::format("got {} with ‖RᵀR − I‖ = {} and det = {}; expected a rotation matrix "
                              "(orthogonal to 1e-6, det = +1)",
                              format_matrix(m), format_number(so3::orthogonality_error(m), 3),
                              format_number(m.determinant(), 6)));
    }
    return so3::project_to_so3(m);
  }
  const toml::table* sub = o.table(how);
  if (how == "axis_angle") {
    const Section a(src, sub, "initial.orientation.axis_angle", {"axis", "angle"}, o.node(how));
    a.require("axis", "[x, y, z] (any non-zero length)");
    a.require("angle", "a number (rad, or degrees with degrees = true)");
    const Vec3 axis = *a.vec3("axis");
    const double angle = *a.number("angle") * unit;
    if (!(axis.norm() > 0.0)) a.fail("axis", "got (0, 0, 0), expected a non-zero vector");
    return located(a, "axis", [&] { return so3::rotation_from_axis_angle(axis.normalized(), angle); });
  }
  const Section e(src, sub, "initial.orientation.euler", {"sequence", "angles"}, o.node(how));
  e.require("sequence", "a sequence name such as \"ZXZ\" or \"ZYX\" (intrinsic)");
  e.require("angles", "[a1, a2, a3] (rad, or degrees with degrees = true)");
  const std::string seq_name = *e.string("sequence");
  const Vec3 angles = *e.vec3("angles") * unit;
  const auto seq = located(e, "sequence", [&] { return so3::EulerSequence::parse(seq_name); });
  return so3::rotation_from_euler(seq, angles);
}

dynamics::State read_initial(const Source& src, const toml::table& root) {
  const Section s(src, root["initial"].as_table(), "initial", {"omega_body", "omega_space", "orientation"});
  const auto how = s.exactly_one({"omega_body", "omega_space"}, "the angular velocity");
  dynamics::State state;
  state.t = 0.0;
  state.R = read_orientation(src, s);
  const Vec3 w = *s.vec3(how);
  state.omega_body = how == "omega_body" ? w : Vec3(state.R.transpose() * w);
  return state;
}

double positive(const Section& s, std::string_view key, std::string_view unit) {
  const double x = *s.number(key);
  if (!(x > 0.0)) {
    s.fail(key,
           fmt::format("got {}{}{}, expected a number > 0", format_number(x), unit.empty() ? "" : " ", unit));
  }
  return x;
}

}  // namespace

void check_method(const Scenario& sc, std::string_view method, std::string_view what) {
  bool known = false;
  std::string valid;
  for (const auto& m : kMethods) {
    known = known || m == method;
    valid += (valid.empty() ? "" : ", ") + std::string(m);
  }
  if (!known) throw InvalidInput(fmt::format("{}: got \"{}\", expected one of {}", what, method, valid));
  if (method == "exact" && (!sc.torque->is_zero() || sc.body.has_pivot())) {
    throw InvalidInput(
        fmt::format("{}: got \"exact\", which solves the torque-free body only, but [torque] type is "
                    "\"{}\"{}; expected one "
                    "of rk4, dopri5, dop853, dlm, rattle",
                    what, sc.torque_type, sc.body.has_pivot() ? " and the body has a pivot" : ""));
  }
}

namespace detail {

Scenario single_scenario_from_table(const toml::table& root, std::string_view source,
                                    std::string_view base_dir) {
  const Source src{std::string(source)};
  const Section top(src, &root, "top level", {"title", "body", "initial", "torque", "integrator", "output"});
  for (const char* key : {"body", "initial", "torque", "integrator", "output"})
    top.table(key);

  BodyPart body = read_body(src, root, base_dir);
  Scenario sc{.name = "scenario",
              .source = std::string(source),
              .title = top.string("title").value_or(""),
              .body = body.body,
              .body_description = body.description,
              .initial = read_initial(src, root),
              .torque_type = "none",
              .torque = nullptr,
              .gravity_space = Vec3::Zero(),
              .method = "",
              .integrator = {},
              .simulation = {},
              .out_dir = ""};

  // [torque]
  const Section t(src, root["torque"].as_table(), "torque", {"type", "g", "value"});
  sc.torque_type = t.string("type").value_or("none");
  if (sc.torque_type == "none") {
    for (const char* k : {"g", "value"})
      if (t.has(k))
        t.fail(k, "given with type = \"none\"; only gravity takes g, only body and space take value");
    sc.torque = dynamics::TorqueModel::none();
  } else if (sc.torque_type == "gravity") {
    if (t.has("value")) t.fail("value", "given with type = \"gravity\"; expected g (m/s²) instead");
    sc.gravity_space = t.vec3("g").value_or(Vec3(0.0, 0.0, -9.81));
    if (!sc.body.has_pivot()) {
      t.fail("type",
             "got \"gravity\", which needs a body held at a pivot; expected [body] mass and pivot_to_com");
    }
    sc.torque = located(t, "g", [&] { return dynamics::TorqueModel::gravity(sc.body, sc.gravity_space); });
  } else if (sc.torque_type == "body" || sc.torque_type == "space") {
    if (t.has("g"))
      t.fail("g", fmt::format("given with type = \"{}\"; expected value (N·m)", sc.torque_type));
    t.require("value", "[x, y, z] (N·m)");
    const Vec3 v = *t.vec3("value");
    sc.torque = sc.torque_type == "body" ? dynamics::TorqueModel::constant_body(v)
                                         : dynamics::TorqueModel::constant_space(v);
  } else {
    t.fail("type", fmt::format("got \"{}\", expected one of none, gravity, body, space", sc.torque_type));
  }

  // [integrator]
  const Section in(src, root["integrator"].as_table(), "integrator", {"method", "dt", "rtol", "atol"});
  sc.method = in.string("method").value_or("dop853");
  try {
    check_method(sc, sc.method, in.label("method"));
  } catch (const InvalidInput& e) {
    throw InvalidInput(detail::location(src, in.node("method")) + e.what());
  }
  if (in.has("dt")) sc.integrator.dt = positive(in, "dt", "s");
  if (in.has("rtol")) sc.integrator.rtol = positive(in, "rtol", "");
  if (in.has("atol")) sc.integrator.atol = positive(in, "atol", "");

  // [output]
  const Section o(src, root["output"].as_table(), "output", {"t_end", "sample_dt", "dir"});
  o.require("t_end", "the final time in seconds, e.g. t_end = 20.0");
  sc.simulation.t_end = positive(o, "t_end", "s");
  sc.simulation.sample_dt = o.has("sample_dt") ? positive(o, "sample_dt", "s") : sc.simulation.t_end / 1000.0;
  sc.out_dir = o.string("dir").value_or("");
  const std::string where = detail::location(src, o.node("t_end")) + "[output] t_end";
  check_step_count(sc.simulation.t_end / sc.integrator.dt, where, "t_end / dt");
  check_sample_count(sc.simulation.t_end / sc.simulation.sample_dt, where, "t_end / sample_dt");
  return sc;
}

}  // namespace detail

Scenario parse_scenario(std::string_view text, std::string_view source, std::string_view base_dir) {
  return detail::single_scenario_from_table(detail::parse_toml(text, source), source, base_dir);
}

Scenario load_scenario(const std::string& path) {
  const std::filesystem::path p(path);
  Scenario sc = parse_scenario(detail::read_text_file(path), path, p.parent_path().string());
  sc.name = p.stem().string();
  return sc;
}

void apply_overrides(Scenario& sc, const ScenarioOverrides& o) {
  const auto check = [](std::string_view option, double x) {
    if (!(std::isfinite(x) && x > 0.0)) {
      throw InvalidInput(fmt::format("{}: got {} s, expected a number > 0", option, format_number(x)));
    }
    return x;
  };
  if (!o.method.empty()) {
    check_method(sc, o.method, "--method");
    sc.method = o.method;
  }
  if (o.has_dt) sc.integrator.dt = check("--dt", o.dt);
  if (o.has_t_end) sc.simulation.t_end = check("--t-end", o.t_end);
  if (o.has_sample_dt) sc.simulation.sample_dt = check("--sample-dt", o.sample_dt);
  if (!o.out_dir.empty()) sc.out_dir = o.out_dir;
  check_step_count(sc.simulation.t_end / sc.integrator.dt, "--t-end/--dt", "t_end / dt");
  check_sample_count(sc.simulation.t_end / sc.simulation.sample_dt, "--t-end/--sample-dt",
                     "t_end / sample_dt");
}

}  // namespace poinsot::io
