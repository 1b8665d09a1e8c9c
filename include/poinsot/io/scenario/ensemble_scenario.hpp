#pragma once
/// @file ensemble_scenario.hpp
/// Ensemble scenarios: a single-body scenario file (scenario.hpp) with an `[ensemble]` section giving the
/// number of samples, the seed and the dispersions (docs/ensemble.md). What an ensemble run writes is
/// io/run/ensemble_output.hpp.
#include <cstdint>
#include <memory>
#include <string>

#include "poinsot/ensemble/runner.hpp"
#include "poinsot/ensemble/sampler.hpp"
#include "poinsot/io/scenario/scenario.hpp"

namespace poinsot::io {

struct EnsembleScenario {
  Scenario base;  ///< the nominal body, state, torque, integrator and t_end
  ensemble::Nominal nominal;
  ensemble::Dispersions dispersions;
  std::uint64_t samples = 1000;
  std::uint64_t seed = 0;
  bool per_sample = true;  ///< keep every sample's row (samples.csv, exact percentiles)
  /// [ensemble.histogram]: `bins` and per output `NAME = [lo, hi]` (the output's unit); the other outputs'
  /// edges come from the pilot (runner.hpp).
  ensemble::HistogramSpec histograms;
  /// [ensemble.slew]: a planned control replayed in closed loop on every sample (slew_tracking.hpp;
  /// docs/ensemble.md "Slew robustness"), or null.
  std::shared_ptr<const ensemble::SlewTracking> slew;
};

/// Reads a scenario file with an `[ensemble]` section. Throws InvalidInput (one line, `FILE:LINE:COLUMN:`,
/// naming the key) on any problem: the scenario's own rules, an unknown key, a negative width, an unknown
/// law, a nominal body the sampler refuses.
EnsembleScenario load_ensemble_scenario(const std::string& path);
/// The same from text (`source` names it in messages).
EnsembleScenario parse_ensemble_scenario(std::string_view text, std::string_view source = "<string>",
                                         std::string_view base_dir = "");

/// The ensemble options of a scenario (samples, method, t_end, dt, tolerances).
ensemble::EnsembleOptions ensemble_options(const EnsembleScenario& scenario);

/// The single-body scenario of one sample (its body, initial state and torque; the base's method, step and
/// output), to run with run_scenario.
Scenario sample_scenario(const EnsembleScenario& scenario, const ensemble::Sample& sample);

}  // namespace poinsot::io
