// `poinsot optimize SCENARIO.toml`: the optimal reorientation of [optimal_control] (docs/optimal_control.md):
// prints the report (or with --json summary.json) and writes report.txt, trajectory.csv, control.csv,
// costates.csv and summary.json into the output folder, and with --plot the figures
// (python/poinsot/plot_optimal.py). Exit status (io/run/optimal_run.hpp): 0 optimal (verified), 3 converged
// (direct; minimum principle not verified: ...), 1 not converged (the files are written and say which), 2 bad
// input (nothing written). While it runs, a progress line on stderr when stderr is a terminal (never in the
// files), unless --quiet. A multibody scenario with an [optimal_control] section
// (io/scenario/multibody_optimal_scenario.hpp) is solved by the multibody transcriptions (exit status 0 or
// 1), with the same progress line.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <memory>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/run/multibody_optimal_run.hpp"
#include "poinsot/io/run/optimal_run.hpp"
#include "poinsot/io/scenario/scenario_file.hpp"
#include "progress_line.hpp"
#include "sparse_solver_memory.hpp"

namespace poinsot::cli {

namespace {

struct OptimizeOptions {
  std::string scenario, out;
  bool json = false, plot = false, quiet = false;
};

/// One progress line on stderr, redrawn at most ten times a second after the first second, only when
/// stderr is a terminal: the phase and, in the direct method, the mesh and Ipopt's iteration; in the indirect
/// one, Newton's iteration and residual.
class OptimizeProgress {
 public:
  explicit OptimizeProgress(bool enabled) : line_(enabled) {}

  void update(const io::OptimalProgress& p) {
    const bool new_phase = p.phase != phase_;
    phase_ = p.phase;
    if (!line_.due(new_phase)) return;
    std::string what;
    if (p.phase == "direct")
      what = fmt::format(
          "direct method: mesh {} ({} intervals){}{}, Ipopt iteration {}, cost {:.6g}, "
          "infeasibility {:.1e}",
          p.direct.mesh_iteration, p.direct.intervals,
          p.direct.starts > 1 ? fmt::format(", start {} of {}", p.direct.start + 1, p.direct.starts)
                              : std::string(),
          p.direct.restart > 0 ? fmt::format(", restart {}", p.direct.restart) : std::string(),
          p.direct.nlp_iteration, p.direct.objective, p.direct.infeasibility);
    else if (p.phase == "phased")
      what = "direct method: the phase-per-arc re-solve";
    else if (p.phase == "indirect")
      what = p.newton_iteration == 0
                 ? std::string("indirect method: shooting (Newton)")
                 : fmt::format("indirect method: shooting, Newton iteration {}, residual {:.1e}",
                               p.newton_iteration, p.newton_residual);
    else if (p.phase == "verification")
      what = "verification: the necessary conditions and the DOP853 re-simulation";
    else
      what = "re-simulating the direct solution's control";
    line_.draw(fmt::format("{}  {:.1f} s", what, line_.elapsed()));
  }
  void finish() { line_.finish(); }

 private:
  ProgressLine line_;
  std::string phase_;
};

/// A multibody scenario (a `[[bodies]]` array): the direct transcription and its re-simulation
/// (io/run/multibody_optimal_run.hpp); no figures are drawn for it yet.
void optimize_multibody(const OptimizeOptions& o) {
  const io::MultibodyOptimalScenario sc = io::load_multibody_optimal_scenario(o.scenario);  // exit 2
  if (o.plot)
    throw InvalidInput("--plot: figures are drawn for single-body problems only; expected no --plot");
  const std::string dir = !o.out.empty() ? o.out : !sc.out_dir.empty() ? sc.out_dir : sc.name + "-optimize";
  OptimizeProgress progress(!o.quiet);
  const io::MultibodyOptimalRun run =
      io::run_multibody_optimal(sc, [&](const io::OptimalProgress& p) { progress.update(p); });
  progress.finish();
  io::write_multibody_optimal_files(run, dir);
  fmt::print("{}", o.json ? io::multibody_optimal_summary_json(run) : io::multibody_optimal_report(run));
  if (!run.optimal) std::exit(1);
}

void optimize(const OptimizeOptions& o) {
  keep_freed_memory_for_factorisations();
  if (io::is_multibody_scenario(o.scenario)) return optimize_multibody(o);
  const io::OptimalScenario sc = io::load_optimal_scenario(o.scenario);  // throws for bad input: exit 2
  const std::string dir = !o.out.empty() ? o.out : !sc.out_dir.empty() ? sc.out_dir : sc.name + "-optimize";
  OptimizeProgress progress(!o.quiet);
  const io::OptimalRun run = io::run_optimal(sc, [&](const io::OptimalProgress& p) { progress.update(p); });
  progress.finish();
  io::write_optimal_files(run, dir);
  fmt::print("{}", o.json ? io::optimal_summary_json(run) : io::optimal_report(run));
  if (o.plot) make_plots(dir, o.json);
  if (const int code = io::outcome_exit_code(run.outcome); code != 0) {
    std::fflush(stdout);
    std::exit(code);
  }
}

}  // namespace

void register_optimize(CLI::App& app) {
  auto o = std::make_shared<OptimizeOptions>();
  auto* cmd = app.add_subcommand(
      "optimize",
      "Optimal reorientation or multibody motion ([optimal_control]): report, trajectory/control CSV, "
      "summary.json");
  cmd->add_option("scenario", o->scenario, "the scenario (TOML, see docs/optimal_control.md)")->required();
  cmd->add_option("--out", o->out, "output folder (default: [output] dir, else SCENARIO-optimize)");
  cmd->add_flag("--json", o->json, "print summary.json on stdout instead of the report");
  cmd->add_flag("--quiet", o->quiet, "no progress line on the terminal");
  cmd->add_flag("--plot", o->plot,
                "also draw torque.png, switching.png, omega.png, attitude_error.png and hamiltonian.png "
                "(Matplotlib) into the output folder");
  cmd->callback([o] { optimize(*o); });
}

}  // namespace poinsot::cli
