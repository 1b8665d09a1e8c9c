// Multibody scenario files with an [optimal_control] section (see multibody_optimal_scenario.hpp).
#include "poinsot/io/scenario/multibody_optimal_scenario.hpp"

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/optimal/problem.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

using detail::Section;
using detail::Source;

/// The system's part of the file, and the robot file and its options when a `[model]` table names one.
struct ModelRead {
  multibody::Scenario scenario;
  std::optional<detail::RobotFileTable> robot;
};

/// The system's part of the file: the same table less the two sections that only `poinsot optimize` reads.
/// (The text is parsed a second time rather than the table copied: a copied toml++ node loses its position
/// in the file, which every message reports.)
ModelRead read_model(std::string_view text, std::string_view source, std::string_view base_dir) {
  toml::table root = detail::parse_toml(text, source);
  root.erase("optimal_control");
  root.erase("output");
  ModelRead out;
  if (root.get("model") != nullptr) {
    out.robot.emplace();
    out.scenario = detail::robot_scenario_from_table(root, source, base_dir, &*out.robot);
  } else {
    out.scenario = detail::multibody_scenario_from_table(root, source, base_dir);
  }
  return out;
}

std::vector<optimal::Actuator> read_actuators(const Source& src, const Section& oc,
                                              const multibody::System& system) {
  const toml::array* list = detail::table_array(oc, "actuators");
  if (list == nullptr || list->empty()) {
    oc.fail("actuators",
            "none given; expected at least one { joint = \"HINGE\", torque_max = N·m } or { body = \"BODY\", "
            "torque_max = N·m } (an unactuated system cannot be steered)");
  }
  std::vector<optimal::Actuator> out;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Section a(src, (*list)[i].as_table(), fmt::format("optimal_control.actuators[{}]", i),
                    {"joint", "body", "torque_max"}, &(*list)[i]);
    const std::string_view which = a.exactly_one({"joint", "body"}, "the actuated hinge, ball joint or body");
    a.require("torque_max", "the bound |u| ≤ torque_max (N·m), a number > 0");
    optimal::Actuator act;
    act.torque_max = *a.number("torque_max");
    const std::string name = *a.string(which);
    if (which == "joint") {
      act = detail::located(a, "joint", [&] { return optimal::joint_motor(system, name, act.torque_max); });
    } else {
      act.kind = optimal::ActuatorKind::body_torque;
      act.index = detail::located(a, "body", [&] { return system.body_index(name); });
      if (act.index == multibody::kWorld) a.fail("body", "got \"world\", expected a body");
    }
    if (!(act.torque_max > 0.0))
      a.fail("torque_max", fmt::format("got {} N·m, expected a number > 0", format_number(act.torque_max)));
    out.push_back(act);
  }
  return out;
}

/// Places every target body without a centre of mass through its joints (x_a = x_b + R_b p_b − R_a p_a, or
/// the same solved for b), sweeping until no more can be placed.
void place_by_joints(const multibody::System& system, multibody::State& state, std::vector<bool>& placed) {
  const auto known = [&](int b) { return b == multibody::kWorld || placed[static_cast<std::size_t>(b)]; };
  for (bool progress = true; progress;) {
    progress = false;
    for (const multibody::Joint& j : system.joints()) {
      if (j.sliding) continue;  // a prismatic joint leaves the distance along its line open
      const bool a = known(j.body_a), b = known(j.body_b);
      if (a == b) continue;
      const multibody::BodyState& sb = multibody::side_state(state.bodies, j.body_b);
      auto& sa = state.bodies[static_cast<std::size_t>(j.body_a)];
      if (b) {
        sa.x_space = sb.x_space + sb.R_space_body * j.point_b - sa.R_space_body * j.point_a;
        placed[static_cast<std::size_t>(j.body_a)] = true;
      } else {
        auto& mb = state.bodies[static_cast<std::size_t>(j.body_b)];
        mb.x_space = sa.x_space + sa.R_space_body * j.point_a - mb.R_space_body * j.point_b;
        placed[static_cast<std::size_t>(j.body_b)] = true;
      }
      progress = true;
    }
  }
}

std::vector<optimal::RateBound> read_rate_bounds(const Source& src, const Section& oc,
                                                 const multibody::System& system) {
  std::vector<optimal::RateBound> out;
  const toml::array* list = detail::table_array(oc, "rate_bounds");
  if (list == nullptr) return out;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Section b(src, (*list)[i].as_table(), fmt::format("optimal_control.rate_bounds[{}]", i),
                    {"joint", "rate_max"}, &(*list)[i]);
    b.require("joint", "the name of a hinge joint");
    b.require("rate_max", "the bound |q̇| ≤ rate_max (rad/s), a number > 0");
    const std::string name = *b.string("joint");
    optimal::RateBound bound;
    bound.joint = detail::located(b, "joint", [&] { return optimal::hinge_index(system, name); });
    bound.rate_max = *b.number("rate_max");
    if (!(bound.rate_max > 0.0))
      b.fail("rate_max", fmt::format("got {} rad/s, expected a number > 0", format_number(bound.rate_max)));
    out.push_back(bound);
  }
  return out;
}

