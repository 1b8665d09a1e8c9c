#pragma once
/// @file scenario.hpp
/// A multibody scenario (a System, its initial State, the step and the output rate) and the driver that runs
/// it: the multibody half of `poinsot run`. The files are read in the io layer (io/multibody_scenario.hpp,
/// the format in docs/multibody.md, examples in examples/multibody/). Units SI throughout.

#include <iosfwd>
#include <string>
#include <vector>

#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

/// The integrator of a multibody run: RATTLE (rattle.hpp; symplectic, for long runs; order 2 or 4) or the
/// projected classical RK4 (projected_rk4.hpp; fourth order, not symplectic, for accurate bounded runs and
/// exact multipliers at every sample).
enum class MultibodyMethod { rattle, projected_rk4 };
/// "rattle" or "rk4": the names of scenario files' `[simulation] method`, of `poinsot run --method`, of
/// summary.json and of Python.
const char* multibody_method_name(MultibodyMethod method);

/// A multibody scenario ready to run: the model, the initial state (velocities already projected onto the
/// joints), the step (s), the duration (s) and the output rate. Each body's `x_space` is its centre of mass.
struct Scenario {
  System system;
  State initial;
  double dt = 1e-3;       ///< s
  double duration = 1.0;  ///< s
  int output_every = 10;  ///< steps between trajectory rows
  MultibodyMethod method = MultibodyMethod::rattle;
  int order = 2;       ///< RATTLE (2) or its fourth-order composition (4), rattle.hpp; 4 for projected_rk4
  std::string source;  ///< the file it came from (or a name), for the report; may be empty
  std::string title;   ///< an optional one-line description, for the report
  /// Per body (system order), how its inertia was given and where its centre of mass lies in the frame of
  /// its file, for the report; may be empty.
  std::vector<std::string> body_descriptions;
};

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
  double max_orthogonality = 0.0;                   ///< max ‖RᵀR − I‖_F
  double mean_newton_iterations = 0.0;  ///< RATTLE's position stages, or RK4's joint projections, per step
  int max_newton_iterations = 0;
  bool tree_solver = true;
  KktMethod kkt_method = KktMethod::tree;
  double cpu_seconds_per_step = 0.0;
};

/// Integrates the scenario with its method (RATTLE, rattle.hpp, or the projected RK4, projected_rk4.hpp).
/// Writes a CSV trajectory to `trajectory_csv` unless it is empty (columns: t, then per body x y z qw qx qy
/// qz vx vy vz wx wy wz: the centre of mass (m), the rotation body → space as a quaternion, the velocity of
/// the centre of mass (m/s), ω in the body frame (rad/s)) and a human-readable report to `report` unless null
/// (energy, momenta, constraint violation, joint reactions and each body's Λ at the end).
///
/// Writes the conserved quantities and the constraint violation to `diagnostics_csv` unless it is empty, one
/// row per trajectory row (t = 0, every `output_every` steps and the last step), columns:
/// `t` (s), `energy` E = T + V (J, observables.hpp), `energy_error` E − E(0) (J; its largest magnitude over
/// every step is RunSummary::max_energy_error), `kinetic` T (J), `potential` V (J, loads.hpp: gravity,
/// springs, constant forces), `linear_momentum` |Σ m v| (kg·m/s), `L_space_x`, `L_space_y`, `L_space_z` the
/// angular momentum about the space origin Σ (x × m v + R J ω) (kg·m²/s), `joint_gap` (m), `joint_angle`
/// (dimensionless) and `orthogonality` max ‖RᵀR − I‖_F (dimensionless), the maxima over joints and bodies of
/// ConstraintViolation.
///
/// On a ComputationFailed the rows already written stay in both files and the exception propagates.
RunSummary run_scenario(const Scenario& scenario, std::ostream* report, const std::string& trajectory_csv,
                        const std::string& diagnostics_csv = "");

}  // namespace poinsot::multibody
