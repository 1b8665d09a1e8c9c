#pragma once
/// @file runner.hpp
/// Runs an ensemble: draws the samples (sampler.hpp), advances them to t_end by the batched kernels (rk4,
/// dlm: batch.hpp), the closed form (exact: dynamics::ExactFreeBody, whose cost does not depend on t) or the
/// scalar integrators through dynamics::simulate (any other method, or a top under gravity), and computes
/// each sample's outputs on the fly:
///   first_flip_time       s, the first sign change of the intermediate-axis momentum (NaN: none; exact: NaN)
///   flip_interval         s, between the first two flips (exact: the closed form)
///   flip_interval_theory  s, 2K(k)/ω_p of the sample (free_body_theory.hpp; NaN with a torque or no flips)
///   attitude_error        rad, the angle between the sample's final attitude and the nominal sample's
///   energy_error          |E − E₀|/|E₀| at t_end (free body or gravity; NaN under other torques)
///   L_space_error         |L − L₀|/|L₀| at t_end (free body; NaN otherwise)
///   precession_rate       rad/s, heavy tops: the mean precession rate of the axis (pivot → centre of mass)
///                         about the vertical, measured by dynamics::AxisTracker on every step (NaN
///                         otherwise)
///   nutation_frequency    rad/s, heavy tops: 2π/T_nut from the minima of θ (NaN: fewer than two minima)
///   nutation_amplitude    rad, heavy tops: θ_max − θ_min of the axis's angle from the vertical
///   pointing_error, rate_error, peak_torque, peak_feedback_torque, peak_wheel_momentum, meets_requirement
///                         a slew replayed in closed loop (options.slew; slew_tracking.hpp defines them;
///                         NaN otherwise). A slew ensemble has no flips, energy or momentum outputs (NaN):
///                         its attitude_error is against the nominal sample's closed-loop final attitude.
///
/// Work is split into blocks of kBlockSamples consecutive samples; threads take whole blocks, and the
/// statistics of the blocks are merged in the fixed binary tree over the block indices (block_merge.hpp), so
/// the results are bit-identical for any number of threads, MPI ranks and with or without SIMD. Without
/// stored rows the outputs are also counted in quantile sketches (integer counts: the same for any threads or
/// ranks), for percentiles. Memory: the stored rows (when kept) plus O(threads · kBlockSamples), O(log
/// blocks) subtrees of block statistics, the sketches' buckets (bounded by the range of the values) and the
/// histograms' bins, independent of the number of samples otherwise. Every output is also counted in a
/// histogram with edges fixed before the counting starts (given, or from a pilot of the first samples: the
/// same on every thread and rank), integer counts merged exactly.
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "poinsot/dynamics/rk4.hpp"
#include "poinsot/ensemble/batch.hpp"
#include "poinsot/ensemble/block_merge.hpp"
#include "poinsot/ensemble/fixed_histogram.hpp"
#include "poinsot/ensemble/quantile_sketch.hpp"
#include "poinsot/ensemble/sampler.hpp"
#include "poinsot/ensemble/slew_tracking.hpp"
#include "poinsot/ensemble/statistics.hpp"

