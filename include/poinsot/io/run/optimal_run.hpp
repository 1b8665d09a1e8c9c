#pragma once
/// @file optimal_run.hpp
/// `poinsot optimize`: the direct method (mesh refinement, then the phase-per-arc re-solve of a minimum-time
/// bang-bang solution), the indirect method from its costates, the verification and the interpretation of an
/// OptimalScenario, and the files and texts that report them (docs/optimal_control.md):
///   report.txt      the human-readable report (also printed)
///   trajectory.csv  t, q (w, x, y, z), ω body (rad/s), u body (N·m), L space (kg·m²/s), and with pointing
///                   constraints each boresight's angle to its cone's axis (rad): angle_keep_out_1, ...,
///                   angle_keep_in_1, ... (numbered per kind in the file's order; summary.json's "pointing"
///                   lists each constraint with its column, half-angle and margins)
///   control.csv     t, u body (N·m): piecewise linear in t, with two rows at each switch (left and right
///                   values), so that linear interpolation replays a bang-bang control exactly
///   costates.csv    t, p_θ, p_ω, σ = J⁻¹p_ω, H
///   summary.json    the same as `--json`: "kind": "optimal", status, the problem's bounds and target, both
///                   methods' results, the checks and the interpretation
/// Every CSV starts with a `# status: ...` line, and summary.json's "outcome" says which of three it is:
///   "optimal"           "optimal (verified)": both methods converged and every check of verification.hpp
///                       passed (exit status 0 of `poinsot optimize`);
///   "converged_direct"  "converged (direct; minimum principle not verified: <reason>)": the indirect method
///                       could not verify the optimum (a structure it does not handle, or it did not
///                       converge, or a check failed: the reason), and the direct solution, refined until
///                       its control re-simulated by DOP853 meets the target (direct_replay.hpp), is
///                       reported; never called optimal (exit status 3);
///   "not_converged"     "not converged: <what failed>": neither (exit status 1); the report names the phase
///                       that failed and what to change, and the files keep the best solution found (the
///                       converged indirect one, else the last direct one Ipopt solved, else the last
///                       iterate).
#include <functional>
#include <string>

#include "poinsot/io/run/optimal_progress.hpp"
#include "poinsot/io/scenario/optimal_scenario.hpp"
#include "poinsot/optimal/direct_replay.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/interpretation.hpp"
#include "poinsot/optimal/verification.hpp"

namespace poinsot::io {

/// What a run ended with (see the file comment).
enum class OptimalOutcome { optimal, converged_direct, not_converged };

/// "optimal", "converged_direct" or "not_converged" (summary.json's "outcome").
const char* outcome_name(OptimalOutcome outcome);
/// The exit status of `poinsot optimize` for an outcome: 0, 3, 1 (2 is bad input, before any run).
int outcome_exit_code(OptimalOutcome outcome);

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
  OptimalOutcome outcome = OptimalOutcome::not_converged;
  /// "optimal (verified)", "converged (direct; minimum principle not verified: <reason>)" or
  /// "not converged: <what failed>"
  std::string status;
  /// Where the run is not optimal: the re-simulation of the direct optimum's control (direct_replay.hpp),
  /// after `direct_replay_refinements` continuations of the mesh refinement at ten times smaller mesh
  /// tolerances (each where the target was within reach of the remaining ones); `direct_replayed` false when
  /// no direct solution was solved by Ipopt.
  bool direct_replayed = false;
  optimal::DirectReplay direct_replay;
  double direct_replay_tolerance = optimal::direct_replay_tolerance;
  int direct_replay_refinements = 0;
  bool direct_refined_for_replay = false;  ///< `direct` is the refined one, and the direct optimum
  /// Not optimal: the phase that failed ("direct method", "indirect method", "verification") and what to
  /// change in the scenario; empty when optimal.
  std::string failed_phase;
  std::string advice;
};

/// The direct optimum the checks compare with: the phased re-solve's when it converged, else the mesh-refined
/// one.
const optimal::DirectSolution& direct_optimum(const OptimalRun& run);
/// "phased" or "mesh_refinement": which phase of the direct method produced direct_optimum(run).
const char* direct_optimum_source(const OptimalRun& run);

/// "indirect" or "direct": the solution the files and the arrays hold (the indirect one when it converged
/// and the outcome is not converged_direct; else direct_optimum(run)).
const char* solution_source(const OptimalRun& run);

/// Solves and checks; never throws for a solver failure (the status says it). `progress`, when given, is
/// called as the run goes (not part of the result).
OptimalRun run_optimal(const OptimalScenario& scenario,
                       const std::function<void(const OptimalProgress&)>& progress = {});

std::string optimal_report(const OptimalRun& run);
std::string optimal_summary_json(const OptimalRun& run);
/// Writes the five files into `dir` (created), each atomically.
void write_optimal_files(const OptimalRun& run, const std::string& dir);

}  // namespace poinsot::io
