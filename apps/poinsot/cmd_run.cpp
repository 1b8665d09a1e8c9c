// `poinsot run SCENARIO.toml`: runs a scenario file, prints its report (or with --json its summary), writes
// trajectory.csv and summary.json into the output folder, and with --plot the figures (Matplotlib, through
// python/poinsot/plot.py). Ctrl-C or SIGTERM stops the run cleanly: the files stay complete and
// summary.json says "interrupted"; the exit status is then 128 + the signal's number. See docs/run.md.
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/io/run/multibody_run.hpp"
#include "poinsot/io/run/report.hpp"
#include "poinsot/io/run/run.hpp"
#include "poinsot/io/run/summary.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/io/scenario/scenario_file.hpp"
#include "poinsot/io/view/view_page.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "progress_line.hpp"

extern char** environ;

#ifndef POINSOT_PYTHON_DIR
#define POINSOT_PYTHON_DIR ""
#endif
#ifndef POINSOT_PYTHON_SOURCE_DIR
#define POINSOT_PYTHON_SOURCE_DIR ""
#endif
#ifndef POINSOT_PYTHON_INSTALL_REL  // the installed package, relative to the installed tool's folder
#define POINSOT_PYTHON_INSTALL_REL ""
#endif
#ifndef POINSOT_PYTHON_EXECUTABLE
#define POINSOT_PYTHON_EXECUTABLE "/usr/bin/python3"
#endif

namespace poinsot::cli {
namespace {

volatile std::sig_atomic_t g_signal = 0;

extern "C" void on_signal(int sig) {
  g_signal = sig;
}

/// Installs the SIGINT/SIGTERM handlers for the duration of a run; a second signal kills as usual
/// (SA_RESETHAND), the rows written so far being complete.
class SignalGuard {
 public:
  SignalGuard() {
    g_signal = 0;
    struct sigaction sa {};
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESETHAND;
    sigaction(SIGINT, &sa, &old_int_);
    sigaction(SIGTERM, &sa, &old_term_);
  }
  ~SignalGuard() {
    sigaction(SIGINT, &old_int_, nullptr);
    sigaction(SIGTERM, &old_term_, nullptr);
  }
  SignalGuard(const SignalGuard&) = delete;
  SignalGuard& operator=(const SignalGuard&) = delete;

 private:
  struct sigaction old_int_ {};
  struct sigaction old_term_ {};
};

/// A one-line progress bar of the simulated time (progress_line.hpp).
class Progress {
 public:
  Progress(bool enabled, double t_end) : line_(enabled), t_end_(t_end) {}
  void update(double t) {
    if (!line_.due()) return;
    const double f = t_end_ > 0.0 ? std::min(1.0, t / t_end_) : 1.0;
    const int width = 30;
    const int done = static_cast<int>(f * width);
    line_.draw(fmt::format("[{}{}] {:5.1f}%  t = {:.4g} / {:.4g} s  {:.1f} s elapsed",
                           std::string(static_cast<std::size_t>(done), '#'),
                           std::string(static_cast<std::size_t>(width - done), '.'), 100.0 * f, t, t_end_,
                           line_.elapsed()));
  }
  void finish() { line_.finish(); }

