#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "poinsot/core/error.hpp"
#include "poinsot/io/scenario/ensemble_scenario.hpp"
#include "poinsot/io/scenario/reference_trajectory.hpp"
#include "poinsot/io/scenario/torque_table.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "scenario_orientation.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

using detail::Section;
using detail::Source;

ensemble::ScalarDispersion read_scalar(const Source& src, const Section& e, std::string_view key) {
  ensemble::ScalarDispersion d;
  const toml::table* t = e.table(key);
  if (!t) return d;
  const Section s(src, t, "ensemble." + std::string(key), {"law", "width", "relative", "truncation"},
                  e.node(key));
  try {
    d.law = ensemble::law_from_string(s.string("law").value_or("normal"), s.label("law"));
    d.width = s.number("width").value_or(0.0);
    d.relative = s.boolean("relative").value_or(false);
    d.truncation = s.number("truncation").value_or(3.0);
    ensemble::validate(d, s.label("width"));
  } catch (const InvalidInput& err) {
    throw InvalidInput(detail::location(src, e.node(key)) + err.what());
  }
  return d;
}

ensemble::RotationDispersion read_rotation(const Source& src, const Section& e, std::string_view key) {
  ensemble::RotationDispersion d;
  const toml::table* t = e.table(key);
  if (!t) return d;
  const Section s(src, t, "ensemble." + std::string(key), {"law", "angle", "degrees"}, e.node(key));
  try {
    d.law = ensemble::rotation_law_from_string(s.string("law").value_or("cone"), s.label("law"));
    const double scale = s.boolean("degrees").value_or(false) ? std::numbers::pi / 180.0 : 1.0;
    d.angle = s.number("angle").value_or(0.0) * scale;
    ensemble::validate(d, s.label("angle"));
  } catch (const InvalidInput& err) {
    throw InvalidInput(detail::location(src, e.node(key)) + err.what());
  }
  return d;
}

ensemble::HistogramSpec read_histograms(const Source& src, const Section& e) {
  ensemble::HistogramSpec h;
  const toml::table* t = e.table("histogram");
  if (!t) return h;
  using ensemble::kOutputNames;
  static_assert(ensemble::kOutputCount == 15, "[ensemble.histogram] lists every output");
  const Section s(
      src, t, "ensemble.histogram",
      {"bins", kOutputNames[0], kOutputNames[1], kOutputNames[2], kOutputNames[3], kOutputNames[4],
       kOutputNames[5], kOutputNames[6], kOutputNames[7], kOutputNames[8], kOutputNames[9], kOutputNames[10],
       kOutputNames[11], kOutputNames[12], kOutputNames[13], kOutputNames[14]},
      e.node("histogram"));
  h.bins = s.integer("bins", 1, ensemble::kMaxHistogramBins).value_or(ensemble::kHistogramBins);
  for (std::size_t q = 0; q < static_cast<std::size_t>(ensemble::kOutputCount); ++q) {
    const auto r = s.numbers(kOutputNames[q], 2);
    if (!r) continue;
    const ensemble::HistogramRange range{(*r)[0], (*r)[1]};
    detail::located(s, kOutputNames[q], [&] { return ensemble::FixedHistogram(range, h.bins); });
    h.ranges[q] = range;
  }
  return h;
}

std::uint64_t read_count(const Section& e, std::string_view key, std::uint64_t fallback,
                         std::uint64_t least) {
  const auto x = e.number(key);
  if (!x) return fallback;
  if (!(*x >= static_cast<double>(least) && *x == std::floor(*x) && *x < 9.2e18)) {
    e.fail(key, fmt::format("got {}, expected an integer >= {}", *x, least));
  }
  return static_cast<std::uint64_t>(*x);
}

