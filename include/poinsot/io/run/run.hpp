#pragma once
/// @file run.hpp
/// Runs a scenario: builds the integrator, streams the samples of dynamics::simulate into trajectory.csv
/// (constant memory), measures the events (flips of the intermediate axis beside their closed-form interval;
/// precession and nutation of a top beside its theory) and writes summary.json atomically. The text report
/// is report.hpp; `poinsot run` (apps/poinsot/cmd_run.cpp) adds signals, the progress bar and the plots.

#include <functional>
#include <string>

#include "poinsot/core/types.hpp"
#include "poinsot/io/run/run_summary.hpp"
#include "poinsot/io/scenario/scenario.hpp"

namespace poinsot::io {

/// Symmetry of the principal moments (ascending), equal when they differ by less than `rel_tol` × trace:
/// "asymmetric", "prolate" (two equal moments larger than the third), "oblate" (two equal moments smaller
/// than the third), "spherical".
std::string symmetry_class(const Vec3& principal_moments, double rel_tol = 1e-9);

struct RunOptions {
  std::string out_dir;  ///< where trajectory.csv and summary.json go; empty: no files
  /// Polled at every sample; true stops the run (the summary then says interrupted).
  std::function<bool()> stop_requested;
  /// Called at every sample with its time (s), e.g. for a progress bar.
  std::function<void(double t)> on_sample;
};

/// Creates `dir` (with its parents) and checks that a file can be written in it, before anything is
/// simulated. Throws InvalidInput naming the folder and the system's reason.
void prepare_output_dir(const std::string& dir);

/// Runs the scenario. Bad input throws InvalidInput before anything is simulated. A ComputationFailed during
/// the run is recorded in `failure` (the files written so far stay complete, summary.json says so) and
/// re-thrown after the summary is written.
RunSummary run_scenario(const Scenario& scenario, const RunOptions& options);

}  // namespace poinsot::io
