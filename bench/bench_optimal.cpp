// Betts' asymmetric spacecraft (J = diag(5621, 4547, 2364) kg·m², |u_i| ≤ 50 N·m, 150° about x, minimum time)
// from a cold start to the verified optimum: the direct phase (Hermite–Simpson + Ipopt with mesh refinement
// to 1e-5), the indirect phase (shooting from the direct costates) and the verification, timed separately and
// together. PSOPT's published run of the same problem takes 98.65 s. BettsPhased: the phase-per-arc re-solve
// (phased_collocation.hpp) from the direct solution, with its t* error against the indirect optimum as a
// counter, per number of intervals per arc (h⁴: 16 times smaller per doubling). BettsIndirect/M: single
// (M = 1) and multiple shooting over M segments, from the same direct solution.
#include <benchmark/benchmark.h>

#include <cmath>

#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/phased_collocation.hpp"
#include "poinsot/optimal/verification.hpp"

namespace {

using namespace poinsot;
using namespace poinsot::optimal;

ReorientationProblem betts() {
  ReorientationProblem p;
  p.inertia_body = Vec3(5621.0, 4547.0, 2364.0).asDiagonal();
  p.torque_max = Vec3::Constant(50.0);
  p.rate_max = 0.5;
  const double half = 0.5 * 150.0 * M_PI / 180.0;
  p.attitude_final = Quat(std::cos(half), std::sin(half), 0.0, 0.0);
  return p;
}

CollocationOptions direct_options() {
  CollocationOptions o;
  o.initial_intervals = 10;
  o.mesh_tolerance = 1e-5;
  return o;
}

void BM_BettsDirect(benchmark::State& state) {
  const auto p = betts();
  for (auto _ : state)
    benchmark::DoNotOptimize(solve_direct(p, direct_options()));
}
BENCHMARK(BM_BettsDirect)->Unit(benchmark::kMillisecond);

// The indirect phase by shooting over M segments (Arg; 1: single shooting), from the same direct solution:
// counters t_star and the Newton iterations.
void BM_BettsIndirect(benchmark::State& state) {
  const auto p = betts();
  const DirectSolution d = solve_direct(p, direct_options());
  ShootingOptions o;
  o.shooting_nodes = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const IndirectSolution s = solve_indirect(p, d, o);
    if (!s.converged) state.SkipWithError("shooting did not converge");
    state.counters["t_star"] = s.final_time;
    state.counters["newton"] = s.iterations;
  }
}
BENCHMARK(BM_BettsIndirect)->Arg(1)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);

void BM_BettsVerification(benchmark::State& state) {
  const auto p = betts();
  const DirectSolution d = solve_direct(p, direct_options());
  const IndirectSolution s = solve_indirect(p, d);
  for (auto _ : state)
    benchmark::DoNotOptimize(verify(p, d, s));
}
BENCHMARK(BM_BettsVerification)->Unit(benchmark::kMillisecond);

void BM_BettsColdStartToVerifiedOptimum(benchmark::State& state) {
  const auto p = betts();
  for (auto _ : state) {
    const DirectSolution d = solve_direct(p, direct_options());
    const IndirectSolution s = solve_indirect(p, d);
    const VerificationReport v = verify(p, d, s);
    if (!v.passed) state.SkipWithError("not verified");
    state.counters["t_star"] = s.final_time;
  }
}
BENCHMARK(BM_BettsColdStartToVerifiedOptimum)->Unit(benchmark::kMillisecond);

void BM_BettsPhased(benchmark::State& state) {
  const auto p = betts();
  const DirectSolution d = solve_direct(p, direct_options());
  const IndirectSolution s = solve_indirect(p, d);
  const SwitchingStructure st = read_switching_structure(p, d);
  PhasedOptions o;
  o.intervals_per_arc = static_cast<int>(state.range(0));
  for (auto _ : state) {
    const PhasedSolution r = solve_direct_phased(p, d, st, o);
    if (!r.converged) state.SkipWithError("phased re-solve did not converge");
    state.counters["t_star_error"] = std::abs(r.solution.final_time / s.final_time - 1.0);
  }
}
BENCHMARK(BM_BettsPhased)->Arg(8)->Arg(16)->Arg(32)->Arg(64)->Unit(benchmark::kMillisecond);

}  // namespace