std::vector<optimal::NoTwist> read_no_twist(const Source& src, const Section& oc,
                                            const multibody::System& system) {
  std::vector<optimal::NoTwist> out;
  const toml::array* list = detail::table_array(oc, "no_twist");
  if (list == nullptr) return out;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const Section c(src, (*list)[i].as_table(), fmt::format("optimal_control.no_twist[{}]", i),
                    {"joint", "axis_a", "rotation", "quaternion"}, &(*list)[i]);
    c.require("joint", "the name of a ball joint");
    c.require("axis_a", "the symmetry axis s of body a (body a's frame), a unit vector [x, y, z]");
    const std::string name = *c.string("joint");
    optimal::NoTwist condition;
    condition.joint = detail::located(c, "joint", [&] { return optimal::ball_index(system, name); });
    condition.axis_a = *c.vec3("axis_a");
    condition.straight = detail::read_rotation(src, c);
    out.push_back(condition);
  }
  return out;
}

/// The mesh sequence `warm_start = [N1, N2, ...]` as written (check_multibody_options checks its order).
std::vector<int> read_mesh_sequence(const Section& oc) {
  std::vector<int> out;
  const toml::node* n = oc.node("warm_start");
  if (n == nullptr) return out;
  const auto* a = n->as_array();
  const auto refuse = [&] {
    oc.fail("warm_start", fmt::format("got {}, expected an array of whole numbers of intervals (the meshes "
                                      "solved before the last, each from the previous one's optimum)",
                                      detail::describe(*n)));
  };
  if (a == nullptr) refuse();
  for (const auto& e : *a) {
    const auto v = e.value<std::int64_t>();
    if (!e.is_integer() || !v || *v < 2 || *v > 2000) refuse();
    out.push_back(static_cast<int>(*v));
  }
  return out;
}

multibody::State read_target(const Source& src, const Section& oc, const multibody::System& system) {
  const toml::array* list = detail::table_array(oc, "final");
  const std::size_t n = static_cast<std::size_t>(system.body_count());
  if (list == nullptr)
    oc.fail("final", "missing; expected one [[optimal_control.final]] table per body (the target state)");
  multibody::State target;
  target.bodies.resize(n);
  std::vector<bool> given(n, false), placed(n, false);
  for (std::size_t k = 0; k < list->size(); ++k) {
    const Section f(src, (*list)[k].as_table(), fmt::format("optimal_control.final[{}]", k),
                    {"body", "rotation", "quaternion", "center_of_mass", "velocity", "omega_body"},
                    &(*list)[k]);
    f.require("body", "the name of a body");
    const std::string name = *f.string("body");
    const int i = detail::located(f, "body", [&] { return system.body_index(name); });
    if (i == multibody::kWorld) f.fail("body", "got \"world\", expected a body");
    const auto u = static_cast<std::size_t>(i);
    if (given[u]) f.fail("body", fmt::format("\"{}\" is given twice; expected one target per body", name));
    given[u] = true;
    multibody::BodyState& s = target.bodies[u];
    s.R_space_body = detail::read_rotation(src, f);
    if (const auto x = f.vec3("center_of_mass")) {
      s.x_space = *x;
      placed[u] = true;
    }
    s.v_space = f.vec3("velocity").value_or(Vec3::Zero());
    s.omega_body = f.vec3("omega_body").value_or(Vec3::Zero());
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!given[i])
      oc.fail("final",
              fmt::format("no target for body \"{}\"; expected one [[optimal_control.final]] per body",
                          system.bodies()[i].name));
  }
  place_by_joints(system, target, placed);
  for (std::size_t i = 0; i < n; ++i) {
    if (!placed[i])
      oc.fail("final", fmt::format("body \"{}\": no center_of_mass and no joint that places it; expected "
                                   "center_of_mass = [x, y, z] (m)",
                                   system.bodies()[i].name));
  }
  multibody::project_velocities(system, target);
  return target;
}

/// The target of a robot model by its joints: `final_positions` and `final_velocities` by joint name, the
/// floating base's `final_base`, as the `[model]` table gives the initial state (joints not named at the
/// file's pose and at rest).
multibody::State read_joint_target(const Source& src, const Section& oc, const detail::RobotFileTable& file) {
  RobotSystemOptions options = file.options;
  options.positions = detail::read_joint_coordinates(src, oc, "final_positions");
  options.velocities = detail::read_joint_coordinates(src, oc, "final_velocities");
  options.base_position.reset();
  options.base_rotation.reset();
  options.base_velocity.reset();
  options.base_omega_body.reset();
  detail::read_robot_base(src, oc, "final_base", options);
  return detail::robot_scenario_located(oc, file.robot, options,
                                        {"final_positions", "final_velocities", "final_base"})
      .initial;
}

