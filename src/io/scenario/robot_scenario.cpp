// Multibody scenario files that name a robot file: `[model] file = "arm.urdf"` (see scenario_table.hpp and
// docs/robot_models.md, "Robot files as multibody systems").
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io::detail {

std::map<std::string, std::vector<double>> read_joint_coordinates(const Source& src, const Section& section,
                                                                  std::string_view key) {
  std::map<std::string, std::vector<double>> out;
  const toml::table* t = section.table(key);
  if (t == nullptr) return out;
  for (const auto& [name, node] : *t) {
    std::vector<double> values;
    const auto bad = [&] {
      throw InvalidInput(fmt::format("{}[{}] {}.{}: got {}, expected a number or an array of numbers",
                                     location(src, &node), section.name(), key, name.str(), describe(node)));
    };
    if (const auto x = node.value<double>()) {
      values.push_back(*x);
    } else if (const toml::array* a = node.as_array()) {
      for (const toml::node& e : *a) {
        const auto element = e.value<double>();
        if (!element) bad();
        values.push_back(*element);
      }
    } else {
      bad();
    }
    for (const double x : values)
      if (!std::isfinite(x)) bad();
    out.emplace(std::string(name.str()), std::move(values));
  }
  return out;
}

void read_robot_base(const Source& src, const Section& section, std::string_view key,
                     RobotSystemOptions& options) {
  const toml::table* b = section.table(key);
  if (b == nullptr) return;
  const Section base(src, b, fmt::format("{}.{}", section.name(), key),
                     {"position", "rotation", "quaternion", "velocity", "omega_body"}, section.node(key));
  options.base_position = base.vec3("position");
  if (base.has("rotation") || base.has("quaternion")) options.base_rotation = read_rotation(src, base);
  options.base_velocity = base.vec3("velocity");
  options.base_omega_body = base.vec3("omega_body");
}

multibody::Scenario robot_scenario_located(const Section& section, const RobotModel& robot,
                                           const RobotSystemOptions& options, const RobotStateKeys& keys) {
  try {
    return robot_scenario(robot, options);
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    // "positions.NAME: ..." → "[section] KEY: KEY.NAME: ..."
    if (what.starts_with("positions."))
      section.fail(keys.positions, fmt::format("{}{}", keys.positions, what.substr(9)));
    if (what.starts_with("velocities."))
      section.fail(keys.velocities, fmt::format("{}{}", keys.velocities, what.substr(10)));
    if (what.starts_with("base:")) section.fail(keys.base, what.substr(6));
    throw;
  }
}

multibody::Scenario robot_scenario_from_table(const toml::table& root, std::string_view source,
                                              std::string_view base_dir, RobotFileTable* kept) {
  const Source src{std::string(source)};
  const Section top(src, &root, "top level", {"title", "simulation", "model"});
  multibody::Scenario timing;
  const std::optional<Vec3> gravity = read_multibody_simulation(src, top, timing);
  const Section model(
      src, top.table("model"), "model",
      {"file", "inertia", "floating_base", "joint_springs", "positions", "velocities", "base"},
      top.node("model"));
  model.require("file", "the robot file (URDF, MJCF or SDF), relative to the scenario's folder");
  const std::filesystem::path file = std::filesystem::path(base_dir) / *model.string("file");
  RobotFileTable read;
  RobotSystemOptions& options = read.options;
  options.gravity = gravity;
  const std::string inertia = model.string("inertia").value_or("file");
  if (inertia != "file" && inertia != "geometry")
    model.fail("inertia", fmt::format("got \"{}\", expected \"file\" or \"geometry\"", inertia));
  options.inertia = inertia == "file" ? RobotInertiaSource::file : RobotInertiaSource::geometry;
  options.floating_base = model.boolean("floating_base").value_or(false);
  options.joint_springs = model.boolean("joint_springs").value_or(true);
  options.positions = read_joint_coordinates(src, model, "positions");
  options.velocities = read_joint_coordinates(src, model, "velocities");
  read_robot_base(src, model, "base", options);
  try {
    read.robot = load_robot_model(file.string());
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    if (what.starts_with("model:")) model.fail("file", what);
    throw;
  }
  multibody::Scenario sc = robot_scenario_located(model, read.robot, options, {});
  sc.source = std::string(source);
  sc.title = top.string("title").value_or(sc.title + ", " + file.filename().string());
  sc.dt = timing.dt;
  sc.duration = timing.duration;
  sc.output_every = timing.output_every;
  sc.method = timing.method;
  sc.order = timing.order;
  if (kept != nullptr) *kept = std::move(read);
  return sc;
}

}  // namespace poinsot::io::detail
