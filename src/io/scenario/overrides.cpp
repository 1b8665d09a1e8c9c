// The command line's overrides of a scenario, single-body and multibody (scenario.hpp,
// multibody_scenario.hpp): the one mapping of --method, --dt, --t-end, --sample-dt and --out.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/io/scenario/work_limits.hpp"
#include "poinsot/multibody/methods.hpp"

namespace poinsot::io {
namespace {

/// A time override: finite and > 0 (s).
double positive_time(std::string_view option, double x) {
  if (!(std::isfinite(x) && x > 0.0)) {
    throw InvalidInput(fmt::format("{}: got {} s, expected a number > 0", option, format_number(x)));
  }
  return x;
}

}  // namespace

void apply_overrides(Scenario& sc, const ScenarioOverrides& o) {
  if (!o.method.empty()) {
    check_method(sc, o.method, "--method");
    sc.method = o.method;
  }
  if (o.dt) sc.integrator.dt = positive_time("--dt", *o.dt);
  if (o.t_end) sc.simulation.t_end = positive_time("--t-end", *o.t_end);
  if (o.sample_dt) sc.simulation.sample_dt = positive_time("--sample-dt", *o.sample_dt);
  if (!o.out_dir.empty()) sc.out_dir = o.out_dir;
  check_step_count(sc.simulation.t_end / sc.integrator.dt, "--t-end/--dt", "t_end / dt");
  check_sample_count(sc.simulation.t_end / sc.simulation.sample_dt, "--t-end/--sample-dt",
                     "t_end / sample_dt");
}

void apply_overrides(multibody::Scenario& sc, const ScenarioOverrides& o) {
  if (!o.method.empty()) {
    sc.method = multibody::parse_multibody_method(o.method, "--method");
    sc.order = multibody::order_for_method(sc.method, sc.order);
  }
  if (o.dt) sc.dt = positive_time("--dt", *o.dt);
  if (o.t_end) sc.duration = positive_time("--t-end", *o.t_end);
  if (o.sample_dt) {
    sc.output_every =
        std::max(1, static_cast<int>(std::lround(positive_time("--sample-dt", *o.sample_dt) / sc.dt)));
  }
  check_step_count(sc.duration / sc.dt, "--t-end/--dt", "duration / dt");
  check_sample_count(sc.duration / sc.dt / sc.output_every, "--t-end/--sample-dt",
                     "duration / dt / output_every");
}

}  // namespace poinsot::io
