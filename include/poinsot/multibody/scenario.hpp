#pragma once
/// @file scenario.hpp
/// A multibody scenario (a System, its initial State, the step and the output rate) and the loop that runs
/// it, handing every output row to an observer. The files are read and written in the io layer
/// (io/scenario/multibody_scenario.hpp, io/run/multibody_run.hpp; the format in docs/multibody.md, examples
/// in examples/multibody/): this layer computes, io serialises. Units SI throughout.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "poinsot/inertia/mesh.hpp"
#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

/// A multibody scenario ready to run: the model, the initial state (velocities already projected onto the
/// joints), the step (s), the duration (s) and the output rate. Each body's `x_space` is its centre of mass.
struct Scenario {
  System system;
  State initial;
  double dt = 1e-3;       ///< s
  double duration = 1.0;  ///< s
  int output_every = 10;  ///< steps between trajectory rows
  MultibodyMethod method = kDefaultMultibodyMethod;
  int order = 2;       ///< RATTLE (2) or its fourth-order composition (4), rattle.hpp; 4 for projected_rk4
  std::string source;  ///< the file it came from (or a name), for the report; may be empty
  std::string title;   ///< an optional one-line description, for the report
  /// Per body (system order), how its inertia was given and where its centre of mass lies in the frame of
  /// its file, for the report; may be empty.
  std::vector<std::string> body_descriptions;
  /// Per body (system order), its surface about its centre of mass (body frame, m) when the file gives a
  /// shape or a mesh, for drawing (view.html); null otherwise. May be empty.
  std::vector<std::shared_ptr<const inertia::TriangleMesh>> body_surfaces;
  /// What the source file states that the model leaves out (a robot file's contacts, limits, actuators...),
  /// one line each, for the report; empty for poinsot's own scenario files.
  std::vector<std::string> not_modelled;
};

/// Projects every body's velocity onto the joint constraints, G v = 0, minimising the change of kinetic
/// energy (one KKT solve, kkt_solver.hpp).
void project_velocities(const System& system, State& state);

/// What a run measured.
struct RunSummary {
  long steps = 0;                                   ///< steps taken (fewer than planned when stopped)
  double energy_initial = 0.0, energy_final = 0.0;  ///< J
  double max_energy_error = 0.0;                    ///< max |E(t) − E(0)| over every step, J
  double max_joint_gap = 0.0;                       ///< m
  double max_joint_angle = 0.0;                     ///< dimensionless
  double max_orthogonality = 0.0;                   ///< max ‖RᵀR − I‖_F
  double mean_newton_iterations = 0.0;  ///< RATTLE's position stages, or RK4's joint projections, per step
  int max_newton_iterations = 0;
  bool tree_solver = true;
  KktMethod kkt_method = KktMethod::tree;
  double cpu_seconds_per_step = 0.0;
  bool interrupted = false;  ///< the observer stopped the run before its end
  std::string failure;       ///< the message of the ComputationFailed that stopped the run; empty: none
  /// The state after the last step taken (after a failure, its time is the last completed step's, the rest as
  /// the failed step left it).
  State final_state;
};

/// Called with the state at t₀, after every `output_every` steps and after the last step; returning false
/// stops the run there (RunSummary::interrupted).
using SampleObserver = std::function<bool(const State&)>;

/// Integrates the scenario with its method (RATTLE, rattle.hpp, or the projected RK4, projected_rk4.hpp)
/// from `initial` for round(duration/dt) steps, the sample times being t₀ + n·dt exactly. Measures over every
/// step the largest energy error |E − E(0)| (E = T + V, observables.hpp), joint gap, joint angle and
/// |RᵀR − I|, and the iterations of the position stage (RATTLE) or of the joint projection (RK4).
///
/// A ComputationFailed in a step (e.g. h|ω| ≥ 1) ends the loop: its message is kept in `failure` and the
/// summary holds what was measured up to the last completed step (the caller decides whether to re-throw).
/// Throws InvalidInput when the scenario is inconsistent (check_consistent) or its step is refused by the
/// integrator.
RunSummary simulate(const Scenario& scenario, const SampleObserver& observer = {});

}  // namespace poinsot::multibody
