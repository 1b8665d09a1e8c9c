#include "poinsot/dynamics/integrator.hpp"

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::dynamics {

State Integrator::dense_output(double t) const {
  throw InvalidInput(
      fmt::format("{}: no dense output (asked for t = {} s); expected an adaptive method such as "
                  "dopri5 or dop853",
                  name(), t));
}

void Integrator::require_step_count(std::string_view method, long long n) {
  if (n < 1) throw InvalidInput(fmt::format("{}: advance: n = {} steps; expected at least 1", method, n));
}

StepResult Integrator::advance(State& state, double dt, long long n, StepWatcher* watcher) {
  require_step_count(name(), n);
  StepResult last;
  int rejected = 0;
  for (long long k = 0; k < n; ++k) {
    last = step(state, dt);
    rejected += last.rejected;
    if (watcher) watcher->after_step(k, state.time, state.omega_body);
  }
  last.rejected = rejected;
  return last;
}

bool Integrator::last_multiplier(Mat3&) const {
  return false;
}

}  // namespace poinsot::dynamics
