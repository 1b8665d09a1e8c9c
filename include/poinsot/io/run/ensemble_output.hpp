#pragma once
/// @file ensemble_output.hpp
/// What an ensemble run writes (docs/ensemble.md): samples.csv (one row per sample) and summary.json
/// (statistics and percentiles of every output).
#include <string>

#include "poinsot/ensemble/runner.hpp"
#include "poinsot/io/scenario/ensemble_scenario.hpp"

namespace poinsot::io {

/// samples.csv: a header, then one row per sample: index, rejected, repaired, I1, I2, I3 (kg·m²),
/// misalignment (rad), omega0 (rad/s), every output (runner.hpp), the final quaternion (w, x, y, z) and ω
/// (rad/s); numbers in shortest round-trip form, NaN as "nan".
std::string ensemble_csv(const ensemble::EnsembleResult& result);

/// summary.json ("kind": "ensemble"): the run (scenario, method, path, samples, seed, threads, wall time,
/// body-steps/s), the validity counts, and per output its count, NaN count, mean, standard deviation, min,
/// max, the percentiles P1, P5, P50, P95, P99, P99.9 (exact from the rows, else from the quantile sketch) and
/// the fixed-edge histogram (edges, counts, underflow, overflow, where the edges come from).
std::string ensemble_summary_json(const EnsembleScenario& scenario, const ensemble::EnsembleOptions& options,
                                  const ensemble::EnsembleResult& result);

}  // namespace poinsot::io