/// The target: one `[[final]]` per body, or, for a robot model, its joints' coordinates.
multibody::State read_final_state(const Source& src, const Section& oc, const ModelRead& model,
                                  const multibody::System& system) {
  const char* by_joint = nullptr;
  for (const char* key : {"final_positions", "final_velocities", "final_base"})
    if (by_joint == nullptr && oc.has(key)) by_joint = key;
  if (by_joint == nullptr) {
    if (model.robot && !oc.has("final"))
      oc.fail("final",
              "missing; expected final_positions = { JOINT = q, ... } (the target by the robot file's "
              "joint names), or one [[optimal_control.final]] table per body");
    return read_target(src, oc, system);
  }
  if (!model.robot)
    oc.fail(by_joint,
            "given without a [model] robot file; expected one [[optimal_control.final]] table per body "
            "(the target by joint names is for robot files)");
  if (oc.has("final"))
    oc.fail("final",
            fmt::format("given with {}; expected the target either by joints or by bodies", by_joint));
  return read_joint_target(src, oc, *model.robot);
}

}  // namespace

std::string_view coordinates_name(optimal::MultibodyCoordinates c) {
  return c == optimal::MultibodyCoordinates::minimal ? "minimal" : "rotation_matrix";
}

MultibodyOptimalScenario parse_multibody_optimal_scenario(std::string_view text, std::string_view source,
                                                          std::string_view base_dir) {
  MultibodyOptimalScenario sc;
  const ModelRead model = read_model(text, source, base_dir);
  sc.model = model.scenario;
  sc.source = std::string(source);
  sc.title = sc.model.title;
  const toml::table root = detail::parse_toml(text, source);
  const Source src{std::string(source)};
  // The other top-level keys were checked by the system's reader (read_model).
  const Section oc(src, root["optimal_control"].as_table(), "optimal_control",
                   {"objective", "final_time", "coordinates", "intervals", "nlp_tolerance",
                    "max_nlp_iterations", "replay_steps", "target_tolerance", "actuators", "rate_bounds",
                    "final", "stabilisation_step", "no_twist", "warm_start", "final_time_bounds",
                    "energy_weight", "final_positions", "final_velocities", "final_base"},
                   root.get("optimal_control"));
  detail::require_optimal_control_section(src, root);

  auto& p = sc.problem;
  p.system = sc.model.system;
  p.initial_state = sc.model.initial;
  if (model.robot && !p.system.joint_springs().empty()) {
    const auto joint = static_cast<std::size_t>(p.system.joint_springs()[0].joint);
    throw InvalidInput(fmt::format(
        "{}[model] joint_springs: the file gives joint '{}' a spring or damper, which the optimal control "
        "transcriptions do not handle; expected joint_springs = false (the plan is then made without them, "
        "and the report lists them as not modelled)",
        detail::location(src, root.get("model")), p.system.joints()[joint].name));
  }
  const optimal::Objective objective =
      oc.has("objective")
          ? detail::located(
                oc, "objective",
                [&] { return optimal::parse_objective(*oc.string("objective"), oc.label("objective")); })
          : optimal::Objective::minimum_energy;
  oc.require("final_time", "the final time in seconds (fixed for minimum_energy, else the guess of T)");
  p.final_time = *oc.number("final_time");
  if (!(p.final_time > 0.0))
    oc.fail("final_time", fmt::format("got {} s, expected a number > 0", format_number(p.final_time)));
  const bool regularised = objective == optimal::Objective::minimum_time_regularised;
  if (objective == optimal::Objective::minimum_energy) {
    for (const char* key : {"final_time_bounds", "energy_weight"})
      if (oc.has(key))
        oc.fail(key, "given with objective = \"minimum_energy\", expected only for minimum_time");
  } else {
    p.objective = optimal::MultibodyObjective::minimum_time;
    oc.require("final_time_bounds", "[T_min, T_max] in seconds, the bounds on the free final time");
    const std::vector<double> bounds = *oc.numbers("final_time_bounds", 2);
    p.final_time_min = bounds[0];
    p.final_time_max = bounds[1];
    if (regularised) {
      oc.require("energy_weight", "ε > 0 in T + ε ∫ Σ u² dt (s/(N²·m²·s))");
      p.energy_weight = *oc.number("energy_weight");
      if (!(p.energy_weight > 0.0)) {
        oc.fail("energy_weight",
                fmt::format("got {}, expected a number > 0", format_number(p.energy_weight)));
      }
    } else if (oc.has("energy_weight")) {
      oc.fail("energy_weight",
              "given with objective = \"minimum_time\", expected it only with "
              "\"minimum_time_regularised\"");
    }
  }
  const std::string coordinates = oc.string("coordinates").value_or("rotation_matrix");
  if (coordinates == "minimal") {
    sc.options.coordinates = optimal::MultibodyCoordinates::minimal;
  } else if (coordinates != "rotation_matrix") {
    oc.fail("coordinates",
            fmt::format("got \"{}\", expected \"rotation_matrix\" or \"minimal\"", coordinates));
  }
  p.intervals = oc.integer("intervals", 2, 2000).value_or(p.intervals);
  sc.options.max_nlp_iterations =
      oc.integer("max_nlp_iterations", 1, 100000).value_or(sc.options.max_nlp_iterations);
  sc.replay_steps = oc.integer("replay_steps", 1, 10000).value_or(sc.replay_steps);
  if (const auto t = oc.number("nlp_tolerance")) {
    if (!(*t > 0.0))
      oc.fail("nlp_tolerance", fmt::format("got {}, expected a number > 0", format_number(*t)));
    sc.options.nlp_tolerance = *t;
  }
  if (const auto t = oc.number("target_tolerance")) {
    if (!(*t > 0.0))
      oc.fail("target_tolerance", fmt::format("got {}, expected a number > 0", format_number(*t)));
    sc.target_tolerance = *t;
  }
  sc.options.stabilisation_step = oc.number("stabilisation_step").value_or(0.0);
  sc.mesh_sequence = read_mesh_sequence(oc);
  p.actuators = read_actuators(src, oc, p.system);
  p.final_state = read_final_state(src, oc, model, p.system);
  p.rate_bounds = read_rate_bounds(src, oc, p.system);
  p.no_twist = read_no_twist(src, oc, p.system);
  detail::located(src, root.get("optimal_control"), [&] {
    optimal::validate(p);
    check_multibody_options(sc);
  });
  const Section out(src, root["output"].as_table(), "output", {"dir"});
  sc.out_dir = out.string("dir").value_or("");
  return sc;
}

