// `poinsot optimize SCENARIO.toml`: the optimal reorientation of [optimal_control] (docs/optimal_control.md):
// prints the report (or with --json summary.json) and writes report.txt, trajectory.csv, control.csv,
// costates.csv and summary.json into the output folder, and with --plot the figures
// (python/poinsot/plot_optimal.py). Exit status 2 for bad input (nothing written), 1 when the solution is not
// verified optimal (the files are written and say "not converged"), 0 otherwise.
#include <cstdlib>
#include <memory>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/io/optimal_run.hpp"

namespace poinsot::cli {

namespace {

struct OptimizeOptions {
  std::string scenario, out;
  bool json = false, plot = false;
};

void optimize(const OptimizeOptions& o) {
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
      "Optimal reorientation ([optimal_control]): report, trajectory/control/costates CSV, summary.json");
  cmd->add_option("scenario", o->scenario, "the scenario (TOML, see docs/optimal_control.md)")->required();
  cmd->add_option("--out", o->out, "output folder (default: [output] dir, else SCENARIO-optimize)");
  cmd->add_flag("--json", o->json, "print summary.json on stdout instead of the report");
  cmd->add_flag("--plot", o->plot,
                "also draw torque.png, switching.png, omega.png, attitude_error.png and hamiltonian.png "
                "(Matplotlib) into the output folder");
  cmd->callback([o] { optimize(*o); });
}

}  // namespace poinsot::cli
