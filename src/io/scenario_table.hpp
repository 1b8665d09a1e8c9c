#pragma once
// Internal to the io layer: the two kinds of scenario read from an already parsed TOML table, so that a file
// is parsed once whichever kind it is (scenario_file.hpp).

#include <string_view>

#include "poinsot/io/scenario.hpp"
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

}  // namespace poinsot::io::detail