 private:
  ProgressLine line_;
  double t_end_;
};

struct RunCliOptions {
  std::string scenario;
  std::string out;
  bool json = false, plot = false, quiet = false, html = false;
  io::ViewOptions view;  ///< --html: view.html's options
  std::string method;
  double dt = 0.0, t_end = 0.0, sample_dt = 0.0;
  CLI::Option* dt_opt = nullptr;
  CLI::Option* t_end_opt = nullptr;
  CLI::Option* sample_dt_opt = nullptr;
};

std::string env_or(const char* name, const char* fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && *v != '\0' ? std::string(v) : std::string(fallback);
}

}  // namespace

/// Runs python/poinsot/plot.py on the run folder, with PYTHONPATH pointing at the build's python folder
/// (POINSOT_PYTHON_DIR, overridden by the environment variable of the same name), or, for an installed tool
/// whose build folder is gone, at the package installed beside it (<bindir>/POINSOT_PYTHON_INSTALL_REL). Its
/// output goes to stderr when stdout carries JSON.
void make_plots(const std::string& dir, bool stdout_is_json) {
  namespace fs = std::filesystem;
  const std::string python = env_or("POINSOT_PYTHON", POINSOT_PYTHON_EXECUTABLE);
  std::string pydir = env_or("POINSOT_PYTHON_DIR", POINSOT_PYTHON_DIR);
  std::string script = (fs::path(pydir) / "poinsot" / "plot.py").string();
  if (!fs::exists(script)) script = (fs::path(POINSOT_PYTHON_SOURCE_DIR) / "poinsot" / "plot.py").string();
  std::error_code ec;
  const fs::path self = fs::read_symlink("/proc/self/exe", ec);
  const fs::path installed = (self.parent_path() / POINSOT_PYTHON_INSTALL_REL).lexically_normal();
  if (!fs::exists(script) && !ec && *POINSOT_PYTHON_INSTALL_REL != '\0' &&
      fs::exists(installed / "poinsot" / "plot.py")) {
    pydir = installed.string();
    script = (installed / "poinsot" / "plot.py").string();
  }
  if (!fs::exists(script)) {
    throw ComputationFailed(
        fmt::format("plot: cannot find poinsot/plot.py under \"{}\"; set POINSOT_PYTHON_DIR "
                    "to the build's python folder",
                    pydir));
  }
  const char* old = std::getenv("PYTHONPATH");
  const std::string path = old != nullptr && *old != '\0' ? pydir + ":" + old : pydir;
  setenv("PYTHONPATH", path.c_str(), 1);
  setenv("MPLBACKEND", "Agg", 0);
  std::vector<std::string> args = {python, script, dir};
  std::vector<char*> argv;
  for (auto& a : args)
    argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  if (stdout_is_json) posix_spawn_file_actions_adddup2(&actions, STDERR_FILENO, STDOUT_FILENO);
  std::fflush(stdout);
  pid_t pid = 0;
  const int rc = posix_spawn(&pid, python.c_str(), &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (rc != 0) {
    throw ComputationFailed(
        fmt::format("plot: cannot start \"{}\": {}; expected a Python 3 with Matplotlib "
                    "(set POINSOT_PYTHON)",
                    python, std::strerror(rc)));
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
    throw ComputationFailed(fmt::format("plot: \"{} {} {}\" failed (status {}); the run's files are complete",
                                        python, script, dir, WIFEXITED(status) ? WEXITSTATUS(status) : -1));
  }
}

namespace {

/// Runs `run(options)` with the progress bar and the SIGINT/SIGTERM handlers: a signal makes
/// options.stop_requested true, and the run stops at its next sample (io/run/run.hpp,
/// io/run/multibody_run.hpp).
template <class Options, class Run>
auto run_guarded(const RunCliOptions& o, double t_end, Options& options, Run&& run) {
  Progress progress(!o.quiet, t_end);
  options.stop_requested = [] { return g_signal != 0; };
  options.on_sample = [&progress](double t) { progress.update(t); };
  SignalGuard guard;
  try {
    auto summary = run(options);
    progress.finish();
    return summary;
  } catch (...) {
    progress.finish();
    throw;
  }
}

/// Prints what io/ produced (summary.json with --json, else the report); after a signal, says so and exits
/// with 128 + the signal's number; else draws the plots with --plot.
void finish(const RunCliOptions& o, const std::string& dir, const std::string& json,
            const std::string& report, double t_final) {
  fmt::print("{}", o.json ? json : report);
  std::fflush(stdout);
  if (g_signal != 0) {
    fmt::print(stderr, "poinsot: interrupted by signal {} at t = {} s; the files are complete up to there\n",
               static_cast<int>(g_signal), t_final);
    std::fflush(stderr);
    std::exit(128 + g_signal);
  }
  if (o.plot) make_plots(dir, o.json);
  if (o.html) io::write_view_page(dir, o.view);
}

/// A multibody scenario (a `[[bodies]]` array, docs/multibody.md): RATTLE or the projected RK4 on the
/// constrained system, its files (io/run/multibody_run.hpp) and with --plot the figures paths.png, energy.png
/// and constraints.png.
void run_multibody(const RunCliOptions& o, const io::ScenarioOverrides& ov, multibody::Scenario mb) {
  io::apply_overrides(mb, ov);
  io::MultibodyRunOptions ro;
  ro.out_dir = o.out.empty() ? std::filesystem::path(o.scenario).stem().string() + "-run" : o.out;
  const io::MultibodyRunSummary s = run_guarded(o, mb.duration, ro, [&](const io::MultibodyRunOptions& r) {
    return io::run_multibody_scenario(mb, r);
  });
  finish(o, ro.out_dir, io::multibody_summary_json(mb, s), io::format_multibody_report(mb, s),
         s.run.final_state.time);
}

void run(RunCliOptions& o) {
  o.view.scenario_path = o.scenario;
  if (o.html) io::check_view_options(o.view);
  io::ScenarioOverrides ov;
  ov.method = o.method;
  if (o.dt_opt->count() > 0) ov.dt = o.dt;
  if (o.t_end_opt->count() > 0) ov.t_end = o.t_end;
  if (o.sample_dt_opt->count() > 0) ov.sample_dt = o.sample_dt;
  ov.out_dir = o.out;
  io::AnyScenario any = io::load_any_scenario(o.scenario);  // the file is parsed once, either kind
  if (auto* mb = std::get_if<multibody::Scenario>(&any)) {
    run_multibody(o, ov, std::move(*mb));
    return;
  }
  io::Scenario& sc = std::get<io::Scenario>(any);
  io::apply_overrides(sc, ov);
  io::RunOptions ro;
  ro.out_dir = sc.out_dir.empty() ? sc.name + "-run" : sc.out_dir;
  io::prepare_output_dir(ro.out_dir);  // before anything is simulated
  const io::RunSummary s = run_guarded(o, sc.simulation.t_end, ro,
                                       [&](const io::RunOptions& r) { return io::run_scenario(sc, r); });
  finish(o, ro.out_dir, io::summary_json(s), io::format_report(s), s.result.final_state.time);
}

}  // namespace

void register_run(CLI::App& app) {
  auto o = std::make_shared<RunCliOptions>();
  auto* cmd = app.add_subcommand("run", "Run a scenario file: report, trajectory.csv, summary.json, plots");
  cmd->add_option("scenario", o->scenario,
                  "the scenario (TOML, see docs/scenario.md), or a robot file (.urdf, .xml, .sdf: "
                  "docs/robot_models.md)")
      ->required();
  cmd->add_option("--out", o->out, "output folder (default: [output] dir, else SCENARIO-run)");
  cmd->add_flag("--json", o->json, "print summary.json on stdout instead of the report");
  cmd->add_flag("--plot", o->plot, "also draw the figures (PNG, Matplotlib) into the output folder");
  cmd->add_flag("--quiet", o->quiet, "no progress bar");
  auto* html = cmd->add_flag("--html", o->html, "also write view.html, the run's 3-D page (docs/viewer.md)");
  cmd->add_option("--frames", o->view.frames,
                  fmt::format("with --html: most frames in the page (default {})", io::kViewFramesDefault))
      ->needs(html);
  cmd->add_option("--method", o->method,
                  fmt::format("override [integrator] method: {} (multibody: {})", dynamics::method_names(),
                              multibody::multibody_method_names()));
  o->dt_opt = cmd->add_option("--dt", o->dt, "override [integrator] dt (s)");
  o->t_end_opt = cmd->add_option("--t-end", o->t_end, "override [output] t_end (s)");
  o->sample_dt_opt = cmd->add_option("--sample-dt", o->sample_dt, "override [output] sample_dt (s)");
  cmd->callback([o] { run(*o); });
}

}  // namespace poinsot::cli
