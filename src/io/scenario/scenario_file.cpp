// A scenario file of either kind, parsed once (see scenario_file.hpp).
#include "poinsot/io/scenario/scenario_file.hpp"

#include <filesystem>

#include "poinsot/io/robot/robot_system.hpp"
#include "scenario_table.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

bool has_bodies(const toml::table& root) {
  return root.get("bodies") != nullptr || root.get("model") != nullptr;
}

}  // namespace

AnyScenario parse_any_scenario(std::string_view text, std::string_view source, std::string_view base_dir) {
  const toml::table root = detail::parse_toml(text, source);
  if (root.get("model") != nullptr) return detail::robot_scenario_from_table(root, source, base_dir);
  if (has_bodies(root)) return detail::multibody_scenario_from_table(root, source, base_dir);
  return detail::single_scenario_from_table(root, source, base_dir);
}

AnyScenario load_any_scenario(const std::string& path) {
  if (is_robot_file(path)) return load_robot_scenario(path);
  const std::filesystem::path p(path);
  AnyScenario sc = parse_any_scenario(detail::read_text_file(path), path, p.parent_path().string());
  if (auto* single = std::get_if<Scenario>(&sc)) single->name = p.stem().string();
  return sc;
}

bool is_multibody_scenario(const std::string& path) {
  if (is_robot_file(path)) return true;
  return has_bodies(detail::parse_toml(detail::read_text_file(path), path));
}

}  // namespace poinsot::io