namespace poinsot::ensemble {

inline constexpr std::uint64_t kBlockSamples = 1024;

enum Output {
  first_flip_time,
  flip_interval,
  flip_interval_theory,
  attitude_error,
  energy_error,
  L_space_error,
  precession_rate,
  nutation_frequency,
  nutation_amplitude,
  pointing_error,
  rate_error,
  peak_torque,
  peak_feedback_torque,
  peak_wheel_momentum,
  meets_requirement,
  kOutputCount
};
/// The outputs' names, as in the CSV header and summary.json.
inline constexpr const char* kOutputNames[kOutputCount] = {
    "first_flip_time", "flip_interval",   "flip_interval_theory", "attitude_error",      "energy_error",
    "L_space_error",   "precession_rate", "nutation_frequency",   "nutation_amplitude",  "pointing_error",
    "rate_error",      "peak_torque",     "peak_feedback_torque", "peak_wheel_momentum", "meets_requirement"};
/// Their units.
inline constexpr const char* kOutputUnits[kOutputCount] = {
    "s", "s", "s", "rad", "", "", "rad/s", "rad/s", "rad", "rad", "rad/s", "N·m", "N·m", "N·m·s", ""};

/// One sample's inputs and outputs.
struct SampleRow {
  std::uint64_t index = 0;
  int rejected = 0;
  bool repaired = false;
  Vec3 moments = Vec3::Zero();  ///< kg·m²
  double misalignment = 0.0;    ///< rad
  Vec3 omega0 = Vec3::Zero();   ///< rad/s, body frame
  std::array<double, kOutputCount> out{};
  dynamics::State final_state;
};

/// The fixed-edge histograms of the outputs (fixed_histogram.hpp): the number of bins, and per output its
/// range, or none for the range of the pilot: the first min(samples, kBlockSamples) samples (pilot_range).
struct HistogramSpec {
  int bins = kHistogramBins;
  std::array<std::optional<HistogramRange>, kOutputCount> ranges{};
};

struct EnsembleOptions {
  std::uint64_t samples = 1000;
  std::string method{dynamics::Rk4Integrator::kName};
  double t_end = 10.0;  ///< s
  double dt = 1e-3;     ///< s, the nominal step (fixed-step methods; the first step of adaptive ones)
  /// s, > 0: the largest step of adaptive methods (default none; a heavy top's axis is still sampled every
  /// dt, from the dense output)
  double max_step = std::numeric_limits<double>::infinity();
  double rtol = 1e-10, atol = 1e-12;  ///< adaptive methods
  unsigned threads = 1;
  Simd simd = Simd::automatic;
  bool keep_rows = true;  ///< store every sample's row (percentiles, CSV); off: statistics only
  /// Polled between rounds of blocks; true stops after the complete rows so far.
  std::function<bool()> stop_requested;
  /// Called after each round with the samples completed.
  std::function<void(std::uint64_t done)> on_progress;
  HistogramSpec histograms;
  /// Refuse keep_rows when the rows would exceed this many bytes (0: half the physical memory).
  std::uint64_t max_row_bytes = 0;
  /// A planned slew replayed in closed loop on every sample (slew_tracking.hpp) instead of the free or
  /// constant-torque motion: its own RK4 grid replaces method, t_end and dt (the sample's torque must be
  /// none).
  std::shared_ptr<const SlewTracking> slew;
};

struct EnsembleResult {
  std::vector<SampleRow> rows;  ///< in index order (keep_rows)
  std::array<RunningStats, kOutputCount> stats;
  /// Percentiles without the rows (keep_rows off; empty sketches otherwise): quantile_sketch.hpp.
  std::array<QuantileSketch, kOutputCount> sketches;
  /// Every output's values over the fixed edges of options.histograms, rows kept or not (no edges: the
  /// output had no finite value in the pilot and no range was given).
  std::array<FixedHistogram, kOutputCount> histograms;
  std::uint64_t completed = 0;  ///< samples done (all, unless interrupted)
  bool interrupted = false;
  std::int64_t rejected = 0;    ///< redraws of the reject policy, all samples
  std::int64_t repaired = 0;    ///< samples moved onto the valid cone
  std::int64_t body_steps = 0;  ///< the steps the completed samples took (adaptive methods: accepted steps)
  double wall_time_s = 0.0;
  std::string path;   ///< "batched rk4 (AVX2)", "exact", "scalar dop853", ...
  SampleRow nominal;  ///< the undispersed sample
};

static_assert(kOutputCount == kOutputSlots, "block_merge.hpp holds one RunningStats per output");

/// The number of blocks of `samples` samples.
std::uint64_t block_count(std::uint64_t samples);
/// Sets the result's statistics and validity counts to the root of the block tree (block_merge.hpp) from the
/// complete subtrees `nodes` of a run of options.samples samples (of one or several run_ensemble_blocks):
/// the statistics of run_ensemble bit for bit, however the blocks were distributed (threads, MPI ranks).
void set_statistics(EnsembleResult& result, std::vector<BlockNode> nodes, std::uint64_t samples);

/// Bytes of the stored rows for `samples` samples.
std::uint64_t row_bytes(std::uint64_t samples);

/// Runs the ensemble. Throws InvalidInput for bad options (samples = 0, threads = 0, t_end or dt <= 0, an
/// unknown method, a slew with a torque or a pivot, `exact` with a torque or a pivot, stored rows that would
/// not fit in memory: refused before allocating, with the size), and the sampler's errors.
EnsembleResult run_ensemble(const Sampler& sampler, const EnsembleOptions& options);

/// Runs the blocks [first_block, last_block) of an ensemble of options.samples samples (rows of those samples
/// only; `completed` counts them; statistics of those blocks) and appends the complete subtrees of their
/// summaries (BlockTree, at most 2⌈log₂ blocks⌉ + 1) to `nodes` when not null: the share of one process of
/// a distributed run. Throws like run_ensemble, and for a block range outside the samples.
EnsembleResult run_ensemble_blocks(const Sampler& sampler, const EnsembleOptions& options,
                                   std::uint64_t first_block, std::uint64_t last_block,
                                   std::vector<BlockNode>* nodes);

/// One sample alone (the same row run_ensemble computes for it).
SampleRow run_sample(const Sampler& sampler, std::uint64_t index, const EnsembleOptions& options);

}  // namespace poinsot::ensemble
