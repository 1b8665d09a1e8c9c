#include "poinsot/io/scenario/optimal_scenario.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "scenario_body.hpp"
#include "scenario_orientation.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {

namespace {

using detail::Section;
using detail::Source;

struct Endpoint {
  Quat attitude;
  Vec3 omega;
  bool free_attitude = false;
};

Endpoint read_endpoint(const Source& src, const Section& oc, const char* key) {
  const Section s(src, oc.table(key), "optimal_control." + std::string(key),
                  {"orientation", "omega_body", "free_attitude"}, oc.node(key));
  const bool free = s.boolean("free_attitude").value_or(false);
  if (free && std::string_view(key) == "initial")
    s.fail("free_attitude", "only the final attitude can be free");
  if (free && s.has("orientation"))
    s.fail("orientation", "given with free_attitude = true; expected one of them");
  return {so3::quaternion_from_rotation(detail::read_orientation(src, s)),
          s.vec3("omega_body").value_or(Vec3::Zero()), free};
}

/// A non-zero vector, normalised.
Vec3 direction(const Section& s, std::string_view key, std::string_view frame) {
  s.require(key, fmt::format("[x, y, z] in the {} frame (any non-zero length)", frame));
  const Vec3 v = *s.vec3(key);
  if (!(v.norm() > 0.0)) s.fail(key, fmt::format("got {}, expected a non-zero vector", format_vector(v)));
  return v.normalized();
}

/// Every [[optimal_control.keep_out]] or [[optimal_control.keep_in]] table: name (optional), boresight_body,
/// direction_space, and half_angle (rad) or half_angle_deg.
void read_pointing(const Source& src, const Section& oc, optimal::PointingKind kind,
                   std::vector<optimal::PointingConstraint>& out) {
  const std::string key(optimal::pointing_kind_name(kind));
  const toml::array* a = detail::table_array(oc, key);
  if (a == nullptr) return;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const Section c(src, (*a)[i].as_table(), fmt::format("optimal_control.{}[{}]", key, i + 1),
                    {"name", "boresight_body", "direction_space", "half_angle", "half_angle_deg"}, &(*a)[i]);
    optimal::PointingConstraint pc;
    pc.kind = kind;
    pc.name = c.string("name").value_or("");
    pc.boresight_body = direction(c, "boresight_body", "body");
    pc.direction_space = direction(c, "direction_space", "space");
    const std::string_view how = c.exactly_one({"half_angle", "half_angle_deg"}, "the cone's half-angle");
    pc.half_angle = *c.number(how) * (how == "half_angle" ? 1.0 : std::numbers::pi / 180.0);
    if (!(pc.half_angle > 0.0 && pc.half_angle < std::numbers::pi))
      c.fail(how, fmt::format("got {}, expected 0 < {} < {}", format_number(*c.number(how)), how,
                              how == "half_angle" ? "π" : "180"));
    out.push_back(std::move(pc));
  }
}

/// [optimal_control.reaction_wheels]: axes (three rows, one wheel's spin axis each, body frame, any
/// non-zero length; default the body axes), spin_inertia (kg·m²), momentum_max (N·m·s, one number for every
/// wheel or three; optional) and momentum_initial (N·m·s, default 0). Absent: no wheels.
std::optional<optimal::ReactionWheels> read_wheels(const Source& src, const Section& oc) {
  const Section s(src, oc.table("reaction_wheels"), "optimal_control.reaction_wheels",
                  {"axes", "spin_inertia", "momentum_max", "momentum_initial"}, oc.node("reaction_wheels"));
  if (!s.present()) return std::nullopt;
  optimal::ReactionWheels w;
  if (const auto rows = s.mat3("axes")) {
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = rows->row(k).transpose();
      if (!(a.norm() > 0.0))
        s.fail("axes", fmt::format("row {} is {}; expected a non-zero spin axis for wheel {}", k + 1,
                                   format_vector(a), k + 1));
      w.axes_body.col(k) = a.normalized();
    }
  }
  s.require("spin_inertia", "[I1, I2, I3], each wheel's axial moment of inertia (kg·m²)");
  w.spin_inertia = *s.vec3("spin_inertia");
  if (s.has("momentum_max"))
    w.momentum_max = s.node("momentum_max")->is_array() ? *s.vec3("momentum_max")
                                                        : Vec3::Constant(*s.number("momentum_max"));
  w.momentum_initial = s.vec3("momentum_initial").value_or(Vec3::Zero());
  return w;
}

}  // namespace

