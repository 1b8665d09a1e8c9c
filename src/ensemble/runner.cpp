#include "poinsot/ensemble/runner.hpp"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <mutex>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/axis_tracker.hpp"
#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/dynamics/exact_integrator.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/top_prediction.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::ensemble {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

enum class Path { batched, exact, scalar, slew };

struct Context {
  const Sampler& sampler;
  const EnsembleOptions& options;
  Path path;
  dynamics::State nominal_final;
};

/// 2K(k)/ω_p of a free sample (NaN when it has no flips).
double closed_form_flip_interval(const Sample& s) {
  const Vec3 w = s.axes.transpose() * s.initial.omega_body;
  int idx[3] = {0, 1, 2};
  std::sort(idx, idx + 3, [&](int a, int b) { return s.moments[a] < s.moments[b]; });
  const Vec3 I(s.moments[idx[0]], s.moments[idx[1]], s.moments[idx[2]]);
  const Vec3 wp(w[idx[0]], w[idx[1]], w[idx[2]]);
  const double f = dynamics::free_body_theory(I, wp).flip_interval();
  return f > 0.0 ? f : kNaN;
}

/// Total energy (J) and L_space (kg·m²/s) of a state.
std::pair<double, Vec3> invariants(const Sample& s, const Mat3& J, const dynamics::State& x) {
  const Vec3 Jw = J * x.omega_body;
  double E = 0.5 * x.omega_body.dot(Jw);
  if (s.torque == TorqueKind::gravity) E -= s.mass * s.torque_value.dot(x.R_space_body * s.pivot_to_com);
  return {E, x.R_space_body * Jw};
}

void fill_outputs(const Sample& s, const dynamics::State& final_state, double first, double second,
                  const Context& c, SampleRow& row, const dynamics::AxisTracker* top = nullptr) {
  row.index = s.index;
  row.rejected = s.rejected;
  row.repaired = s.repaired;
  row.moments = s.moments;
  row.misalignment = s.misalignment;
  row.omega0 = s.initial.omega_body;
  row.final_state = final_state;
  const bool free = s.torque == TorqueKind::none;
  // J about the rotation point: the centre of mass, or the pivot (parallel axes) for a top.
  const Mat3 J = s.has_pivot ? s.body().inertia() : s.inertia_com();
  const auto [E0, L0] = invariants(s, J, s.initial);
  const auto [E1, L1] = invariants(s, J, final_state);
  row.out[first_flip_time] = first;
  row.out[flip_interval] = c.path == Path::exact ? closed_form_flip_interval(s) : second - first;
  row.out[flip_interval_theory] = free ? closed_form_flip_interval(s) : kNaN;
  row.out[attitude_error] = so3::angle_between(final_state.R_space_body, c.nominal_final.R_space_body);
  row.out[energy_error] =
      (free || s.torque == TorqueKind::gravity) ? std::abs(E1 - E0) / std::max(std::abs(E0), 1e-300) : kNaN;
  row.out[L_space_error] = free && L0.norm() > 0.0 ? (L1 - L0).norm() / L0.norm() : kNaN;
  row.out[precession_rate] = top ? top->precession_rate_mean().value_or(kNaN) : kNaN;
  row.out[nutation_frequency] = top ? top->nutation_frequency().value_or(kNaN) : kNaN;
  row.out[nutation_amplitude] = top ? top->theta_max() - top->theta_min() : kNaN;
  for (int q = pointing_error; q <= meets_requirement; ++q)
    row.out[static_cast<std::size_t>(q)] = kNaN;
}

/// The outputs of a sample replayed in closed loop (slew_tracking.hpp).
void fill_slew_outputs(const Sample& s, const SlewOutcome& r, const Context& c, SampleRow& row) {
  fill_outputs(s, r.final_state, kNaN, kNaN, c, row);
  row.out[flip_interval_theory] = kNaN;
  row.out[energy_error] = kNaN;
  row.out[L_space_error] = kNaN;
  row.out[pointing_error] = r.pointing_error;
  row.out[rate_error] = r.rate_error;
  row.out[peak_torque] = r.peak_torque;
  row.out[peak_feedback_torque] = r.peak_feedback_torque;
  row.out[peak_wheel_momentum] = r.peak_wheel_momentum;
  row.out[meets_requirement] = r.meets_requirement ? 1.0 : 0.0;
}

/// The integrator options of the scalar path: the step, the largest step and the tolerances of `o`.
dynamics::IntegratorOptions integrator_options(const EnsembleOptions& o) {
  return {.dt = o.dt, .max_step = o.max_step, .rtol = o.rtol, .atol = o.atol};
}

