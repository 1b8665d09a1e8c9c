// `poinsot optimize SCENARIO.toml`: the optimal reorientation of [optimal_control] (docs/optimal_control.md):
// prints the report (or with --json summary.json) and writes report.txt, trajectory.csv, control.csv,
// costates.csv and summary.json into the output folder, and with --plot the figures
// (python/poinsot/plot_optimal.py). Exit status 2 for bad input (nothing written), 1 when the solution is not
// verified optimal (the files are written and say "not converged"), 0 otherwise. A multibody scenario with an
// [optimal_control] section (io/multibody_optimal_scenario.hpp) is solved by the multibody transcriptions.
#include <cstdlib>
#include <memory>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/multibody_optimal_run.hpp"
#include "poinsot/io/optimal_run.hpp"
#include "poinsot/io/scenario_file.hpp"

namespace poinsot::cli {

namespace {

struct OptimizeOptions {
  std::string scenario, out;
  bool json = false, plot = false;
};

/// A multibody scenario (a `[[bodies]]` array): the direct transcription and its re-simulation
/// (io/multibody_optimal_run.hpp); no figures are drawn for it yet.
void optimize_multibody(const OptimizeOptions& o) {
  const io::MultibodyOptimalScenario sc = io::load_multibody_optimal_scenario(o.scenario);  // exit 2
  if (o.plot)
    throw InvalidInput("--plot: figures are drawn for single-body problems only; expected no --plot");
  const std::string dir = !o.out.empty() ? o.out : !sc.out_dir.empty() ? sc.out_dir : sc.name + "-optimize";
  const io::MultibodyOptimalRun run = io::run_multibody_optimal(sc);
  io::write_multibody_optimal_files(run, dir);
  fmt::print("{}", o.json ? io::multibody_optimal_summary_json(run) : io::multibody_optimal_report(run));
  if (!run.optimal) std::exit(1);
}

void optimize(const OptimizeOptions& o) {
  if (io::is_multibody_scenario(o.scenario)) return optimize_multibody(o);
  const io::OptimalScenario sc = io::load_optimal_scenario(o.scenario);  // throws for bad input: exit 2
  const std::string dir = !o.out.empty() ? o.out : !sc.out_dir.empty() ? sc.out_dir : sc.name + "-optimize";
  const io::OptimalRun run = io::run_optimal(sc);
  io::write_optimal_files(run, dir);
  fmt::print("{}", o.json ? io::optimal_summary_json(run) : io::optimal_report(run));
  if (o.plot) make_plots(dir, o.json);
  if (!run.optimal) std::exit(1);
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
  cmd->add_flag("--plot", o->plot,
                "also draw torque.png, switching.png, omega.png, attitude_error.png and hamiltonian.png "
                "(Matplotlib) into the output folder");
  cmd->callback([o] { optimize(*o); });
}

}  // namespace poinsot::cli
