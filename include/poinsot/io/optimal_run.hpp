#pragma once
/// @file optimal_run.hpp
/// `poinsot optimize`: the direct method (mesh refinement, then the phase-per-arc re-solve of a minimum-time
/// bang-bang solution), the indirect method from its costates, the verification and the interpretation of an
/// OptimalScenario, and the files and texts that report them (docs/optimal_control.md):
///   report.txt      the human-readable report (also printed)
///   trajectory.csv  t, q (w, x, y, z), ω body (rad/s), u body (N·m), L space (kg·m²/s)
///   control.csv     t, u body (N·m): piecewise linear in t, with two rows at each switch (left and right
///                   values), so that linear interpolation replays a bang-bang control exactly
///   costates.csv    t, p_θ, p_ω, σ = J⁻¹p_ω, H
///   summary.json    the same as `--json`: "kind": "optimal", status, the problem's bounds and target, both
///                   methods' results, the checks and the interpretation
/// Every CSV starts with a `# status: ...` line; a solution that is not verified optimal says
/// "not converged" there, in the report and in summary.json, and keeps the best iterate.
#include <string>

#include "poinsot/io/optimal_scenario.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/interpretation.hpp"
#include "poinsot/optimal/verification.hpp"

namespace poinsot::io {

struct OptimalRun {
  OptimalScenario scenario;
  optimal::DirectSolution direct;  ///< the mesh-refined direct solution (it seeds the indirect method)
  /// The phase-per-arc re-solve (phased_collocation.hpp): applied when the scenario allows it, the objective
  /// is minimum time, the direct solution converged and its switching structure is one the re-solve takes
  /// (read_switching_structure does not refuse it); `phased_status` says "converged", Ipopt's failure,
  /// "not applicable: <why>" or "off".
  bool phased_applied = false;
  optimal::PhasedSolution phased;
  std::string phased_status;
  optimal::IndirectSolution indirect;
  optimal::VerificationReport verification;
  bool has_interpretation = false;
  optimal::ManoeuvreInterpretation interpretation;
  bool optimal = false;  ///< both methods converged and every check passed
  std::string status;    ///< "optimal (verified)" or "not converged: <what failed>"
};

/// The direct optimum the checks compare with: the phased re-solve's when it converged, else the mesh-refined
/// one.
const optimal::DirectSolution& direct_optimum(const OptimalRun& run);
/// "phased" or "mesh_refinement": which phase of the direct method produced direct_optimum(run).
const char* direct_optimum_source(const OptimalRun& run);

/// Solves and checks; never throws for a solver failure (the status says it).
OptimalRun run_optimal(const OptimalScenario& scenario);

std::string optimal_report(const OptimalRun& run);
std::string optimal_summary_json(const OptimalRun& run);
/// Writes the five files into `dir` (created), each atomically.
void write_optimal_files(const OptimalRun& run, const std::string& dir);

}  // namespace poinsot::io