/// Runs samples [first, first + count) into rows (count ≤ kBlockSamples) by the context's path; returns the
/// body steps they took (an adaptive method's accepted steps, each sample's own).
std::int64_t run_block(const Context& c, std::uint64_t first, std::uint64_t count, SampleRow* rows) {
  const EnsembleOptions& o = c.options;
  const auto samples = static_cast<std::int64_t>(count);
  if (c.path == Path::slew) {
    for (std::uint64_t i = 0; i < count; ++i) {
      const Sample s = c.sampler.draw(first + i);
      fill_slew_outputs(s, o.slew->run(s.inertia_com(), s.initial), c, rows[i]);
    }
    return samples * o.slew->step_count();
  }
  if (c.path == Path::batched) {
    std::vector<Sample> drawn;
    std::vector<LaneResult> lanes(kBatchLanes);
    for (std::uint64_t b = 0; b < count; b += kBatchLanes) {
      const std::uint64_t n = std::min<std::uint64_t>(kBatchLanes, count - b);
      drawn.clear();
      for (std::uint64_t i = 0; i < n; ++i)
        drawn.push_back(c.sampler.draw(first + b + i));
      run_batch(o.method, drawn, o.t_end, o.dt, o.simd, lanes);
      for (std::uint64_t i = 0; i < n; ++i)
        fill_outputs(drawn[i], lanes[i].final_state, lanes[i].first_flip, lanes[i].second_flip, c,
                     rows[b + i]);
    }
    return samples * batch_step_count(o.t_end, o.dt);
  }
  std::int64_t steps = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    const Sample s = c.sampler.draw(first + i);
    const dynamics::RigidBody body = s.body();
    if (c.path == Path::exact) {
      const dynamics::State x = dynamics::ExactFreeBody(body, s.initial).state_at(o.t_end);
      fill_outputs(s, x, kNaN, kNaN, c, rows[i]);
      continue;  // the closed form takes no steps
    }
    const auto torque = s.torque_model(body);
    auto integrator = dynamics::make_integrator(o.method, body, torque, integrator_options(o));
    // A heavy top's axis is sampled on every step (the tracker needs several samples per nutation period).
    std::optional<dynamics::AxisTracker> top;
    dynamics::Observer observer;
    if (dynamics::is_heavy_top(body, torque->is_gravity(), s.torque_value)) {
      top.emplace(s.pivot_to_com, -s.torque_value);
      observer = [&top](const dynamics::State& x) {
        top->add(x.time, x.R_space_body);
        return true;
      };
    }
    const dynamics::SimulationResult r = dynamics::simulate(
        body, torque, s.initial, *integrator,
        {.t_end = o.t_end, .sample_dt = top ? o.dt : o.t_end, .locate_flips = true}, observer);
    const auto& f = r.flip_times;
    fill_outputs(s, r.final_state, f.empty() ? kNaN : f[0], f.size() < 2 ? kNaN : f[1], c, rows[i],
                 top ? &*top : nullptr);
    steps += r.steps;
  }
  return steps;
}

Path choose_path(const Sampler& sampler, const EnsembleOptions& o) {
  const Sample nominal = sampler.nominal();
  if (o.slew) {
    if (nominal.torque != TorqueKind::none || nominal.has_pivot)
      throw InvalidInput(
          "ensemble: a slew replayed in closed loop with a torque or a pivot; expected a free body (the "
          "slew's control is its only torque)");
    return Path::slew;
  }
  if (o.method == dynamics::kExactMethodName) {
    if (nominal.torque != TorqueKind::none || nominal.has_pivot) {
      std::string with_torque;
      for (const dynamics::MethodInfo& m : dynamics::methods()) {
        if (!m.takes_torque) continue;
        if (!with_torque.empty()) with_torque += ", ";
        with_torque += m.name;
      }
      throw InvalidInput(fmt::format(
          "ensemble: method \"{}\" solves the torque-free body only; expected one of {} with a torque or a "
          "pivot",
          dynamics::kExactMethodName, with_torque));
    }
    return Path::exact;
  }
  return batchable(o.method, nominal) ? Path::batched : Path::scalar;
}

void validate(const EnsembleOptions& o) {
  if (o.samples == 0) throw InvalidInput("ensemble: samples = 0; expected at least 1");
  if (o.threads == 0) throw InvalidInput("ensemble: threads = 0; expected at least 1");
  require_positive("ensemble: t_end", o.t_end, "s");
  require_positive("ensemble: dt", o.dt, "s");
  // The histograms' bins and given ranges (FixedHistogram's checks).
  FixedHistogram(HistogramRange{0.0, 1.0}, o.histograms.bins);
  for (const auto& r : o.histograms.ranges)
    if (r) FixedHistogram(*r, o.histograms.bins);
  // Builds one integrator to validate the method's name (the registry's own message lists the methods).
  if (o.method != dynamics::kExactMethodName) {
    dynamics::make_integrator(o.method, dynamics::RigidBody::from_principal_moments(Vec3(1, 2, 3)), nullptr,
                              integrator_options(o));
  }
}

