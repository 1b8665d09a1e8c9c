// Cost per RATTLE step of a chain of N ball-jointed thin rods (1 m, 1 kg, radius 1 cm) released from
// horizontal under gravity, dt = 1e-3. Counters: the energy error relative to the releasable
// potential energy m g l N²/2, the largest joint gap (m) and the mean Newton iterations, over the benchmark's
// run. Run: build/release/bench/bench_multibody --benchmark_counters_tabular=true The growth exponent is
// fitted by Google Benchmark (BigO, "oN" expected).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "rod_chain.hpp"

namespace {

using namespace poinsot;
using namespace poinsot::multibody;

using bench::rod_chain;

// One benchmark per method: RATTLE (order 2), its fourth-order triple-jump composition, and the projected
// RK4 (projected_rk4.hpp). `make` builds a fresh integrator (also to restart the chain every 5000 steps).
template <class Make>
void rod_chain_steps(benchmark::State& bm, Make make) {
  const int n = static_cast<int>(bm.range(0));
  const System system = rod_chain(n);
  const State released = bench::released_chain(n);
  State st = released;
  auto integrator = make(system);
  const double E0 = total_energy(system, st);
  double max_dE = 0.0, max_gap = 0.0;
  long steps = 0, iterations = 0;
  for (auto _ : bm) {
    integrator.step(st);
    ++steps;
    iterations += integrator.last_iterations();
    if (steps % 10 == 0) {  // sampled diagnostics, not timed (the whip's energy peak lasts ~20 steps)
      bm.PauseTiming();
      max_dE = std::max(max_dE, std::abs(total_energy(system, st) - E0));
      max_gap = std::max(max_gap, constraint_violation(system, st).joint_gap);
      if (steps % 5000 == 0) {
        st = released;
        integrator = make(system);
      }
      bm.ResumeTiming();
    }
  }
  bm.counters["energy_err_rel"] = max_dE / (9.81 * n * n / 2.0);
  bm.counters["max_gap_m"] = max_gap;
  // Newton iterations of the position stages (RATTLE) or of the joint projection (RK4), per step.
  bm.counters["newton_its"] = static_cast<double>(iterations) / static_cast<double>(std::max(1L, steps));
  bm.SetComplexityN(n);
}
auto rattle_of_order(int order) {
  return [order](const System& system) {
    RattleOptions options;
    options.order = order;
    return Rattle(system, 1e-3, options);
  };
}
void BM_RodChainStep(benchmark::State& bm) {
  rod_chain_steps(bm, rattle_of_order(2));
}
void BM_RodChainStepOrder4(benchmark::State& bm) {
  rod_chain_steps(bm, rattle_of_order(4));
}
void BM_RodChainStepRk4(benchmark::State& bm) {
  rod_chain_steps(bm, [](const System& system) { return ProjectedRk4(system, 1e-3); });
}
// N = 1, 4, 16, 64, 256 and the fitted growth.
void chain_sizes(benchmark::internal::Benchmark* b) {
  for (int n = 1; n <= 256; n *= 4)
    b->Arg(n);
  b->Unit(benchmark::kMicrosecond)->Complexity();
}
BENCHMARK(BM_RodChainStep)->Apply(chain_sizes);
BENCHMARK(BM_RodChainStepOrder4)->Apply(chain_sizes);
BENCHMARK(BM_RodChainStepRk4)->Apply(chain_sizes);

}  // namespace