void check_multibody_options(const MultibodyOptimalScenario& sc) {
  const double c = sc.options.stabilisation_step;
  if (!(c >= 0.0 && c < 0.6)) {
    throw InvalidInput(fmt::format(
        "optimal control: stabilisation_step: got {}; expected a number from 0 to 0.6 (0: unbounded)",
        format_number(c)));
  }
  const bool minimal = sc.options.coordinates == optimal::MultibodyCoordinates::minimal;
  if (minimal && c != 0.0) {
    throw InvalidInput(
        fmt::format("optimal control: stabilisation_step: got {} with minimal coordinates; "
                    "expected 0 (it bounds the rotation-matrix transcription's variables)",
                    format_number(c)));
  }
  if (minimal && !sc.problem.no_twist.empty()) {
    throw InvalidInput(
        "optimal control: no_twist: given with minimal coordinates; expected none (a path constraint of the "
        "rotation-matrix transcription)");
  }
  for (std::size_t i = 0; i < sc.mesh_sequence.size(); ++i) {
    const int n = sc.mesh_sequence[i];
    if (n < 2 || n >= sc.problem.intervals || (i > 0 && n <= sc.mesh_sequence[i - 1])) {
      throw InvalidInput(
          fmt::format("optimal control: warm_start: got [{}]; expected increasing whole numbers of intervals "
                      "from 2 to intervals − 1 = {}",
                      fmt::join(sc.mesh_sequence, ", "), sc.problem.intervals - 1));
    }
  }
}

MultibodyOptimalScenario multibody_optimal_scenario_of(const optimal::MultibodyProblem& problem,
                                                       const optimal::MultibodyOptions& options,
                                                       std::vector<int> mesh_sequence) {
  optimal::validate(problem);
  MultibodyOptimalScenario sc;
  sc.name = "multibody";
  sc.source = "<problem>";
  sc.model.system = problem.system;
  sc.model.initial = problem.initial_state;
  sc.problem = problem;
  sc.options = options;
  sc.options.warm_start = nullptr;  // the mesh sequence gives the warm starts
  sc.mesh_sequence = std::move(mesh_sequence);
  check_multibody_options(sc);
  return sc;
}

MultibodyOptimalScenario load_multibody_optimal_scenario(const std::string& path) {
  const std::filesystem::path p(path);
  MultibodyOptimalScenario sc =
      parse_multibody_optimal_scenario(detail::read_scenario_file(path), path, p.parent_path().string());
  sc.name = p.stem().string();
  return sc;
}

}  // namespace poinsot::io
