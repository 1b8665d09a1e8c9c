// The scenario loop: integrate, measure, hand the output rows to an observer (scenario.hpp).
#include <algorithm>
#include <cmath>
#include <ctime>

#include "poinsot/core/error.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::multibody {
namespace {

// The run with the scenario's method (methods.hpp: step, last_iterations, kkt_method).
RunSummary run_with(const Scenario& sc, MultibodyIntegrator& integrator, const SampleObserver& observer) {
  RunSummary s;
  State& st = s.final_state;
  st = sc.initial;
  s.kkt_method = integrator.kkt_method();
  s.tree_solver = s.kkt_method != KktMethod::sparse_lu;
  s.energy_initial = total_energy(sc.system, st);
  s.energy_final = s.energy_initial;
  if (observer && !observer(st)) {
    s.interrupted = true;
    return s;
  }
  const long steps = std::lround(sc.duration / sc.dt);
  long iterations = 0;
  const std::clock_t c0 = std::clock();
  for (long n = 0; n < steps; ++n) {
    try {
      integrator.step(st);
    } catch (const ComputationFailed& e) {
      s.failure = e.what();
      st.time = sc.initial.time + static_cast<double>(n) * sc.dt;  // the last completed step's time
      break;
    }
    // Sample times t₀ + n h exactly, as the single-body runs have them (the integrator adds h each step,
    // whose rounding would otherwise accumulate: 0.5000000000000002 s after 50 steps of 0.01 s).
    st.time = sc.initial.time + static_cast<double>(n + 1) * sc.dt;
    ++s.steps;
    iterations += integrator.last_iterations();
    s.max_newton_iterations = std::max(s.max_newton_iterations, integrator.last_iterations());
    const ConstraintViolation v = constraint_violation(sc.system, st);
    s.max_joint_gap = std::max(s.max_joint_gap, v.joint_gap);
    s.max_joint_angle = std::max(s.max_joint_angle, v.joint_angle);
    s.max_orthogonality = std::max(s.max_orthogonality, v.orthogonality);
    s.max_energy_error =
        std::max(s.max_energy_error, std::abs(total_energy(sc.system, st) - s.energy_initial));
    if ((n + 1) % sc.output_every == 0 || n + 1 == steps) {
      if (observer && !observer(st)) {
        s.interrupted = n + 1 < steps;
        break;
      }
    }
  }
  const auto taken = static_cast<double>(s.steps);
  s.cpu_seconds_per_step =
      s.steps > 0 ? static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / taken : 0.0;
  s.mean_newton_iterations = s.steps > 0 ? static_cast<double>(iterations) / taken : 0.0;
  s.energy_final = total_energy(sc.system, st);
  return s;
}

}  // namespace

RunSummary simulate(const Scenario& sc, const SampleObserver& observer) {
  check_consistent(sc.system, sc.initial);
  const auto integrator = multibody_method_info(sc.method).make(sc.system, sc.dt, sc.order);
  return run_with(sc, *integrator, observer);
}

}  // namespace poinsot::multibody
