// Scenario files: TOML → validated Scenario (see scenario.hpp and docs/scenario.md).
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/io/scenario/torque_table.hpp"
#include "poinsot/io/scenario/work_limits.hpp"

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
#include "poinsot/so3/rotation_check.hpp"
#include "scenario_body.hpp"
#include "scenario_orientation.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

using detail::Section;
using detail::Source;

struct BodyPart {
  dynamics::RigidBody body;
  std::string description;
  std::shared_ptr<const inertia::TriangleMesh> surface;
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
  return {*body, description, b.surface};
}

dynamics::State read_initial(const Source& src, const toml::table& root) {
  const Section s(src, root["initial"].as_table(), "initial", {"omega_body", "omega_space", "orientation"});
  const auto how = s.exactly_one({"omega_body", "omega_space"}, "the angular velocity");
  dynamics::State state;
  state.time = 0.0;
  state.R_space_body = detail::read_orientation(src, s);
  const Vec3 w = *s.vec3(how);
  state.omega_body = how == "omega_body" ? w : Vec3(state.R_space_body.transpose() * w);
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
  const dynamics::MethodInfo& info = dynamics::method_info(method, what);
  if (!info.takes_torque && (!sc.torque->is_zero() || sc.body.has_pivot())) {
    std::string with_torque;
    for (const dynamics::MethodInfo& m : dynamics::methods())
      if (m.takes_torque) with_torque += (with_torque.empty() ? "" : ", ") + std::string(m.name);
    throw InvalidInput(fmt::format(
        "{}: got \"{}\", which solves the torque-free body only, but [torque] type is \"{}\"{}; "
        "expected one of {}",
        what, method, sc.torque_type, sc.body.has_pivot() ? " and the body has a pivot" : "", with_torque));
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
              .out_dir = "",
              .body_surface = body.surface};

  // [torque]
  const Section t(src, root["torque"].as_table(), "torque", {"type", "g", "value", "file", "interpolation"});
  sc.torque_type = t.string("type").value_or("none");
  for (const char* k : {"file", "interpolation"})
    if (t.has(k) && sc.torque_type != "table")
      t.fail(k, fmt::format("given with type = \"{}\"; only type = \"table\" takes {}", sc.torque_type, k));
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
  } else if (sc.torque_type == "table") {
    for (const char* k : {"g", "value"})
      if (t.has(k))
        t.fail(k, "given with type = \"table\"; expected file (a t,ux,uy,uz table) and interpolation only");
    t.require("file", "the path of a t,ux,uy,uz table (N·m, body frame), e.g. a control.csv");
    // The spellings are the dynamics layer's (table_interpolation_name), the default linear.
    const std::string name =
        t.string("interpolation")
            .value_or(dynamics::table_interpolation_name(dynamics::TableInterpolation::linear));
    dynamics::TableInterpolation interpolation = dynamics::TableInterpolation::linear;
    if (name == dynamics::table_interpolation_name(dynamics::TableInterpolation::cubic))
      interpolation = dynamics::TableInterpolation::cubic;
    else if (name != dynamics::table_interpolation_name(dynamics::TableInterpolation::linear))
      t.fail("interpolation", fmt::format("got \"{}\"; expected \"linear\" or \"cubic\"", name));
    std::filesystem::path file(*t.string("file"));
    if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
    sc.torque = located(t, "file", [&] { return read_torque_table(file.string(), interpolation); });
  } else {
    t.fail("type",
           fmt::format("got \"{}\", expected one of none, gravity, body, space, table", sc.torque_type));
  }

  // [integrator]
  const Section in(src, root["integrator"].as_table(), "integrator",
                   {"method", "dt", "max_step", "rtol", "atol"});
  sc.method = in.string("method").value_or(std::string(dynamics::kDefaultMethod));
  try {
    check_method(sc, sc.method, in.label("method"));
  } catch (const InvalidInput& e) {
    throw InvalidInput(detail::location(src, in.node("method")) + e.what());
  }
  if (in.has("dt")) sc.integrator.dt = positive(in, "dt", "s");
  if (in.has("max_step")) sc.integrator.max_step = positive(in, "max_step", "s");
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
  // A finite max_step caps the adaptive methods' steps: at least t_end / max_step of them.
  check_step_count(sc.simulation.t_end / sc.integrator.max_step, where, "t_end / max_step");
  check_sample_count(sc.simulation.t_end / sc.simulation.sample_dt, where, "t_end / sample_dt");
  return sc;
}

}  // namespace detail

Scenario parse_scenario(std::string_view text, std::string_view source, std::string_view base_dir) {
  return detail::single_scenario_from_table(detail::parse_toml(text, source), source, base_dir);
}

Scenario load_scenario(const std::string& path) {
  const std::filesystem::path p(path);
  Scenario sc = parse_scenario(detail::read_scenario_file(path), path, p.parent_path().string());
  sc.name = p.stem().string();
  return sc;
}

}  // namespace poinsot::io
