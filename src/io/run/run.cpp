// Runs a scenario into its files and its summary (see run.hpp).
#include "poinsot/io/run/run.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/axis_tracker.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/io/run/summary.hpp"
#include "poinsot/io/run/trajectory_writer.hpp"
#include "run_lambda.hpp"

namespace poinsot::io {

std::string symmetry_class(const Vec3& m, double rel_tol) {
  return inertia::to_string(inertia::classify(m, rel_tol));
}

void prepare_output_dir(const std::string& dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec) {
    throw InvalidInput(
        fmt::format("output: cannot create folder \"{}\": {}; expected a writable place", dir, ec.message()));
  }
  if (!fs::is_directory(dir)) {
    throw InvalidInput(fmt::format("output: \"{}\" exists and is not a folder; expected a folder", dir));
  }
  const std::string probe = (fs::path(dir) / ".poinsot-write-test").string();
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw InvalidInput(fmt::format("output: cannot write in folder \"{}\": {}; expected a writable folder",
                                   dir, std::strerror(errno)));
  }
  ::close(fd);
  ::unlink(probe.c_str());
}

namespace {

/// The top the scenario makes, if any, with the theory's predictions (dynamics/top_prediction.hpp).
std::optional<TopEvents> top_setup(const Scenario& sc, const dynamics::State& s0) {
  const auto theory = dynamics::predict_top(sc.body, *sc.torque, sc.gravity_space, s0);
  if (!theory) return std::nullopt;
  TopEvents top;
  static_cast<dynamics::TopPrediction&>(top) = *theory;
  return top;
}

}  // namespace

RunSummary run_scenario(const Scenario& sc, const RunOptions& options) {
  RunSummary sum;
  sum.scenario = sc.name;
  sum.source = sc.source;
  sum.title = sc.title;
  sum.method = sc.method;
  sum.torque = sc.torque->describe();
  sum.body_description = sc.body_description;
  sum.principal_moments = sc.body.principal_moments();
  sum.inertia = sc.body.inertia();
  sum.symmetry = symmetry_class(sum.principal_moments);
  sum.initial = sc.initial;
  sum.energy0 = dynamics::total_energy(sc.body, sc.initial, sc.gravity_space);
  sum.L_space0 = dynamics::angular_momentum_space(sc.body, sc.initial);
  sum.t_end = sc.simulation.t_end;
  sum.sample_dt = sc.simulation.sample_dt;
  sum.out_dir = options.out_dir;

  // Everything that can be refused is checked before the first step.
  check_method(sc, sc.method, "[integrator] method");
  auto integrator = dynamics::make_integrator(sc.method, sc.body, sc.torque, sc.integrator);
  if (!options.out_dir.empty()) prepare_output_dir(options.out_dir);

  if (sc.torque->is_zero()) {
    // Torque-free about the rotation point (the centre of mass, or a pivot without gravity): Euler-Poinsot.
    const dynamics::FreeBodyTheory theory = dynamics::free_body_theory(sc.body, sc.initial.omega_body);
    sum.free_body_regime = dynamics::to_string(theory.regime);
    if (theory.flip_interval() > 0.0) sum.flip_interval_theory = theory.flip_interval();
    if (theory.omega_period() > 0.0) sum.period_theory = theory.omega_period();
  }
  sum.top = top_setup(sc, sc.initial);

  std::optional<TrajectoryCsvWriter> csv;
  if (!options.out_dir.empty()) {
    sum.trajectory_file = (std::filesystem::path(options.out_dir) / "trajectory.csv").string();
    sum.summary_file = (std::filesystem::path(options.out_dir) / "summary.json").string();
    csv.emplace(sum.trajectory_file, sc.body, sc.gravity_space);
  }
  analysis::LambdaTracker lambda(sc.body, sc.torque, sc.initial);
  std::optional<dynamics::AxisTracker> tracker;
  if (sum.top) tracker.emplace(sum.top->axis_body, sum.top->direction_space);

  bool stopped = false;
  const dynamics::Observer observer = [&](const dynamics::State& s) {
    if (csv) csv->write(s);
    if (tracker) tracker->add(s.time, s.R_space_body);
    if (s.time > sc.initial.time) lambda.observe(s);  // the tracker observed the initial state itself
    ++sum.samples;
    if (options.on_sample) options.on_sample(s.time);
    if (options.stop_requested && options.stop_requested()) {
      stopped = true;
      return false;
    }
    return true;
  };
  try {
    sum.result = dynamics::simulate(sc.body, sc.torque, sc.initial, *integrator, sc.simulation, observer);
  } catch (const ComputationFailed& e) {
    sum.failure = e.what();
  }
  sum.result.interrupted = sum.result.interrupted || stopped;
  if (tracker) {
    sum.top->precession_rate_mean = tracker->precession_rate_mean();
    sum.top->nutation_frequency = tracker->nutation_frequency();
    sum.top->theta_min = tracker->theta_min();
    sum.top->theta_max = tracker->theta_max();
  }
  sum.lambda = lambda.properties();
  sum.lambda_lines = detail::lambda_lines(*sum.lambda);
  if (csv) csv->flush();
  if (!sum.summary_file.empty()) write_file_atomic(sum.summary_file, summary_json(sum));
  if (!sum.failure.empty()) throw ComputationFailed(sum.failure);
  return sum;
}

}  // namespace poinsot::io