/// The target (attitude_final as w, x, y, z; omega_final, rad/s) of a summary.json of `poinsot optimize`.
std::pair<Quat, Vec3> optimal_target(const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(detail::read_text_file(path));
  } catch (const nlohmann::json::exception& e) {
    throw InvalidInput(
        fmt::format("\"{}\": {}; expected the summary.json of poinsot optimize", path, e.what()));
  }
  const auto numbers = [&](const char* key, std::size_t n) {
    const nlohmann::json* v = j.contains("problem") && j["problem"].is_object() && j["problem"].contains(key)
                                  ? &j["problem"][key]
                                  : nullptr;
    std::vector<double> x;
    if (v && v->is_array() && v->size() == n)
      for (const auto& e : *v)
        if (e.is_number()) x.push_back(e.get<double>());
    if (x.size() != n || !std::all_of(x.begin(), x.end(), [](double y) { return std::isfinite(y); }))
      throw InvalidInput(
          fmt::format("\"{}\": problem.{} missing or not {} numbers; expected the summary.json "
                      "of poinsot optimize with a fixed final attitude",
                      path, key, n));
    return x;
  };
  const std::vector<double> q = numbers("attitude_final", 4), w = numbers("omega_final", 3);
  const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (j["problem"].value("free_final_attitude", false) || !(n > 0.5))
    throw InvalidInput(
        fmt::format("\"{}\": the plan's final attitude is free; expected a fixed target (give "
                    "orientation instead)",
                    path));
  return {Quat(q[0] / n, q[1] / n, q[2] / n, q[3] / n), Vec3(w[0], w[1], w[2])};
}

double non_negative(const Section& s, std::string_view key, double scale, std::string_view unit) {
  const double x = *s.number(key);
  if (!(x >= 0.0)) s.fail(key, fmt::format("got {}, expected a number >= 0 {}", x, unit));
  return x * scale;
}

