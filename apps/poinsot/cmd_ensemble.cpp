// poinsot ensemble SCENARIO.toml [--samples N] [--threads T] [--out DIR] [--json] [--sample K] [--no-simd]
// [--no-per-sample] [--per-rank-files]: Monte Carlo over the dispersions of the scenario's [ensemble] section
// (docs/ensemble.md). Writes DIR/samples.csv (per-sample output on) and DIR/summary.json atomically; --sample
// K instead runs sample K alone through the single-body run (DIR/sample_K/trajectory.csv and summary.json).
// Ctrl-C stops after the complete rows so far, which are written and marked "interrupted"; the exit status is
// then 130.
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <system_error>
#include <thread>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "ensemble_hdf5.hpp"
#include "ensemble_mpi.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/run/ensemble_output.hpp"
#include "poinsot/io/run/run.hpp"
#include "poinsot/io/run/summary.hpp"

namespace poinsot::cli {
namespace {

volatile std::sig_atomic_t g_interrupted = 0;
extern "C" void on_interrupt(int) {
  g_interrupted = 1;
}

// samples.csv is written for runs up to this many rows (about 300 bytes a row); samples.h5 for any size.
constexpr std::size_t kCsvRows = 1000000;

struct EnsembleCliOptions {
  std::string scenario, out;
  std::uint64_t samples = 0;
  unsigned threads = 0;
  long long sample = -1;
  bool json = false, plot = false, no_simd = false, no_per_sample = false, per_rank_files = false,
       quiet = false;
};

void run_ensemble_command(const EnsembleCliOptions& c) {
  const MpiSession mpi;  // MPI_Init under mpirun (when built with MPI), nothing otherwise
  io::EnsembleScenario sc = io::load_ensemble_scenario(c.scenario);
  ensemble::EnsembleOptions o = io::ensemble_options(sc);
  if (c.samples > 0) o.samples = c.samples;
  o.threads = c.threads > 0 ? c.threads : std::max(1u, std::thread::hardware_concurrency());
  if (c.no_simd) o.simd = ensemble::Simd::off;
  if (c.no_per_sample) o.keep_rows = false;
  const std::string dir = !c.out.empty()             ? c.out
                          : !sc.base.out_dir.empty() ? sc.base.out_dir
                                                     : sc.base.name + "_ensemble";
  const ensemble::Sampler sampler(sc.nominal, sc.dispersions, sc.seed);

  if (c.sample >= 0) {
    if (o.slew)
      throw InvalidInput(
          "ensemble: --sample runs one sample through the single-body run, which does not replay "
          "[ensemble.slew]; expected no --sample with a slew (samples.csv has every sample's row)");
    const ensemble::Sample s = sampler.draw(static_cast<std::uint64_t>(c.sample));
    const std::string sample_dir = fmt::format("{}/sample_{}", dir, c.sample);
    io::prepare_output_dir(sample_dir);
    io::RunOptions ro;
    ro.out_dir = sample_dir;
    const io::RunSummary r = io::run_scenario(io::sample_scenario(sc, s), ro);
    if (!c.json) fmt::print("sample {}: trajectory in {}\n", c.sample, r.trajectory_file);
    if (c.json) fmt::print("{}", io::summary_json(r));
    return;
  }

  const bool root = mpi.rank() == 0;
  // Per-rank files: each rank writes its own rows, in parallel, instead of gathering them on rank 0.
  const bool per_rank = c.per_rank_files && mpi.size() > 1 && o.keep_rows;
  if (per_rank && c.plot) {
    throw InvalidInput(
        "ensemble: --plot reads samples.csv, which --per-rank-files does not write; expected one of them");
  }
  const bool dir_existed = std::filesystem::exists(dir);
  if (root) io::prepare_output_dir(dir);  // before anything is simulated
  g_interrupted = 0;
  struct sigaction sa {
  }, old_int{};
  sa.sa_handler = on_interrupt;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESETHAND;
  sigaction(SIGINT, &sa, &old_int);
  o.stop_requested = [] { return g_interrupted != 0; };
  const bool tty = root && isatty(STDERR_FILENO) == 1 && !c.json && !c.quiet;
  const auto start = std::chrono::steady_clock::now();
  o.on_progress = [&](std::uint64_t done) {
    if (!tty) return;
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double rate = s > 0 ? static_cast<double>(done) / s : 0.0;
    fmt::print(stderr, "\r{} / {} samples  {:.3g} samples/s  ETA {:.0f} s   ", done, o.samples, rate,
               rate > 0 ? static_cast<double>(o.samples - done) / rate : 0.0);
  };
  ensemble::EnsembleResult r;
  ensemble::EnsembleResult own;  // this rank's rows (per-rank files)
  try {
    r = mpi.size() > 1 ? run_ensemble_mpi(mpi, sampler, o, per_rank ? &own.rows : nullptr)
                       : ensemble::run_ensemble(sampler, o);
  } catch (...) {
    sigaction(SIGINT, &old_int, nullptr);
    std::error_code ignored;  // bad input found while sampling: leave no empty folder behind
    if (root && !dir_existed) std::filesystem::remove(dir, ignored);
    throw;
  }
  sigaction(SIGINT, &old_int, nullptr);
  if (tty) fmt::print(stderr, "\r\033[K");
  std::string written;
  if (per_rank) {  // every rank its own index range, in parallel
    const std::string stem = fmt::format("{}/samples.rank_{}", dir, mpi.rank());
    if (own.rows.size() <= kCsvRows) io::write_file_atomic(stem + ".csv", io::ensemble_csv(own));
    if (hdf5_available()) write_ensemble_hdf5(stem + ".h5", own);
    written += fmt::format("{}/samples.rank_*.{} ({} ranks), ", dir, hdf5_available() ? "csv|h5" : "csv",
                           mpi.size());
  }
  if (!root) return;  // rank 0 writes the summary and reports for all ranks
  if (o.keep_rows && !per_rank && r.rows.size() <= kCsvRows) {
    io::write_file_atomic(dir + "/samples.csv", io::ensemble_csv(r));
    written += dir + "/samples.csv, ";
  }
  if (o.keep_rows && !per_rank && hdf5_available()) {
    write_ensemble_hdf5(dir + "/samples.h5", r);
    written += dir + "/samples.h5, ";
  }
  const std::string summary = io::ensemble_summary_json(sc, o, r);
  io::write_file_atomic(dir + "/summary.json", summary);
  if (c.json) {
    fmt::print("{}", summary);
  } else {
    fmt::print("{}: {} of {} samples by {} in {:.3g} s ({:.3g} body-steps/s)\n", sc.base.name, r.completed,
               o.samples, r.path, r.wall_time_s,
               r.wall_time_s > 0 ? static_cast<double>(r.body_steps) / r.wall_time_s : 0.0);
    fmt::print("validity ({}): {} rejected draws, {} repaired samples\n",
               ensemble::to_string(sc.dispersions.policy), r.rejected, r.repaired);
    for (int q = 0; q < ensemble::kOutputCount; ++q) {
      const auto& s = r.stats[static_cast<std::size_t>(q)];
      if (s.count == 0) continue;
      fmt::print("  {:<22} mean {:<12.6g} std {:<12.6g} min {:<12.6g} max {:<12.6g} {}\n",
                 ensemble::kOutputNames[q], s.mean, std::sqrt(s.variance()), s.min, s.max,
                 ensemble::kOutputUnits[q]);
    }
    if (o.slew) {
      const auto& m = r.stats[ensemble::meets_requirement];
      fmt::print("slew: {} of {} samples within the pointing requirement {:.6g} rad ({:.4g} %)\n",
                 static_cast<long long>(std::llround(m.mean * static_cast<double>(m.count))), m.count,
                 o.slew->spec().pointing_requirement, 100.0 * m.mean);
    }
    fmt::print("written: {}{}/summary.json\n", written, dir);
  }
  if (c.plot) make_plots(dir, c.json);
  if (r.interrupted) {
    fmt::print(stderr, "poinsot: interrupted: {} complete samples of {} written\n", r.completed, o.samples);
    std::exit(130);
  }
}

}  // namespace

void register_ensemble(CLI::App& app) {
  auto opts = std::make_shared<EnsembleCliOptions>();
  CLI::App* cmd = app.add_subcommand("ensemble", "Monte Carlo over the [ensemble] dispersions of a scenario");
  cmd->add_option("scenario", opts->scenario, "scenario file (TOML) with an [ensemble] section")->required();
  cmd->add_option("--samples", opts->samples, "number of samples (overrides [ensemble] samples)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--threads", opts->threads, "threads (default: all cores)")->check(CLI::PositiveNumber);
  cmd->add_option("--out", opts->out, "output folder");
  cmd->add_flag("--json", opts->json, "print summary.json on stdout");
  cmd->add_flag("--quiet", opts->quiet, "no progress line");
  cmd->add_flag(
      "--plot", opts->plot,
      "also draw histograms.png, cdf.png and scatter.png (Matplotlib; without per-sample output only "
      "histograms.png, from summary.json's histograms)");
  cmd->add_option("--sample", opts->sample,
                  "run sample K alone through the single-body run (full trajectory)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_flag("--no-simd", opts->no_simd, "use the portable loops of the batched kernels (same results)");
  cmd->add_flag("--no-per-sample", opts->no_per_sample,
                "statistics only (memory independent of the samples)");
  cmd->add_flag("--per-rank-files", opts->per_rank_files,
                "under mpirun: each rank writes its own rows to samples.rank_R.csv (and .h5) in parallel, "
                "rows not gathered; percentiles from quantile sketches");
  cmd->callback([opts] { run_ensemble_command(*opts); });
}

}  // namespace poinsot::cli
