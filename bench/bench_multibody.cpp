// Cost per RATTLE step of a chain of N ball-jointed thin rods (1 m, 1 kg, radius 1 cm) released from
// horizontal under gravity, dt = 1e-3 (issue 8). Counters: the energy error relative to the releasable
// potential energy m g l N²/2, the largest joint gap (m) and the mean Newton iterations, over the benchmark's
// run. Run: build/release/bench/bench_multibody --benchmark_counters_tabular=true The growth exponent is
// fitted by Google Benchmark (BigO, "oN" expected).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/rattle.hpp"

namespace {

using namespace poinsot;
using namespace poinsot::multibody;

System rod_chain(int n) {
  System s;
  const double m = 1.0, l = 1.0, r = 0.01;
  const Mat3 K = Vec3(m * l * l / 12.0, m * r * r / 4.0, m * r * r / 4.0).asDiagonal();
  for (int i = 0; i < n; ++i) {
    std::string name("link");
    name.append(std::to_string(i));
    s.add_body(name, m, K);
  }
  s.add_ball("pivot", 0, Vec3(-l / 2, 0, 0), kWorld, Vec3::Zero());
  for (int i = 1; i < n; ++i) {
    std::string name("j");
    name.append(std::to_string(i));
    s.add_ball(name, i, Vec3(-l / 2, 0, 0), i - 1, Vec3(l / 2, 0, 0));
  }
  s.set_gravity(Vec3(0, 0, -9.81));
  return s;
}

// One benchmark per method: RATTLE (order 2) and its fourth-order triple-jump composition.
void rod_chain_steps(benchmark::State& bm, int order) {
  const int n = static_cast<int>(bm.range(0));
  RattleOptions options;
  options.order = order;
  const System system = rod_chain(n);
  State released;
  released.bodies.resize(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i)
    released.bodies[static_cast<std::size_t>(i)].x_space = Vec3(i + 0.5, 0, 0);
  State st = released;
  Rattle rattle(system, 1e-3, options);
  const double E0 = total_energy(system, st);
  double max_dE = 0.0, max_gap = 0.0;
  long steps = 0, iterations = 0;
  for (auto _ : bm) {
    rattle.step(st);
    ++steps;
    iterations += rattle.last_iterations();
    if (steps % 10 == 0) {  // sampled diagnostics, not timed (the whip's energy peak lasts ~20 steps)
      bm.PauseTiming();
      max_dE = std::max(max_dE, std::abs(total_energy(system, st) - E0));
      max_gap = std::max(max_gap, constraint_violation(system, st).joint_gap);
      if (steps % 5000 == 0) {
        st = released;
        rattle = Rattle(system, 1e-3, options);
      }
      bm.ResumeTiming();
    }
  }
  bm.counters["energy_err_rel"] = max_dE / (9.81 * n * n / 2.0);
  bm.counters["max_gap_m"] = max_gap;
  bm.counters["newton_its"] = static_cast<double>(iterations) / static_cast<double>(std::max(1L, steps));
  bm.SetComplexityN(n);
}
void BM_RodChainStep(benchmark::State& bm) {
  rod_chain_steps(bm, 2);
}
void BM_RodChainStepOrder4(benchmark::State& bm) {
  rod_chain_steps(bm, 4);
}
BENCHMARK(BM_RodChainStep)
    ->Arg(1)
    ->Arg(4)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity();
BENCHMARK(BM_RodChainStepOrder4)
    ->Arg(1)
    ->Arg(4)
    ->Arg(16)
    ->Arg(64)
    ->Arg(256)
    ->Unit(benchmark::kMicrosecond)
    ->Complexity();

}  // namespace
