#pragma once
/// @file scenario.hpp
/// Multibody scenario files (TOML) and the driver that runs them: the entry point of `poinsot run` for files
/// with a `[[bodies]]` array. The format is documented in docs/multibody.md, with examples in
/// examples/multibody/. Units SI throughout.
///
///     [simulation]   dt (s), duration (s), output_every (steps), gravity = [x, y, z] (m/s²)
///     [[bodies]]     name, mass (kg), one of inertia (J, kg·m²: [Jxx, Jyy, Jzz] or 3×3) / poinsot (K) /
///                    shape = { type = "rod"|"cylinder"|"box"|"sphere", length, radius, size, axis },
///                    position (m), rotation ({ axis, angle } rad, or quaternion = [w, x, y, z], or matrix),
///                    velocity (m/s), omega_body (rad/s, body frame)
///     [[joints]]     name, type = "ball"|"hinge"|"weld", body_a, point_a (body a frame), body_b (default
///                    "world"), point_b (body b or space frame; default: where point_a is at t = 0),
///                    axis_a, axis_b (hinge; axis_b defaults to axis_a carried by the initial rotations)
///     [[springs]]    body_a, point_a, body_b, point_b, stiffness (N/m), damping (N·s/m), rest_length (m)
///     [[forces]]     body, force (N, space), point (m, body frame)
///     [[torques]]    body, torque (N·m), frame = "space"|"body"
///
/// Initial velocities are projected onto the joint constraints (least kinetic-energy change), so a scenario
/// may give only the velocities it cares about.

#include <iosfwd>
#include <string>

#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

struct Scenario {
  System system;
  State initial;
  double dt = 1e-3;       ///< s
  double duration = 1.0;  ///< s
  int output_every = 10;  ///< steps between trajectory rows
  int order = 2;          ///< RATTLE (2) or its fourth-order composition (4), rattle.hpp
};

/// True when the TOML file at `toml_path` has a `[[bodies]]` array (a multibody scenario). Throws
/// InvalidInput when the file cannot be read or parsed.
bool is_multibody_scenario(const std::string& toml_path);

/// Reads and validates a scenario. Throws InvalidInput with a one-line message naming the file, the entry and
/// the field (e.g. `scenario chain.toml: bodies[2].mass: -1 kg must be > 0`).
Scenario load_scenario(const std::string& toml_path);
/// Same from TOML text; `source_name` is used in messages.
Scenario parse_scenario(const std::string& toml_text, const std::string& source_name);

/// Projects every body's velocity onto the joint constraints, G v = 0, minimising the change of kinetic
/// energy (one KKT solve, kkt_solver.hpp).
void project_velocities(const System& system, State& state);

/// What a run measured.
struct RunSummary {
  long steps = 0;
  double energy_initial = 0.0, energy_final = 0.0;  ///< J
  double max_energy_error = 0.0;                    ///< max |E(t) − E(0)|, J
  double max_joint_gap = 0.0;                       ///< m
  double max_joint_angle = 0.0;                     ///< dimensionless
  double max_orthogonality = 0.0;                   ///< max |RᵀR − I|
  double mean_newton_iterations = 0.0;
  int max_newton_iterations = 0;
  bool tree_solver = true;
  KktMethod kkt_method = KktMethod::tree;
  double cpu_seconds_per_step = 0.0;
};

/// Integrates the scenario with RATTLE (rattle.hpp). Writes a CSV trajectory to `trajectory_csv` unless it is
/// empty (columns: t, then per body x y z qw qx qy qz vx vy vz wx wy wz) and a human-readable report to
/// `report` unless null (energy, momenta, constraint violation, joint reactions and each body's Λ at the
/// end). On a ComputationFailed the rows already written stay in the file and the exception propagates.
RunSummary run_scenario(const Scenario& scenario, std::ostream* report, const std::string& trajectory_csv);

/// `poinsot run` entry: load_scenario + run_scenario. Returns 0.
int run_file(const std::string& toml_path, std::ostream& report, const std::string& trajectory_csv);

}  // namespace poinsot::multibody
