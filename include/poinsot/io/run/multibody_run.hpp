#pragma once
/// @file multibody_run.hpp
/// Runs a multibody scenario (multibody/scenario.hpp) into its files and its summary: the multibody half of
/// `poinsot run` and of Python's `poinsot.multibody.run_scenario`. The loop is multibody::simulate; this
/// file serialises what it hands over.
///
/// Files (into RunOptions::out_dir; the layouts in docs/multibody.md, "Output files"):
///   trajectory.csv   t, then per body NAME.x NAME.y NAME.z (centre of mass, m), NAME.qw .qx .qy .qz (the
///                    rotation body → space), NAME.vx .vy .vz (m/s), NAME.wx .wy .wz (ω, body frame, rad/s);
///                    one row at t₀, every `output_every` steps and at the last step, streamed in whole rows
///   diagnostics.csv  at the same rows: t (s), energy E = T + V, energy_error E − E(0), kinetic T,
///                    potential V (J), linear_momentum |Σ m v| (kg·m/s), L_space_x/y/z about the origin
///                    (kg·m²/s), joint_gap (m), joint_angle, orthogonality max |RᵀR − I| (dimensionless)
///   reactions.csv    at the final time, per joint: the reaction force (N) and couple (N·m) on body a, at
///                    the joint point, space frame (multibody/multipliers.hpp)
///   multipliers.csv  at the final time, per body: the centre of mass (m) and Λ (J, body frame, row by row)
///   report.txt       format_multibody_report
///   summary.json     multibody_summary_json, written atomically (also after an interruption or a failure)
///
/// A stop request (RunOptions::stop_requested, polled at every row) ends the run at that row: every file is
/// complete and summary.json says "interrupted". A ComputationFailed ends it too: the files hold what was
/// computed, summary.json says "failed", and the exception is re-thrown.

#include <optional>
#include <string>

#include "poinsot/io/run/run.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::io {

/// RunOptions, with the two streamed CSV files optionally elsewhere than out_dir.
struct MultibodyRunOptions : RunOptions {
  std::string trajectory_csv;   ///< non-empty: the trajectory goes there (with or without out_dir)
  std::string diagnostics_csv;  ///< non-empty: the diagnostics go there (with or without out_dir)
};

/// Everything a multibody run produced, for the report and summary.json.
struct MultibodyRunSummary {
  std::string scenario;       ///< the scenario's name: its file's stem, else "multibody"
  multibody::RunSummary run;  ///< the loop's measurements and the final state
  long long rows = 0;         ///< trajectory rows (t₀, every output_every steps, the last step)
  /// The exact multipliers at the final state (reactions and each body's Λ); none after a failure.
  std::optional<multibody::ExactMultipliers> final_multipliers;
  std::string out_dir;  ///< empty: no run folder
  std::string trajectory_file, diagnostics_file, reactions_file, multipliers_file, report_file, summary_file;
};

/// Runs the scenario into the files of `options` (see the file comment): every file of the run folder
/// `out_dir` (none when empty), the trajectory and diagnostics CSV at `trajectory_csv` and `diagnostics_csv`
/// when given (with or without a folder). Bad input (an inconsistent scenario, an unwritable folder or file)
/// throws InvalidInput before the first step; a failed step throws ComputationFailed after summary.json is
/// written. From Python: `run_scenario(scenario, trajectory_csv="", report=None, diagnostics_csv="",
/// out_dir="")` returns the multibody::RunSummary and writes the report text to `report` (e.g. sys.stdout).
MultibodyRunSummary run_multibody_scenario(const multibody::Scenario& scenario,
                                           const MultibodyRunOptions& options);

/// The text report: the system, the run, the conserved quantities and the constraints over the run, the
/// joint reactions and each body's Λ at the end (for more than 5 joints or bodies the 5 largest, the full
/// tables being reactions.csv and multipliers.csv), the cost and the files. SI units on every line.
std::string format_multibody_report(const multibody::Scenario& scenario, const MultibodyRunSummary& summary);

/// summary.json of a multibody run (pretty-printed, keys in docs/multibody.md, "Output files").
std::string multibody_summary_json(const multibody::Scenario& scenario, const MultibodyRunSummary& summary);

}  // namespace poinsot::io
