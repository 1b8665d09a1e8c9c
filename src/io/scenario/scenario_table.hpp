#pragma once
// Internal to the io layer: the two kinds of scenario read from an already parsed TOML table, so that a file
// is parsed once whichever kind it is (scenario_file.hpp).

#include <optional>
#include <string_view>

#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "toml_fields.hpp"

namespace poinsot::io::detail {

/// A single-body scenario (docs/scenario.md) from its table; `source` names it in messages, relative files
/// are looked up in `base_dir`.
Scenario single_scenario_from_table(const toml::table& root, std::string_view source,
                                    std::string_view base_dir);

/// A multibody scenario (docs/multibody.md, a `[[bodies]]` array) from its table.
multibody::Scenario multibody_scenario_from_table(const toml::table& root, std::string_view source,
                                                  std::string_view base_dir);

/// The `[simulation]` section of a multibody file (dt, duration, output_every, method, order) into `sc`;
/// returns its `gravity` (m/s²) when given. Throws located InvalidInput.
std::optional<Vec3> read_multibody_simulation(const Source& src, const Section& top, multibody::Scenario& sc);

/// A multibody scenario whose system comes from a robot file (`[model] file = "arm.urdf"`, relative to
/// `base_dir`; docs/robot_models.md) from its table.
multibody::Scenario robot_scenario_from_table(const toml::table& root, std::string_view source,
                                              std::string_view base_dir);

/// The array of tables `key` of a section (`[[key]]`, or an array of inline tables), or null when absent.
/// Throws located InvalidInput when it is something else.
const toml::array* table_array(const Section& section, std::string_view key);

/// A body's orientation in a multibody file: `rotation` ({ axis, angle } rad, or a 3×3 rotation matrix) or
/// `quaternion` = [w, x, y, z] (normalised); the identity when neither is given. Throws located InvalidInput.
Mat3 read_rotation(const Source& src, const Section& body);

}  // namespace poinsot::io::detail
