#pragma once
/// @file multibody_optimal_scenario.hpp
/// Multibody scenario files with an `[optimal_control]` section, for `poinsot optimize`
/// (docs/optimal_control.md, "Multibody scenario files"): the system and its initial state exactly as
/// `poinsot run` reads them (multibody_scenario.hpp: [simulation] gravity, [[bodies]], [[joints]],
/// [[forces]], [[torques]]; the integration keys dt, duration, output_every, method and order are read but
/// not used), and the problem:
///
///     [optimal_control]
///     objective = "minimum_energy"       # ∫ Σ u_i² dt at fixed final_time; or "minimum_time" (T), or
///                                        # "minimum_time_regularised" (T + energy_weight ∫ Σ u_i² dt)
///     final_time = 1.5                   # s: fixed (minimum_energy) or the guess of T (minimum_time)
///     final_time_bounds = [0.1, 10]      # s, minimum_time only: T_min ≤ T ≤ T_max
///     energy_weight = 1e-3               # ε > 0, s/(N²·m²·s), minimum_time_regularised only
///     coordinates = "rotation_matrix"    # or "minimal" (hinges and balls, fixed or floating base)
///     intervals = 20                     # Hermite–Simpson intervals, 2 … 2000
///     nlp_tolerance = 1e-10              # optional: Ipopt's tol
///     max_nlp_iterations = 500           # optional, 1 … 100000
///     replay_steps = 64                  # RK4 steps per interval re-simulating the control, 1 … 10000
///     target_tolerance = 1e-3            # how close the re-simulation must come to the target (below)
///     actuators = [ { joint = "shoulder", torque_max = 50 },   # a hinge motor, or three ball motors (N·m)
///                   { body = "upper", torque_max = 5 } ]       # three body-frame torques on a body (N·m)
///     rate_bounds = [ { joint = "shoulder", rate_max = 2.0 } ]   # optional: |q̇| ≤ rate_max (rad/s)
///     stabilisation_step = 0.05          # optional, rotation_matrix: c of MultibodyOptions, 0 ≤ c < 0.6
///     warm_start = [6, 12]               # optional: meshes solved first, each from the previous optimum
///     no_twist = [ { joint = "waist", axis_a = [1, 0, 0],         # optional, rotation_matrix: NoTwist of
///                    rotation = { axis = [0, 0, 1], angle = 3.141592653589793 } } ]   # a ball joint (C)
///     [[optimal_control.final]]          # one per body: the target state at t = final_time
///     body = "upper"
///     rotation = { axis = [0, 0, 1], angle = 1.0 }   # or quaternion = [w, x, y, z], or a 3×3 matrix
///     center_of_mass = [x, y, z]         # m, optional: else placed by its joints (see below)
///     velocity = [vx, vy, vz]            # m/s (centre of mass), optional, default 0
///     omega_body = [wx, wy, wz]          # rad/s, optional, default 0
///     [output]
///     dir = "..."                        # optional, default SCENARIO-optimize
///
/// A target body without `center_of_mass` is placed by a joint to the world or to a placed body so that the
/// joint's two points coincide (x_a = x_b + R_b p_b − R_a p_a); the target's velocities are projected onto
/// the joints as the initial ones are (least change of kinetic energy), so a rest-to-rest target needs
/// rotations only. The re-simulation meets the target when its attitude error is at most `target_tolerance`
/// rad, its position error at most target_tolerance·L and its velocity error at most target_tolerance·max(1
/// m, L)/T (L the system's length scale; the velocity error is the larger of |Δv| in m/s and |Δω| in rad/s).
///
/// The system may instead come from a robot file named by a `[model]` table (scenario_table.hpp,
/// docs/robot_models.md), the actuators naming its joints; the target is then given by the joints too:
/// `final_positions = { JOINT = q, ... }` and `final_velocities` (the file's coordinates, joints not named at
/// the file's pose and at rest) and a floating base's `final_base` (as `[model.base]`), or by
/// `[[optimal_control.final]]` tables, not both. A file whose joints have springs or dampers is refused
/// unless `[model] joint_springs = false`. What the file states and the plan leaves out is in
/// `model.not_modelled`.
///
/// Throws InvalidInput, one line located at the key, for every malformed or invalid value; the problem's own
/// checks (optimal::validate: a target that violates a joint, no actuator, a bound ≤ 0, ...) are located at
/// [optimal_control].
#include <string>
#include <string_view>

#include "poinsot/multibody/scenario.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::io {

struct MultibodyOptimalScenario {
  std::string name;                   ///< the file's stem
  std::string source;                 ///< the file's path (or "<string>")
  std::string title;                  ///< the file's `title`, or empty
  multibody::Scenario model;          ///< the system and initial state as `poinsot run` reads them
  optimal::MultibodyProblem problem;  ///< validated
  optimal::MultibodyOptions options;  ///< coordinates and Ipopt's settings
  int replay_steps = 64;              ///< projected-RK4 steps per interval in the re-simulation
  double target_tolerance = 1e-3;     ///< see the file comment
  /// The mesh sequence (`warm_start`): the numbers of intervals solved before problem.intervals, increasing,
  /// the first from the naive guess and each later one (the last included) from the previous optimum
  /// (optimal::MultibodyOptions::warm_start). Empty: the naive guess on problem.intervals alone.
  std::vector<int> mesh_sequence;
  std::string out_dir;  ///< [output] dir; empty: the default
};

/// Parses scenario text; `source` names it in messages, `base_dir` resolves relative mesh paths. Throws
/// InvalidInput located at the offending key.
MultibodyOptimalScenario parse_multibody_optimal_scenario(std::string_view text, std::string_view source,
                                                          std::string_view base_dir);
/// Reads and parses the file at `path` (name = its stem).
MultibodyOptimalScenario load_multibody_optimal_scenario(const std::string& path);

/// A scenario around a problem built in code (Python's poinsot.optimal.MultibodyProblem): named "multibody",
/// source "<problem>", the default replay and target tolerance, no output folder. options.warm_start is
/// ignored (the mesh sequence gives the warm starts). Throws InvalidInput when the problem is invalid
/// (optimal::validate) or the options are (check_multibody_options).
MultibodyOptimalScenario multibody_optimal_scenario_of(const optimal::MultibodyProblem& problem,
                                                       const optimal::MultibodyOptions& options = {},
                                                       std::vector<int> mesh_sequence = {});

/// Throws InvalidInput `optimal control: KEY: got ...; expected ...` unless the stabilisation step is in
/// [0, 0.6) and 0 in minimal coordinates, there is no no-twist condition in minimal coordinates, and the mesh
/// sequence increases from 2 to below problem.intervals.
void check_multibody_options(const MultibodyOptimalScenario& scenario);

/// The name of a coordinates value as the files spell it ("rotation_matrix", "minimal").
std::string_view coordinates_name(optimal::MultibodyCoordinates coordinates);

}  // namespace poinsot::io