OptimalScenario parse_optimal_scenario(std::string_view text, std::string_view source,
                                       std::string_view base_dir) {
  const toml::table root = detail::parse_toml(text, source);
  const Source src{std::string(source)};
  detail::require_optimal_control_section(src, root);
  const Section top(src, &root, "top level", {"title", "body", "optimal_control", "output"});
  OptimalScenario sc;
  sc.source = std::string(source);
  sc.title = top.string("title").value_or("");

  const Section b(src, root["body"].as_table(), "body",
                  {"principal_moments", "inertia", "poinsot", "shape", "mesh", "composite", "mass"});
  const detail::BodyInertia body = detail::read_body_inertia(src, b, base_dir, 'z');
  sc.body_description = body.description;
  sc.problem.inertia_body = body.inertia_com;
  sc.body_mass = body.mass;
  sc.body_surface = body.surface;

  const Section oc(
      src, root["optimal_control"].as_table(), "optimal_control",
      {"objective", "torque_bound", "torque_max", "rate_max", "final_time", "energy_weight", "mesh_tolerance",
       "initial_intervals", "max_mesh_iterations", "starts", "shooting_nodes", "phased",
       "phased_intervals_per_arc", "initial", "final", "keep_out", "keep_in", "reaction_wheels"},
      root.get("optimal_control"));
  auto& p = sc.problem;
  if (const auto o = oc.string("objective"))
    p.objective =
        detail::located(oc, "objective", [&] { return optimal::parse_objective(*o, oc.label("objective")); });
  const std::string bound = oc.string("torque_bound").value_or("per_axis");
  if (bound != "per_axis" && bound != "norm")
    oc.fail("torque_bound", fmt::format("got \"{}\", expected \"per_axis\" or \"norm\"", bound));
  p.bound = bound == "norm" ? optimal::TorqueBound::norm : optimal::TorqueBound::per_axis;
  oc.require("torque_max", bound == "norm" ? "a number (N·m)" : "[u1, u2, u3] (N·m)");
  if (p.bound == optimal::TorqueBound::norm) {
    p.torque_max = Vec3::Constant(*oc.number("torque_max"));
  } else {
    p.torque_max = *oc.vec3("torque_max");
  }
  if (const auto r = oc.number("rate_max")) p.rate_max = *r;
  p.final_time = oc.number("final_time").value_or(0.0);
  p.energy_weight = oc.number("energy_weight").value_or(0.0);
  if (p.objective == optimal::Objective::minimum_energy)
    oc.require("final_time", "the fixed final time in seconds (minimum_energy)");
  else if (oc.has("final_time"))
    oc.fail("final_time", "given for a free-final-time objective; only minimum_energy takes final_time");
  if (const auto m = oc.number("mesh_tolerance")) sc.collocation.mesh_tolerance = *m;
  if (const auto n = oc.integer("initial_intervals", 2, 4000)) sc.collocation.initial_intervals = *n;
  if (const auto n = oc.integer("max_mesh_iterations", 1, 100)) sc.collocation.max_mesh_iterations = *n;
  if (const auto n = oc.integer("starts", 1, optimal::kMaxStarts)) sc.collocation.starts = *n;
  if (const auto n = oc.integer("shooting_nodes", 1, 1000)) sc.shooting.shooting_nodes = *n;
  sc.phased = oc.boolean("phased").value_or(true);
  if (const auto n = oc.integer("phased_intervals_per_arc", 1, 2000))
    sc.phased_options.intervals_per_arc = *n;
  if (const auto m = oc.number("mesh_tolerance"); m && !(*m > 0.0))
    oc.fail("mesh_tolerance", fmt::format("got {}, expected a positive tolerance", format_number(*m)));
  const Endpoint a = read_endpoint(src, oc, "initial"), f = read_endpoint(src, oc, "final");
  p.attitude_initial = a.attitude;
  p.omega_initial = a.omega;
  p.attitude_final = f.attitude;
  p.omega_final = f.omega;
  p.free_final_attitude = f.free_attitude;
  read_pointing(src, oc, optimal::PointingKind::keep_out, p.pointing);
  read_pointing(src, oc, optimal::PointingKind::keep_in, p.pointing);
  p.wheels = read_wheels(src, oc);
  detail::located(src, root.get("optimal_control"), [&] { optimal::validate(p); });

  const Section out(src, root["output"].as_table(), "output", {"dir"});
  sc.out_dir = out.string("dir").value_or("");
  return sc;
}

OptimalScenario load_optimal_scenario(const std::string& path) {
  const std::filesystem::path p(path);
  OptimalScenario sc =
      parse_optimal_scenario(detail::read_scenario_file(path), path, p.parent_path().string());
  sc.name = p.stem().string();
  return sc;
}

}  // namespace poinsot::io