/// [ensemble.slew]: the planned control, its target, the feedback law and the pointing requirement
/// (slew_tracking.hpp); t_end and dt are the scenario's [output] t_end and [integrator] dt.
std::shared_ptr<const ensemble::SlewTracking> read_slew(const Source& src, const Section& e,
                                                        const toml::table& root, const Scenario& base,
                                                        std::string_view base_dir,
                                                        const ensemble::Nominal& nominal) {
  const toml::table* t = e.table("slew");
  if (!t) return nullptr;
  const Section s(src, t, "ensemble.slew",
                  {"control", "interpolation", "kp", "kd", "torque_bound", "torque_max",
                   "pointing_requirement", "degrees", "target", "reference"},
                  e.node("slew"));
  ensemble::SlewSpec spec;
  s.require("control",
            "the path of the planned control, a t,ux,uy,uz table such as poinsot optimize's "
            "control.csv (relative to the scenario file)");
  const std::string name = s.string("interpolation").value_or("linear");
  dynamics::TableInterpolation interpolation = dynamics::TableInterpolation::linear;
  if (name == dynamics::table_interpolation_name(dynamics::TableInterpolation::cubic))
    interpolation = dynamics::TableInterpolation::cubic;
  else if (name != dynamics::table_interpolation_name(dynamics::TableInterpolation::linear))
    s.fail("interpolation", fmt::format("got \"{}\", expected \"linear\" or \"cubic\"", name));
  std::filesystem::path file(*s.string("control"));
  if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
  spec.control =
      detail::located(s, "control", [&] { return read_torque_table(file.string(), interpolation); });
  if (s.has("reference")) {
    std::filesystem::path reference(*s.string("reference"));
    if (reference.is_relative() && !base_dir.empty()) reference = std::filesystem::path(base_dir) / reference;
    spec.reference =
        detail::located(s, "reference", [&] { return read_reference_trajectory(reference.string()); });
  }
  s.require("kp", "the proportional gain K_p in N·m/rad (0: none)");
  s.require("kd", "the derivative gain K_d in N·m·s/rad (0: none)");
  spec.kp = non_negative(s, "kp", 1.0, "N·m/rad");
  spec.kd = non_negative(s, "kd", 1.0, "N·m·s/rad");
  const std::string bound = s.string("torque_bound").value_or(s.has("torque_max") ? "per_axis" : "none");
  if (bound == "per_axis") {
    spec.limit = ensemble::SlewTorqueLimit::per_axis;
  } else if (bound == "norm") {
    spec.limit = ensemble::SlewTorqueLimit::norm;
  } else if (bound != "none") {
    s.fail("torque_bound", fmt::format("got \"{}\", expected \"per_axis\", \"norm\" or \"none\"", bound));
  }
  if (spec.limit == ensemble::SlewTorqueLimit::none) {
    if (s.has("torque_max"))
      s.fail("torque_max", "given with torque_bound = \"none\"; expected no torque_max");
  } else {
    s.require("torque_max",
              "the torque limit in N·m: a number, or [x, y, z] with torque_bound = \"per_axis\"");
    const toml::node* m = s.node("torque_max");
    if (m->is_array()) {
      if (spec.limit == ensemble::SlewTorqueLimit::norm)
        s.fail("torque_max", "got an array with torque_bound = \"norm\"; expected one number (N·m)");
      spec.torque_max = *s.vec3("torque_max");
    } else {
      spec.torque_max = Vec3::Constant(*s.number("torque_max"));
    }
    for (int i = 0; i < 3; ++i)
      if (!(spec.torque_max[i] > 0.0))
        s.fail("torque_max", fmt::format("got {}, expected a bound > 0 N·m", spec.torque_max[i]));
  }
  s.require("pointing_requirement",
            "the largest final pointing error that meets the requirement (rad, or "
            "degrees with degrees = true)");
  const double unit = s.boolean("degrees").value_or(false) ? std::numbers::pi / 180.0 : 1.0;
  spec.pointing_requirement = non_negative(s, "pointing_requirement", unit, unit == 1.0 ? "rad" : "degrees");
  const toml::table* target = s.table("target");
  if (!target)
    s.fail("target",
           "missing; expected [ensemble.slew.target] with the target orientation and omega_body, or the "
           "summary.json of the plan");
  const Section g(src, target, "ensemble.slew.target", {"orientation", "omega_body", "summary"},
                  s.node("target"));
  if (g.exactly_one({"orientation", "summary"}, "the target") == "orientation") {
    spec.target_attitude = detail::read_orientation(src, g);
    spec.target_omega = g.vec3("omega_body").value_or(Vec3::Zero());
  } else {
    if (g.has("omega_body"))
      g.fail("omega_body", "given with summary; expected the summary's omega_final alone");
    std::filesystem::path summary(*g.string("summary"));
    if (summary.is_relative() && !base_dir.empty()) summary = std::filesystem::path(base_dir) / summary;
    const auto [q, w] = detail::located(g, "summary", [&] { return optimal_target(summary.string()); });
    spec.target_attitude = so3::rotation_from_quaternion(q);
    spec.target_omega = w;
  }

  const Section in(src, root["integrator"].as_table(), "integrator",
                   {"method", "dt", "max_step", "rtol", "atol"});
  if (base.method != "rk4") {
    in.fail("method",
            fmt::format("got \"{}\" with [ensemble.slew]; expected \"rk4\" (the closed-loop slew is "
                        "integrated by fixed-step RK4 with steps of at most dt)",
                        base.method));
  }
  if (base.torque_type != "none") {
    const Section tq(src, root["torque"].as_table(), "torque",
                     {"type", "g", "value", "file", "interpolation"});
    tq.fail("type", fmt::format("got \"{}\" with [ensemble.slew]; expected none (the slew's control is the "
                                "only torque)",
                                base.torque_type));
  }
  if (base.body.has_pivot()) s.fail("control", "given for a body with a pivot; expected a free body");
  spec.t_end = base.simulation.t_end;
  spec.dt = base.integrator.dt;
  const ensemble::Sampler undispersed(nominal, ensemble::Dispersions{}, 0);
  const ensemble::Sample n = undispersed.nominal();
  return detail::located(src, e.node("slew"), [&] {
    return std::make_shared<const ensemble::SlewTracking>(spec, n.inertia_com(), n.initial);
  });
}

}  // namespace

