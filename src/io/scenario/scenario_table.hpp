#pragma once
// Internal to the io layer: the two kinds of scenario read from an already parsed TOML table, so that a file
// is parsed once whichever kind it is (scenario_file.hpp).

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/io/robot/robot_system.hpp"
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

/// A `[model]` table read: the robot file and the scenario's choices about it (the initial state among them).
struct RobotFileTable {
  RobotModel robot;
  RobotSystemOptions options;
};

/// A multibody scenario whose system comes from a robot file (`[model] file = "arm.urdf"`, relative to
/// `base_dir`; docs/robot_models.md) from its table. `kept`, when given, receives the file and the choices,
/// so that a caller can build other states of the same system (robot_scenario_located).
multibody::Scenario robot_scenario_from_table(const toml::table& root, std::string_view source,
                                              std::string_view base_dir, RobotFileTable* kept = nullptr);

/// Joint coordinates by joint name, the table `key` of `section`: `{ shoulder = 0.3, neck = [1, 0, 0, 0] }`
/// (RobotSystemOptions::positions and velocities); empty when absent. Throws located InvalidInput for a value
/// that is not a finite number or an array of them.
std::map<std::string, std::vector<double>> read_joint_coordinates(const Source& src, const Section& section,
                                                                  std::string_view key);

/// The floating base's pose and twist, the table `key` of `section` (position m, rotation or quaternion,
/// velocity m/s, omega_body rad/s), into `options`; nothing when absent.
void read_robot_base(const Source& src, const Section& section, std::string_view key,
                     RobotSystemOptions& options);

/// The keys of a section that gave RobotSystemOptions' positions, velocities and base.
struct RobotStateKeys {
  std::string_view positions = "positions";
  std::string_view velocities = "velocities";
  std::string_view base = "base";
};

/// io::robot_scenario(robot, options), with its messages about the positions, velocities and base located at
/// the keys of `section` that gave them.
multibody::Scenario robot_scenario_located(const Section& section, const RobotModel& robot,
                                           const RobotSystemOptions& options, const RobotStateKeys& keys);

/// The array of tables `key` of a section (`[[key]]`, or an array of inline tables), or null when absent.
/// Throws located InvalidInput when it is something else.
const toml::array* table_array(const Section& section, std::string_view key);

/// A body's orientation in a multibody file: `rotation` ({ axis, angle } rad, or a 3×3 rotation matrix) or
/// `quaternion` = [w, x, y, z] (normalised); the identity when neither is given. Throws located InvalidInput.
Mat3 read_rotation(const Source& src, const Section& body);

}  // namespace poinsot::io::detail
