// The analysis layer (Λ of Vallée & Dumitriu 2002), one core, double precision.
// Run: build/release/bench/bench_analysis
// Per-state costs of Λ from the state (eq. 3.2), the closed form (3.7), the tracker (eigenvalues, stress,
// closed-form checks), and a whole analyse_lambda run of 10^6 rattle steps (the long-run figure that the
// tests keep short).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "poinsot/analysis/closed_form.hpp"
#include "poinsot/analysis/lambda_report.hpp"
#include "poinsot/analysis/lambda_tracker.hpp"
#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/analysis/stress.hpp"

namespace {
using poinsot::Mat3;
using poinsot::Vec3;
using poinsot::dynamics::RigidBody;
using poinsot::dynamics::State;
constexpr std::size_t kN = 1024;

std::vector<State> random_states() {
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::vector<State> out(kN);
  for (auto& s : out) {
    s.omega_body = Vec3(u(rng), u(rng), u(rng));
    s.R_space_body = Eigen::Quaterniond(u(rng), u(rng), u(rng), u(rng)).normalized().toRotationMatrix();
  }
  return out;
}

const RigidBody& body() {
  static const RigidBody b = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  return b;
}

void BM_LambdaFromState(benchmark::State& st) {
  const auto states = random_states();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(poinsot::analysis::lambda_from_state(body(), states[i++ % kN]));
  }
}
BENCHMARK(BM_LambdaFromState);

void BM_LambdaClosedForm37(benchmark::State& st) {
  const auto states = random_states();
  const Mat3 J = body().inertia();
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(poinsot::analysis::lambda_closed_form(J, states[i++ % kN].omega_body));
  }
}
BENCHMARK(BM_LambdaClosedForm37);

void BM_StressSummary(benchmark::State& st) {
  const auto states = random_states();
  std::size_t i = 0;
  for (auto _ : st) {
    const State& s = states[i++ % kN];
    benchmark::DoNotOptimize(
        poinsot::analysis::summarize_stress(poinsot::analysis::stress_integral_space(body(), s)));
  }
}
BENCHMARK(BM_StressSummary);

void BM_TrackerObserveAxisymmetric(benchmark::State& st) {
  const RigidBody prolate = RigidBody::from_principal_moments(Vec3(2.0, 2.0, 1.0));
  const auto states = random_states();
  poinsot::analysis::LambdaTracker tracker(prolate, nullptr, states[0]);
  std::size_t i = 0;
  for (auto _ : st) {
    tracker.observe(states[i++ % kN]);
  }
  benchmark::DoNotOptimize(tracker.properties().symmetry_error_max);
}
BENCHMARK(BM_TrackerObserveAxisymmetric);

// 10^6 rattle steps of case b (dt = 1e-3 s, 1000 s), Λ checked every 0.01 s (10^5 samples, each with the
// rattle-multiplier comparison). Reports the worst deviations as counters.
void BM_AnalyseLambdaRattleMillionSteps(benchmark::State& st) {
  const RigidBody prolate = RigidBody::from_principal_moments(Vec3(2.0, 2.0, 1.0));
  State s0;
  s0.omega_body = Vec3(0.3, -0.4, 1.2);
  poinsot::analysis::LambdaAnalysisOptions o;
  o.method = "rattle";
  o.integrator.dt = 1e-3;
  o.t_end = 1000.0;
  o.sample_dt = 0.01;
  poinsot::analysis::LambdaReport r;
  for (auto _ : st) {
    r = poinsot::analysis::analyse_lambda(prolate, s0, o);
  }
  st.counters["steps"] = static_cast<double>(r.steps);
  st.counters["eig_closed_form_dev"] = r.properties.closed_form->max_deviation;
  st.counters["rattle_multiplier_dev"] = r.properties.integrator_multiplier_deviation_max;
  st.counters["ETLambdaE_drift"] = r.properties.closed_form->constant_matrix_deviation_max;
  st.counters["energy_rel"] = r.invariant_errors.energy_rel_max;
}
BENCHMARK(BM_AnalyseLambdaRattleMillionSteps)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