EnsembleScenario parse_ensemble_scenario(std::string_view text, std::string_view source,
                                         std::string_view base_dir) {
  const Source src{std::string(source)};
  toml::table root = detail::parse_toml(text, source);
  const toml::table* ens = root["ensemble"].as_table();
  if (!ens) {
    // Which sub-command reads the file, when it is another kind of scenario.
    const std::string reader = root.get("optimal_control") != nullptr
                                   ? fmt::format(
                                         "; the file is an optimal-control problem, which `poinsot "
                                         "optimize {}` solves",
                                         source)
                               : root.get("bodies") != nullptr || root.get("model") != nullptr
                                   ? fmt::format(
                                         "; the file is a multibody scenario, which `poinsot run {}` "
                                         "simulates (an ensemble disperses one body)",
                                         source)
                                   : fmt::format("; `poinsot run {}` simulates the file as it is", source);
    throw InvalidInput(
        fmt::format("{}: [ensemble]: missing; expected a section with samples, seed and the "
                    "dispersions (docs/ensemble.md){}",
                    source, reader));
  }
  const toml::table ensemble_table = *ens;
  toml::table body_table = root;
  body_table.erase("ensemble");
  EnsembleScenario sc{.base = detail::single_scenario_from_table(body_table, source, base_dir),
                      .nominal = {},
                      .dispersions = {},
                      .samples = 1000,
                      .seed = 0,
                      .per_sample = true,
                      .histograms = {},
                      .slew = {}};

  const Section e(src, &ensemble_table, "ensemble",
                  {"samples", "seed", "policy", "max_tries", "per_sample", "moments", "axes", "mass",
                   "center_of_mass", "omega", "attitude", "torque", "histogram", "slew"},
                  root.get("ensemble"));
  sc.samples = read_count(e, "samples", 1000, 1);
  sc.seed = read_count(e, "seed", 0, 0);
  sc.per_sample = e.boolean("per_sample").value_or(true);
  ensemble::Dispersions& d = sc.dispersions;
  try {
    d.policy = ensemble::policy_from_string(e.string("policy").value_or("reject"), e.label("policy"));
  } catch (const InvalidInput& err) {
    throw InvalidInput(detail::location(src, e.node("policy")) + err.what());
  }
  d.max_tries = static_cast<int>(read_count(e, "max_tries", 100, 1));
  d.moments = read_scalar(src, e, "moments");
  d.axes = read_rotation(src, e, "axes");
  d.mass = read_scalar(src, e, "mass");
  d.center_of_mass = read_scalar(src, e, "center_of_mass");
  d.omega = read_scalar(src, e, "omega");
  d.attitude = read_rotation(src, e, "attitude");
  d.torque = read_scalar(src, e, "torque");
  sc.histograms = read_histograms(src, e);

  ensemble::TorqueKind kind = ensemble::TorqueKind::none;
  Vec3 value = Vec3::Zero();
  const Section t(src, root["torque"].as_table(), "torque", {"type", "g", "value"});
  if (sc.base.torque_type == "gravity") {
    kind = ensemble::TorqueKind::gravity;
    value = sc.base.gravity_space;
  } else if (sc.base.torque_type == "body" || sc.base.torque_type == "space") {
    kind = sc.base.torque_type == "body" ? ensemble::TorqueKind::body : ensemble::TorqueKind::space;
    value = *t.vec3("value");
  }
  sc.nominal = ensemble::Nominal::from(sc.base.body, sc.base.initial, kind, value);
  try {
    const ensemble::Sampler check(sc.nominal, d, sc.seed);
  } catch (const InvalidInput& err) {
    throw InvalidInput(fmt::format("{}: {}", source, err.what()));
  }
  sc.slew = read_slew(src, e, root, sc.base, base_dir, sc.nominal);
  return sc;
}

EnsembleScenario load_ensemble_scenario(const std::string& path) {
  const std::filesystem::path p(path);
  EnsembleScenario sc =
      parse_ensemble_scenario(detail::read_scenario_file(path), path, p.parent_path().string());
  sc.base.name = p.stem().string();
  return sc;
}

ensemble::EnsembleOptions ensemble_options(const EnsembleScenario& sc) {
  ensemble::EnsembleOptions o;
  o.samples = sc.samples;
  o.method = sc.base.method;
  o.t_end = sc.base.simulation.t_end;
  o.dt = sc.base.integrator.dt;
  o.max_step = sc.base.integrator.max_step;
  o.rtol = sc.base.integrator.rtol;
  o.atol = sc.base.integrator.atol;
  o.keep_rows = sc.per_sample;
  o.histograms = sc.histograms;
  o.slew = sc.slew;
  return o;
}

Scenario sample_scenario(const EnsembleScenario& sc, const ensemble::Sample& s) {
  Scenario x = sc.base;
  x.name = fmt::format("{}_sample_{}", sc.base.name, s.index);
  x.body = s.body();
  x.body_description = fmt::format("ensemble sample {} of {}", s.index, sc.base.name);
  x.initial = s.initial;
  x.torque = s.torque_model(x.body);
  if (s.torque == ensemble::TorqueKind::gravity) x.gravity_space = s.torque_value;
  return x;
}

}  // namespace poinsot::io
