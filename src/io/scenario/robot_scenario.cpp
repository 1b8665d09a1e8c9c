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
namespace {

/// A table of joint coordinates by name: `{ shoulder = 0.3, neck = [1, 0, 0, 0] }`.
std::map<std::string, std::vector<double>> read_coordinates(const Source& src, const Section& model,
                                                            std::string_view key) {
  std::map<std::string, std::vector<double>> out;
  const toml::table* t = model.table(key);
  if (t == nullptr) return out;
  for (const auto& [name, node] : *t) {
    std::vector<double> values;
    const auto bad = [&] {
      throw InvalidInput(fmt::format("{}[{}] {}.{}: got {}, expected a number or an array of numbers",
                                     location(src, &node), model.name(), key, name.str(), describe(node)));
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

}  // namespace

multibody::Scenario robot_scenario_from_table(const toml::table& root, std::string_view source,
                                              std::string_view base_dir) {
  const Source src{std::string(source)};
  const Section top(src, &root, "top level", {"title", "simulation", "model"});
  multibody::Scenario timing;
  const std::optional<Vec3> gravity = read_multibody_simulation(src, top, timing);
  const Section model(src, top.table("model"), "model",
                      {"file", "inertia", "floating_base", "positions", "velocities", "base"},
                      top.node("model"));
  model.require("file", "the robot file (URDF, MJCF or SDF), relative to the scenario's folder");
  const std::filesystem::path file = std::filesystem::path(base_dir) / *model.string("file");
  RobotSystemOptions options;
  options.gravity = gravity;
  const std::string inertia = model.string("inertia").value_or("file");
  if (inertia != "file" && inertia != "geometry")
    model.fail("inertia", fmt::format("got \"{}\", expected \"file\" or \"geometry\"", inertia));
  options.inertia = inertia == "file" ? RobotInertiaSource::file : RobotInertiaSource::geometry;
  options.floating_base = model.boolean("floating_base").value_or(false);
  options.positions = read_coordinates(src, model, "positions");
  options.velocities = read_coordinates(src, model, "velocities");
  if (const toml::table* b = model.table("base")) {
    const Section base(src, b, "model.base", {"position", "rotation", "quaternion", "velocity", "omega_body"},
                       model.node("base"));
    options.base_position = base.vec3("position");
    if (base.has("rotation") || base.has("quaternion")) options.base_rotation = read_rotation(src, base);
    options.base_velocity = base.vec3("velocity");
    options.base_omega_body = base.vec3("omega_body");
  }
  RobotModel robot;
  try {
    robot = load_robot_model(file.string());
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    if (what.starts_with("model:")) model.fail("file", what);
    throw;
  }
  multibody::Scenario sc;
  try {
    sc = robot_scenario(robot, options);
  } catch (const InvalidInput& e) {
    const std::string what = e.what();
    for (const char* key : {"positions", "velocities"})
      if (what.starts_with(std::string(key) + ".")) model.fail(key, what);
    if (what.starts_with("base:")) model.fail("base", what.substr(6));
    throw;
  }
  sc.source = std::string(source);
  sc.title = top.string("title").value_or(sc.title + ", " + file.filename().string());
  sc.dt = timing.dt;
  sc.duration = timing.duration;
  sc.output_every = timing.output_every;
  sc.method = timing.method;
  sc.order = timing.order;
  return sc;
}

}  // namespace poinsot::io::detail
