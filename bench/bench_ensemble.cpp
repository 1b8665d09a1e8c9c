// Throughput of the ensemble's batched integrators against the scalar integrators of dynamics/ in the same
// process: body-steps per second (items_per_second) for rk4 and dlm on free asymmetric bodies, one thread;
// the scalar integrators one step() at a time and through Integrator::advance. Run:
// build/release/bench/bench_ensemble --benchmark_filter=Ensemble --benchmark_repetitions=5
// --benchmark_enable_random_interleaving=true
// Under a constant torque in the body frame or in space (the Betts spacecraft of examples/ensemble, dt = 1
// s): the batched kernels against the scalar path the ensemble would otherwise take, dynamics::simulate with
// the flips located (--benchmark_filter=EnsembleTorque).
// Also the cost per value of the statistics without rows: the quantile sketch against the running moments
// (--benchmark_filter=Statistics).
// A planned slew replayed in closed loop on dispersed bodies (slew_tracking.hpp; the sphere example of
// examples/ensemble/sphere_slew_robustness.toml, dt = 1e-3 s, 3 247 steps a sample): the replay of one
// sample after the other (SlewTracking::run) and the whole runner, one thread, rows off, 1024 samples (one
// block: sampling, outputs, statistics, sketches, histograms) (--benchmark_filter=Slew).
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/ensemble/batch.hpp"
#include "poinsot/ensemble/quantile_sketch.hpp"
#include "poinsot/ensemble/runner.hpp"
#include "poinsot/ensemble/slew_tracking.hpp"
#include "poinsot/ensemble/statistics.hpp"
#include "poinsot/so3/axis_angle.hpp"

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

/// The Betts spacecraft, diag(5621, 4547, 2364) kg·m² ±5 %, under (1, −2, 0.5) mN·m ±10 % in the body frame
/// (`torque` body) or in space.
std::vector<ensemble::Sample> betts_samples(ensemble::TorqueKind torque) {
  ensemble::Nominal n;
  n.moments = Vec3(5621.0, 4547.0, 2364.0);
  n.omega_body = Vec3(0.0, 0.0, 0.001);
  n.torque = torque;
  n.torque_value = Vec3(0.001, -0.002, 0.0005);
  ensemble::Dispersions d;
  d.moments = {ensemble::Law::truncated_normal, 0.05, true};
  d.torque = {ensemble::Law::normal, 0.1, true};
  const ensemble::Sampler s(n, d, 7);
  std::vector<ensemble::Sample> out;
  for (int i = 0; i < ensemble::kBatchLanes; ++i)
    out.push_back(s.draw(static_cast<std::uint64_t>(i)));
  return out;
}

constexpr long long kSteps = 2000;
constexpr double kDt = 1e-3;
constexpr double kBettsDt = 1.0;  // s, as the example

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

void BM_EnsembleTorqueBatched(benchmark::State& st, const char* method, ensemble::TorqueKind torque) {
  const auto s = betts_samples(torque);
  std::vector<ensemble::LaneResult> r(s.size());
  for (auto _ : st) {
    ensemble::run_batch(method, s, kSteps * kBettsDt, kBettsDt, ensemble::Simd::automatic, r);
    benchmark::DoNotOptimize(r.data());
  }
  st.SetItemsProcessed(st.iterations() * kSteps * static_cast<long long>(s.size()));
}

// The scalar path of the runner for a sample it cannot batch: dynamics::simulate to t_end, flips located.
void BM_EnsembleTorqueScalar(benchmark::State& st, const char* method, ensemble::TorqueKind kind) {
  const auto s = betts_samples(kind);
  for (auto _ : st) {
    for (const auto& x : s) {
      const dynamics::RigidBody body = x.body();
      const auto torque = x.torque_model(body);
      auto integrator = dynamics::make_integrator(method, body, torque, {.dt = kBettsDt});
      const dynamics::SimulationResult r = dynamics::simulate(
          body, torque, x.initial, *integrator,
          {.t_end = kSteps * kBettsDt, .sample_dt = kSteps * kBettsDt, .locate_flips = true});
      benchmark::DoNotOptimize(r.final_state);
    }
  }
  st.SetItemsProcessed(st.iterations() * kSteps * static_cast<long long>(s.size()));
}

