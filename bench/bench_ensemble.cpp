// Throughput of the ensemble's batched integrators against the scalar integrators of dynamics/ in the same
// process: body-steps per second (items_per_second) for rk4 and dlm on free asymmetric bodies, one thread;
// the scalar integrators one step() at a time and through Integrator::advance. Run:
// build/release/bench/bench_ensemble --benchmark_filter=Ensemble --benchmark_repetitions=5
// --benchmark_enable_random_interleaving=true
// Also the cost per value of the statistics without rows: the quantile sketch against the running moments
// (--benchmark_filter=Statistics).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/ensemble/batch.hpp"
#include "poinsot/ensemble/quantile_sketch.hpp"
#include "poinsot/ensemble/statistics.hpp"

namespace {

using namespace poinsot;

std::vector<ensemble::Sample> samples() {
  ensemble::Nominal n;
  n.moments = Vec3(1.0, 2.0, 2.6);
  n.omega_body = Vec3(0.05, 2.0, 0.05);
  ensemble::Dispersions d;
  d.moments = {ensemble::Law::normal, 0.02, true};
  d.omega = {ensemble::Law::normal, 0.02, false};
  const ensemble::Sampler s(n, d, 1);
  std::vector<ensemble::Sample> out;
  for (int i = 0; i < ensemble::kBatchLanes; ++i)
    out.push_back(s.draw(static_cast<std::uint64_t>(i)));
  return out;
}

constexpr long long kSteps = 2000;
constexpr double kDt = 1e-3;

void BM_EnsembleBatched(benchmark::State& st, const char* method, ensemble::Simd simd) {
  const auto s = samples();
  std::vector<ensemble::LaneResult> r(s.size());
  for (auto _ : st) {
    ensemble::run_batch(method, s, kSteps * kDt, kDt, simd, r);
    benchmark::DoNotOptimize(r.data());
  }
  st.SetItemsProcessed(st.iterations() * kSteps * static_cast<long long>(s.size()));
}

// The scalar path, one sample after the other: `step` per step, or, as the simulation driver takes it for a
// torque-free body, Integrator::advance over all the steps (one conversion to a State per call).
void run_scalar(benchmark::State& st, const char* method, bool use_advance) {
  const auto s = samples();
  for (auto _ : st) {
    for (const auto& x : s) {
      const dynamics::RigidBody body = x.body();
      auto integrator = dynamics::make_integrator(method, body, nullptr, {.dt = kDt});
      dynamics::State y = x.initial;
      if (use_advance) {
        integrator->advance(y, kDt, kSteps);
      } else {
        for (long long i = 0; i < kSteps; ++i)
          integrator->step(y, kDt);
      }
      benchmark::DoNotOptimize(y);
    }
  }
  st.SetItemsProcessed(st.iterations() * kSteps * static_cast<long long>(s.size()));
}

void BM_EnsembleScalar(benchmark::State& st, const char* method) {
  run_scalar(st, method, false);
}

void BM_EnsembleScalarAdvance(benchmark::State& st, const char* method) {
  run_scalar(st, method, true);
}

BENCHMARK_CAPTURE(BM_EnsembleBatched, rk4_simd, "rk4", ensemble::Simd::automatic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleBatched, rk4_portable, "rk4", ensemble::Simd::off)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleScalar, rk4, "rk4")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleScalarAdvance, rk4, "rk4")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleBatched, dlm_simd, "dlm", ensemble::Simd::automatic)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleBatched, dlm_portable, "dlm", ensemble::Simd::off)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleScalar, dlm, "dlm")->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleScalarAdvance, dlm, "dlm")->Unit(benchmark::kMillisecond);

/// Lognormal values over about four decades, as an output like an energy error spreads.
std::vector<double> output_values() {
  std::mt19937_64 rng(1);
  std::lognormal_distribution<double> ln(0.0, 2.0);
  std::vector<double> v(4096);
  for (double& x : v)
    x = ln(rng);
  return v;
}

void BM_StatisticsRunning(benchmark::State& st) {
  const auto v = output_values();
  for (auto _ : st) {
    ensemble::RunningStats s;
    for (double x : v)
      s.add(x);
    benchmark::DoNotOptimize(s);
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long long>(v.size()));
}

void BM_StatisticsSketch(benchmark::State& st) {
  const auto v = output_values();
  ensemble::QuantileSketch s;  // kept across iterations: the steady state of a long run (buckets exist)
  for (auto _ : st) {
    for (double x : v)
      s.add(x);
    benchmark::DoNotOptimize(s);
  }
  st.SetItemsProcessed(st.iterations() * static_cast<long long>(v.size()));
}

BENCHMARK(BM_StatisticsRunning);
BENCHMARK(BM_StatisticsSketch);

}  // namespace