std::string path_name(Path p, const EnsembleOptions& o) {
  if (p == Path::exact) return "exact (closed form per sample)";
  if (p == Path::scalar) return "scalar " + o.method;
  if (p == Path::slew) return "closed-loop slew, scalar rk4";
  const bool avx2 = o.simd == Simd::automatic && simd_available();
  return fmt::format("batched {} ({}, {} lanes)", o.method, avx2 ? "AVX2" : "portable", kBatchLanes);
}

/// Per-sample rows of `range` samples must fit in o.max_row_bytes (default half the memory). Throws
/// InvalidInput.
void check_row_memory(const EnsembleOptions& o, std::uint64_t range) {
  const std::uint64_t limit = o.max_row_bytes > 0 ? o.max_row_bytes
                                                  : static_cast<std::uint64_t>(sysconf(_SC_PHYS_PAGES)) *
                                                        static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE)) / 2;
  if (range > limit / sizeof(SampleRow)) {
    throw InvalidInput(fmt::format(
        "ensemble: {} samples with per-sample output need {:.3g} GB, more than the {:.3g} GB allowed (half "
        "the memory); expected fewer samples or per-sample output off",
        range, static_cast<double>(row_bytes(range)) / 1e9, static_cast<double>(limit) / 1e9));
  }
}

/// One round of nb blocks on o.threads threads: the range's block b0 + k (its samples from first_sample +
/// (b0 + k)·kBlockSamples on, at most `range` in all) into rows_of(k), its statistics into block[k]. The
/// threads take the blocks in any order; a block's content depends on its index only. Rethrows the first
/// error.
template <class RowsOf>
void run_round(const Context& context, const EnsembleOptions& o, std::uint64_t first_sample,
               std::uint64_t first_block, std::uint64_t range, std::uint64_t b0, std::uint64_t nb,
               const RowsOf& rows_of, std::vector<BlockSummary>& block) {
  std::atomic<std::uint64_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto worker = [&] {
    for (std::uint64_t k; (k = next.fetch_add(1)) < nb;) {
      try {
        const std::uint64_t offset = (b0 + k) * kBlockSamples;  // within the range
        const std::uint64_t count = std::min(kBlockSamples, range - offset);
        SampleRow* rows = rows_of(k);
        const std::int64_t steps = run_block(context, first_sample + offset, count, rows);
        BlockSummary& b = block[k];
        b = BlockSummary{};
        b.index = first_block + b0 + k;
        b.body_steps = steps;
        for (std::uint64_t i = 0; i < count; ++i) {
          for (std::size_t q = 0; q < static_cast<std::size_t>(kOutputCount); ++q)
            b.stats[q].add(rows[i].out[q]);
          b.rejected += rows[i].rejected;
          b.repaired += rows[i].repaired ? 1 : 0;
        }
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
      }
    }
  };
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<std::uint64_t>(o.threads, nb); ++t)
    pool.emplace_back(worker);
  worker();
  for (auto& t : pool)
    t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace

std::uint64_t row_bytes(std::uint64_t samples) {
  return samples * sizeof(SampleRow);
}

SampleRow run_sample(const Sampler& sampler, std::uint64_t index, const EnsembleOptions& options) {
  EnsembleOptions one = options;
  one.samples = 1;
  validate(one);
  const Path path = choose_path(sampler, options);
  Context nominal_context{sampler, options, path, {}};
  // The nominal sample by the same path: a Sampler without dispersions draws it for every index.
  const Sampler undispersed(sampler.nominal_values(), Dispersions{}, sampler.seed());
  SampleRow nominal;
  run_block(Context{undispersed, options, path, {}}, 0, 1, &nominal);
  nominal_context.nominal_final = nominal.final_state;
  SampleRow row;
  run_block(nominal_context, index, 1, &row);
  return row;
}

void set_statistics(EnsembleResult& result, std::vector<BlockNode> nodes, std::uint64_t samples) {
  const BlockSummary root = merge_tree(std::move(nodes), block_count(samples));
  result.stats = root.stats;
  result.rejected = root.rejected;
  result.repaired = root.repaired;
  result.body_steps = root.body_steps;
}

std::uint64_t block_count(std::uint64_t samples) {
  return (samples + kBlockSamples - 1) / kBlockSamples;
}

EnsembleResult run_ensemble(const Sampler& sampler, const EnsembleOptions& o) {
  return run_ensemble_blocks(sampler, o, 0, block_count(o.samples), nullptr);
}