// The minimum-time 180° slew of a sphere about x (examples/ensemble/sphere_slew_control.csv), its
// dispersions and feedback those of examples/ensemble/sphere_slew_robustness.toml.
std::shared_ptr<const ensemble::SlewTracking> sphere_slew() {
  const double t[] = {0.0,
                      0.4454389949447971,
                      1.1761026437813165,
                      1.621541638726129,
                      2.0669806336709238,
                      2.7976442825074437,
                      3.2430832774522544};
  const double u[6][3] = {{1, -1, 1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, 1, 1}, {-1, -1, 1}};
  std::vector<double> time;
  std::vector<Vec3> torque;
  for (int a = 0; a < 6; ++a)
    for (int e = 0; e < 2; ++e) {
      time.push_back(t[a + e]);
      torque.emplace_back(u[a][0], u[a][1], u[a][2]);
    }
  ensemble::SlewSpec s;
  s.control = std::make_shared<dynamics::TabulatedTorque>(time, torque, "sphere slew");
  s.target_attitude = so3::rotation_from_axis_angle(Vec3::UnitX(), 3.141592653589793);
  s.kp = 4.0;
  s.kd = 4.0;
  s.limit = ensemble::SlewTorqueLimit::per_axis;
  s.torque_max = Vec3::Constant(1.2);
  s.pointing_requirement = 0.0174533;
  s.t_end = t[6];
  s.dt = 1e-3;
  return std::make_shared<const ensemble::SlewTracking>(s, Mat3::Identity(), dynamics::State{});
}

ensemble::Sampler slew_sampler() {
  ensemble::Nominal n;
  ensemble::Dispersions d;
  d.moments = {ensemble::Law::truncated_normal, 0.05, true};
  d.axes = {ensemble::RotationLaw::cone, 0.0175};
  d.attitude = {ensemble::RotationLaw::cone, 0.0087};
  d.omega = {ensemble::Law::normal, 0.001, false};
  return ensemble::Sampler(n, d, 11);
}

void BM_SlewReplay(benchmark::State& st) {
  const auto slew = sphere_slew();
  const ensemble::Sampler sampler = slew_sampler();
  std::vector<ensemble::Sample> s;
  for (std::uint64_t i = 0; i < 64; ++i)
    s.push_back(sampler.draw(i));
  for (auto _ : st)
    for (const auto& x : s)
      benchmark::DoNotOptimize(slew->run(x.inertia_com(), x.initial));
  st.SetItemsProcessed(st.iterations() * slew->step_count() * static_cast<long long>(s.size()));
}

void BM_SlewEnsemble(benchmark::State& st) {
  ensemble::EnsembleOptions o;
  o.samples = ensemble::kBlockSamples;
  o.threads = 1;
  o.keep_rows = false;
  o.slew = sphere_slew();
  o.t_end = o.slew->spec().t_end;
  o.dt = o.slew->spec().dt;
  const ensemble::Sampler sampler = slew_sampler();
  std::int64_t steps = 0;
  for (auto _ : st) {
    const ensemble::EnsembleResult r = ensemble::run_ensemble(sampler, o);
    steps += r.body_steps;
    benchmark::DoNotOptimize(r.stats);
  }
  st.SetItemsProcessed(steps);
}

BENCHMARK(BM_SlewReplay)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlewEnsemble)->Unit(benchmark::kMillisecond);

constexpr auto kBody = ensemble::TorqueKind::body;
constexpr auto kSpace = ensemble::TorqueKind::space;
BENCHMARK_CAPTURE(BM_EnsembleTorqueBatched, rk4_body, "rk4", kBody)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueScalar, rk4_body, "rk4", kBody)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueBatched, dlm_body, "dlm", kBody)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueScalar, dlm_body, "dlm", kBody)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueBatched, rk4_space, "rk4", kSpace)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueScalar, rk4_space, "rk4", kSpace)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueBatched, dlm_space, "dlm", kSpace)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_EnsembleTorqueScalar, dlm_space, "dlm", kSpace)->Unit(benchmark::kMillisecond);

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
