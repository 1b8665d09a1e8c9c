#pragma once
/// @file multibody_optimal_run.hpp
/// `poinsot optimize` on a multibody scenario (multibody_optimal_scenario.hpp): the direct transcription
/// (optimal/multibody_direct.hpp), the re-simulation of its control history by the multibody projected RK4,
/// and the files and texts that report them (docs/optimal_control.md, "Multibody scenario files"):
///   report.txt       the human-readable report (also printed)
///   trajectory.csv   at every collocation point (nodes and midpoints): the columns of a multibody run's
///                    trajectory.csv (t; per body NAME.x .y .z, NAME.qw .qx .qy .qz, NAME.vx .vy .vz,
///                    NAME.wx .wy .wz)
///   control.csv      t, then per actuator NAME.u (a hinge motor, N·m) or NAME.ux .uy .uz (a body torque,
///                    body frame, N·m) at every collocation point; between them the control is the quadratic
///                    through the node, midpoint and node values of each interval (optimal::control_at)
///   reactions.csv    per point and joint: the reaction on body a (N, N·m, space frame)
///   multipliers.csv  per point and body: the centre of mass and Λ (J, body frame)
///   summary.json     the same as `--json`: "kind": "multibody_optimal", status, the problem (with its
///                    actuators, rate bounds, no-twist conditions, stabilisation step and mesh sequence, each
///                    mesh's status, iterations and cost under "mesh_sequence"), the solution (with the peak
///                    rate of every bounded hinge over the collocation points), the re-simulation
/// Every CSV starts with a `# status: ...` line. The result is "optimal" only when Ipopt converged and the
/// re-simulated control reaches the target within the scenario's tolerance; otherwise the status says
/// "not converged: ..." everywhere and the last iterate is kept.
#include <functional>
#include <string>
#include <vector>

#include "poinsot/io/run/optimal_progress.hpp"
#include "poinsot/io/scenario/multibody_optimal_scenario.hpp"
#include "poinsot/optimal/multibody_direct.hpp"

namespace poinsot::io {

/// One mesh of the scenario's mesh sequence, solved before the last (warm_start).
struct MultibodyMeshStage {
  int intervals = 0;
  std::string status;  ///< the solver's ("converged" or "not converged: ...")
  int nlp_iterations = 0;
  double cost = 0.0;  ///< N²·m²·s
};

struct MultibodyOptimalRun {
  MultibodyOptimalScenario scenario;
  std::vector<MultibodyMeshStage> mesh_stages;  ///< the mesh sequence's solves, in order
  optimal::MultibodyOptimum optimum;            ///< on scenario.problem.intervals
  optimal::MultibodyReplay replay;
  bool target_reached = false;  ///< the re-simulation's errors within the scenario's tolerance
  bool optimal = false;         ///< Ipopt converged and the target is reached
  std::string status;           ///< "optimal" or "not converged: <what failed>"
};

/// Solves on each mesh of the scenario's mesh sequence, then on its intervals (each from the previous
/// optimum), and re-simulates; never throws for a solver failure (the status says it). A mesh of the
/// sequence that does not converge only gives its last iterate as the next guess: the last mesh decides.
/// `progress`, when given, is called after every Ipopt iteration (phase "direct", the mesh's place in the
/// sequence) and before the re-simulation ("replay").
MultibodyOptimalRun run_multibody_optimal(const MultibodyOptimalScenario& scenario,
                                          const std::function<void(const OptimalProgress&)>& progress = {});

std::string multibody_optimal_report(const MultibodyOptimalRun& run);
std::string multibody_optimal_summary_json(const MultibodyOptimalRun& run);
/// Writes the six files into `dir` (created), each atomically.
void write_multibody_optimal_files(const MultibodyOptimalRun& run, const std::string& dir);

}  // namespace poinsot::io