EnsembleResult run_ensemble_blocks(const Sampler& sampler, const EnsembleOptions& o,
                                   std::uint64_t first_block, std::uint64_t last_block,
                                   std::vector<BlockNode>* nodes_out) {
  validate(o);
  if (!(first_block <= last_block && last_block <= block_count(o.samples))) {
    throw InvalidInput(fmt::format("ensemble: blocks [{}, {}) of {}; expected a range within the samples",
                                   first_block, last_block, block_count(o.samples)));
  }
  const std::uint64_t first_sample = first_block * kBlockSamples;
  const std::uint64_t end_sample = std::min(o.samples, last_block * kBlockSamples);
  const std::uint64_t range = end_sample - first_sample;
  const auto start = std::chrono::steady_clock::now();
  if (o.keep_rows) check_row_memory(o, range);
  const Path path = choose_path(sampler, o);
  EnsembleResult result;
  result.path = path_name(path, o);
  {
    const Sampler undispersed(sampler.nominal_values(), Dispersions{}, sampler.seed());
    run_block(Context{undispersed, o, path, {}}, 0, 1, &result.nominal);
    result.nominal.out[attitude_error] = 0.0;  // against itself, by definition
  }
  const Context context{sampler, o, path, result.nominal.final_state};

  // The histograms' edges, fixed before any value is counted: given, or from the pilot, samples [0,
  // pilot_count). The process that runs block 0 takes the pilot's rows from its first round; another runs
  // the pilot alone (one block), so that every process derives the same edges.
  const std::uint64_t pilot_count = std::min(o.samples, kBlockSamples);
  const auto set_histograms = [&](const SampleRow* pilot) {
    std::vector<double> v(pilot ? pilot_count : 0);
    for (std::size_t q = 0; q < static_cast<std::size_t>(kOutputCount); ++q) {
      for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = pilot[i].out[q];
      const std::optional<HistogramRange> edges =
          o.histograms.ranges[q] ? o.histograms.ranges[q] : pilot_range(v);
      if (edges) result.histograms[q] = FixedHistogram(*edges, o.histograms.bins);
    }
  };
  const bool needs_pilot = std::any_of(o.histograms.ranges.begin(), o.histograms.ranges.end(),
                                       [](const auto& r) { return !r.has_value(); });
  bool histograms_set = !needs_pilot || first_block > 0 || range == 0;
  if (!needs_pilot) {
    set_histograms(nullptr);
  } else if (histograms_set) {
    std::vector<SampleRow> pilot(pilot_count);
    run_block(context, 0, pilot_count, pilot.data());
    set_histograms(pilot.data());
  }

  const std::uint64_t blocks = last_block - first_block;
  const std::uint64_t per_round = 4 * static_cast<std::uint64_t>(o.threads);
  std::vector<std::vector<SampleRow>> scratch(o.keep_rows ? 0 : per_round,
                                              std::vector<SampleRow>(kBlockSamples));
  std::vector<BlockSummary> block(per_round);
  BlockTree tree;  // the blocks' statistics, merged in the fixed tree as they complete

  for (std::uint64_t round = 0; round * per_round < blocks; ++round) {
    const std::uint64_t b0 = round * per_round;
    const std::uint64_t nb = std::min(per_round, blocks - b0);
    // The rows grow round by round (amortised doubling), so an interrupted run never touched the rest.
    if (o.keep_rows) result.rows.resize(std::min(range, (b0 + nb) * kBlockSamples));
    const auto block_rows = [&](std::uint64_t k) {
      return o.keep_rows ? result.rows.data() + (b0 + k) * kBlockSamples : scratch[k].data();
    };
    run_round(context, o, first_sample, first_block, range, b0, nb, block_rows, block);
    if (!histograms_set) {  // block 0 is the pilot, run in this first round
      set_histograms(block_rows(0));
      histograms_set = true;
    }
    for (std::uint64_t k = 0; k < nb; ++k) {  // pushed in block order: independent of the threads
      tree.push(block[k]);
      const std::uint64_t count = std::min(kBlockSamples, range - (b0 + k) * kBlockSamples);
      const SampleRow* rows = block_rows(k);
      for (std::uint64_t i = 0; i < count; ++i) {
        for (std::size_t q = 0; q < static_cast<std::size_t>(kOutputCount); ++q) {
          result.histograms[q].add(rows[i].out[q]);
          if (!o.keep_rows) result.sketches[q].add(rows[i].out[q]);
        }
      }
    }
    result.completed = std::min(range, (b0 + nb) * kBlockSamples);
    if (o.on_progress) o.on_progress(result.completed);
    if (result.completed < range && o.stop_requested && o.stop_requested()) {
      result.interrupted = true;
      break;
    }
  }
  if (o.keep_rows) result.rows.resize(result.completed);
  set_statistics(result, tree.nodes(), o.samples);
  if (nodes_out) nodes_out->insert(nodes_out->end(), tree.nodes().begin(), tree.nodes().end());
  result.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace poinsot::ensemble
