#pragma once
/// @file scenario_file.hpp
/// A scenario file of either kind, parsed once: a single-body scenario (scenario.hpp, docs/scenario.md) or,
/// when its top level has a `bodies` array, a multibody scenario (multibody_scenario.hpp, docs/multibody.md).
/// `poinsot run` reads its file through this, then runs the kind it got.

#include <string>
#include <string_view>
#include <variant>

#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::io {

/// One scenario of either kind.
using AnyScenario = std::variant<Scenario, multibody::Scenario>;

/// Parses TOML text once and reads the scenario of the kind it is (multibody when the top level has
/// `bodies`). `source` names it in messages; relative files are looked up in `base_dir`. Throws InvalidInput
/// (one line, located) on any problem.
AnyScenario parse_any_scenario(std::string_view text, std::string_view source = "<string>",
                               std::string_view base_dir = "");

/// Reads a scenario file of either kind; a single-body scenario is named after the file's stem, as
/// load_scenario does. A robot file (.urdf, .xml, .sdf: robot_system.hpp) is read as a multibody scenario
/// with the defaults of RobotSystemOptions; a TOML file with a `[model]` table names one
/// (docs/robot_models.md).
AnyScenario load_any_scenario(const std::string& path);

/// True when the TOML file at `path` is a multibody scenario (its top level has `bodies` or `model`), or
/// `path` is a robot file. Parses the file;
/// prefer load_any_scenario when the scenario is then loaded. Throws InvalidInput when the file cannot be
/// read or is not TOML.
bool is_multibody_scenario(const std::string& path);

}  // namespace poinsot::io
