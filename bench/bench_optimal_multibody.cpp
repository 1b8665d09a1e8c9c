// Optimal motions of coupled bodies: the rotation-matrix transcription against the minimal-coordinate one
// (docs/optimal_control_multibody.md, "Multibody systems"). The argument "minimal" is 0 for the
// rotation-matrix transcription, 1 for the minimal-coordinate one. Each benchmark runs once (Iterations(1));
// its counters and printed lines are the measurement:
// - BM_ArmRandomBoundaryConditions: 100 rest-to-rest motions of the two-link arm between
//   random configurations (fixed seed), N = 6 intervals, T = 1.5 s, each from the naive guess (linear
//   interpolation of every state coordinate, all else zero), at most 200 Ipopt iterations: the fraction
//   solved, the mean and median Ipopt iterations of the solved ones, the mean wall time per problem;
// - BM_ArmFineMesh: the arm of the tests, (Δ1, Δ2) = (1, 0.5) rad, on N = 8 to 128 (minimal coordinates to
//   256), each from the naive guess: the costs, printed in full (the rotation-matrix runs at N ≥ 64 take
//   minutes);
// - BM_ArmKktScaling: the arm in R-coordinates on N = 8, 16, 32 with MUMPS' automatic scaling (Ipopt's
//   default) and without (MultibodyOptions::mumps_scaling = 0): iterations, CPU time;
// - BM_ArmFormulationsAgree: the arm in both coordinates on N = 16, 32, …, up to 64 or 512, each mesh
//   warm-started from the previous one, without MUMPS' scaling: the costs and the difference of the two
//   formulations' costs and trajectories (N = 512: minutes of CPU);
// - BM_ReactionWheel: the spacecraft with a reaction wheel of tests/optimal/multibody_test_problems.hpp, the
//   bus turned by 1 rad in 10 s with |u| ≤ 0.1 N·m (the unbounded optimum's peak is 0.12 N·m: the bound is
//   active), in both coordinates on N = 8, 16 and 32, against the single-body optimum of the same effective
//   inertia (direct_collocation.hpp, mesh refined to 1e-9, solved once outside the timed loop), each from the
//   naive guess and re-simulated.
// - BM_FallingCat: the falling cat of the tests turned over (by π about its spine in 1 s), with and without
//   the no-twist condition, on N = 6 and 12, each from the naive guess (at most 500 Ipopt iterations), the
//   last iterate re-simulated with 256 steps per interval (the refined, verified optima: the example
//   example_falling_cat).
// - BM_FallingCatMinimal: the same half turn in minimal coordinates (the front half a floating base, the
//   waist a relative quaternion), from the naive guess or from the cat turned rigidly about its spine
//   (falling_cat_rigid_turn), N = 6, 12, 24, at most 500 Ipopt iterations, re-simulated.
// Run: build/release/bench/bench_optimal_multibody --benchmark_counters_tabular=true
//   [--benchmark_filter='Random|Fine.*N:32|KktScaling|FormulationsAgree/N:512|Wheel|Cat']
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "../tests/optimal/multibody_test_problems.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/multibody_direct.hpp"

namespace {

using namespace poinsot;
using namespace poinsot::optimal;

// The two-link arm of tests/optimal/multibody_test_problems.hpp (rods of 1 kg, 1 m, radius 5 cm on hinges
// about z, gravity −9.81 m/s² along y, both hinges driven with |u| ≤ 50 N·m), rest at the angles (a1, a2) to
// rest at (b1, b2) rad in T.
MultibodyProblem arm(double a1, double a2, double b1, double b2, double T, int intervals) {
  MultibodyProblem p = testing::two_link_arm(0.0, 0.0, T, intervals);
  p.initial_state = testing::two_link_state(a1, a2);
  p.final_state = testing::two_link_state(b1, b2);
  return p;
}

MultibodyCoordinates coordinates(const benchmark::State& state) {
  return state.range(0) == 0 ? MultibodyCoordinates::rotation_matrix : MultibodyCoordinates::minimal;
}

void BM_ArmRandomBoundaryConditions(benchmark::State& state) {
  constexpr int kProblems = 100;
  const double down = -0.5 * std::numbers::pi;
  MultibodyOptions options;
  options.coordinates = coordinates(state);
  options.max_nlp_iterations = 200;
  int solved = 0;
  std::vector<double> iterations;
  double seconds = 0.0, cost_sum = 0.0;
  for (auto _ : state) {
    std::mt19937_64 rng(20261124);
    std::uniform_real_distribution<double> angle(-1.0, 1.0);
    for (int k = 0; k < kProblems; ++k) {
      const double a1 = down + angle(rng), a2 = angle(rng), b1 = down + angle(rng), b2 = angle(rng);
      const MultibodyOptimum o = solve_multibody(arm(a1, a2, b1, b2, 1.5, 6), options);
      seconds += o.wall_seconds;
      if (o.converged) {
        ++solved;
        iterations.push_back(o.nlp_iterations);
        cost_sum += o.cost;
      } else {
        std::printf(
            "arm random boundary conditions: problem %d (%.3f, %.3f) -> (%.3f, %.3f) rad: %s after %d "
            "iterations\n",
            k, a1, a2, b1, b2, o.status.c_str(), o.nlp_iterations);
      }
    }
  }
  std::sort(iterations.begin(), iterations.end());
  double mean = 0.0;
  for (const double i : iterations)
    mean += i;
  state.counters["problems"] = kProblems;
  state.counters["solved_fraction"] = static_cast<double>(solved) / kProblems;
  state.counters["mean_iterations"] =
      iterations.empty() ? 0.0 : mean / static_cast<double>(iterations.size());
  state.counters["median_iterations"] = iterations.empty() ? 0.0 : iterations[iterations.size() / 2];
  state.counters["mean_wall_s"] = seconds / kProblems;
  state.counters["mean_cost_solved"] = solved == 0 ? 0.0 : cost_sum / solved;
  std::printf(
      "arm random boundary conditions: coordinates %s: %d of %d solved, iterations mean %.1f median %.0f, "
      "%.3f s per problem\n",
      state.range(0) == 0 ? "rotation_matrix" : "minimal", solved, kProblems,
      state.counters["mean_iterations"].value, state.counters["median_iterations"].value,
      seconds / kProblems);
}
BENCHMARK(BM_ArmRandomBoundaryConditions)
    ->Arg(0)
    ->Arg(1)
    ->ArgName("minimal")
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

void BM_ArmFineMesh(benchmark::State& state) {
  MultibodyOptions options;
  options.coordinates = coordinates(state);
  const int intervals = static_cast<int>(state.range(1));
  MultibodyOptimum o;
  for (auto _ : state) {
    const double down = -0.5 * std::numbers::pi;
    o = solve_multibody(arm(down, 0.0, down + 1.0, 0.5, 1.5, intervals), options);
  }
  state.counters["converged"] = o.converged ? 1.0 : 0.0;
  state.counters["iterations"] = o.nlp_iterations;
  state.counters["wall_s"] = o.wall_seconds;
  if (!o.converged) state.SkipWithError(o.status.c_str());
  std::printf("arm fine mesh: coordinates %s N = %d: %s, cost %.14g, %d iterations, %.2f s\n",
              state.range(0) == 0 ? "rotation_matrix" : "minimal", intervals, o.status.c_str(), o.cost,
              o.nlp_iterations, o.wall_seconds);
}
BENCHMARK(BM_ArmFineMesh)
    ->ArgsProduct({{0, 1}, {8, 16, 32, 64, 128}})
    ->Args({1, 256})
    ->ArgNames({"minimal", "N"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// The arm of the tests in R-coordinates from the naive guess, with MUMPS' scaling of the KKT matrix as
// Ipopt chooses it by default (range(0) = 77, MultibodyOptions' default) and without it (0), on N = range(1)
// intervals: Ipopt iterations and the process CPU time per iteration. Their ratio is the figure of
// docs/measurements/optimal_multibody.md ("The cost of the R-coordinate transcription").
void BM_ArmKktScaling(benchmark::State& state) {
  MultibodyOptions options;
  options.mumps_scaling = static_cast<int>(state.range(0));
  const int intervals = static_cast<int>(state.range(1));
  const double down = -0.5 * std::numbers::pi;
  MultibodyOptimum o;
  double cpu = 0.0;
  for (auto _ : state) {
    const std::clock_t c0 = std::clock();
    o = solve_multibody(arm(down, 0.0, down + 1.0, 0.5, 1.5, intervals), options);
    cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
  }
  state.counters["iterations"] = o.nlp_iterations;
  state.counters["cpu_s"] = cpu;
  state.counters["cpu_s_per_iteration"] = cpu / std::max(o.nlp_iterations, 1);
  if (!o.converged) state.SkipWithError(o.status.c_str());
  std::printf("arm KKT scaling %d N = %d: %s, cost %.14g, %d iterations, %.2f s CPU (%.3f s per iteration)\n",
              options.mumps_scaling, intervals, o.status.c_str(), o.cost, o.nlp_iterations, cpu,
              cpu / std::max(o.nlp_iterations, 1));
}
BENCHMARK(BM_ArmKktScaling)
    ->ArgsProduct({{77, 0}, {8, 16, 32}})
    ->ArgNames({"mumps_scaling", "N"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// The arm of the tests in both coordinates on a sequence of equal meshes, N = 16 from the naive guess and
// every later mesh (2N) warm-started from the previous optimum of the same coordinates (MultibodyOptions::
// warm_start), up to N = range(0): per mesh and coordinates the cost (printed in full), Ipopt iterations and
// the process CPU time; then the relative difference of the two costs and of the two trajectories at the
// common collocation points: the largest angle between the two attitudes of a link (rad) and the largest
// control difference relative to the peak control (docs/measurements/optimal_multibody.md, "Convergence on
// the arm and the formulations at 1e-8").
void BM_ArmFormulationsAgree(benchmark::State& state) {
  const int finest = static_cast<int>(state.range(0));
  const double down = -0.5 * std::numbers::pi;
  double cost_difference = 0.0;
  for (auto _ : state) {
    MultibodyOptimum previous[2];
    for (int n = 16; n <= finest; n *= 2) {
      MultibodyOptimum o[2];
      for (int c = 0; c < 2; ++c) {
        MultibodyOptions options;
        options.coordinates = c == 0 ? MultibodyCoordinates::rotation_matrix : MultibodyCoordinates::minimal;
        options.mumps_scaling = 0;  // 25 iterations instead of 61 at N = 32 (BM_ArmKktScaling)
        options.warm_start = n == 16 ? nullptr : &previous[c];
        const std::clock_t c0 = std::clock();
        o[c] = solve_multibody(arm(down, 0.0, down + 1.0, 0.5, 1.5, n), options);
        const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
        std::printf("arm N = %d, coordinates %s: %s, cost %.14g, %d iterations, %.2f s CPU\n", n,
                    c == 0 ? "rotation_matrix" : "minimal", o[c].status.c_str(), o[c].cost,
                    o[c].nlp_iterations, cpu);
        if (!o[c].converged) {
          state.SkipWithError(o[c].status.c_str());
          return;
        }
      }
      double angle = 0.0, control = 0.0, peak = 0.0;
      for (std::size_t p = 0; p < o[0].time.size(); ++p) {
        for (std::size_t i = 0; i < 2; ++i) {
          const Mat3 d =
              o[0].states[p].bodies[i].R_space_body.transpose() * o[1].states[p].bodies[i].R_space_body;
          angle = std::max(angle, std::acos(std::clamp(0.5 * (d.trace() - 1.0), -1.0, 1.0)));
        }
        control = std::max(control, (o[0].controls[p] - o[1].controls[p]).cwiseAbs().maxCoeff());
        peak = std::max(peak, o[1].controls[p].cwiseAbs().maxCoeff());
      }
      cost_difference = o[0].cost / o[1].cost - 1.0;
      std::printf(
          "arm N = %d: R-coordinates relative to minimal: cost %.3g; trajectories: attitude %.3g rad, "
          "control %.3g of the peak %.4g N·m\n",
          n, cost_difference, angle, control / peak, peak);
      std::fflush(stdout);
      previous[0] = o[0];
      previous[1] = o[1];
    }
  }
  state.counters["relative_cost_difference"] = cost_difference;
}
BENCHMARK(BM_ArmFormulationsAgree)->Arg(64)->Arg(512)->ArgName("N")->Iterations(1)->Unit(benchmark::kSecond);

/// The single-body optimum of the wheel's effective inertia (solved once, outside the timed loops).
const DirectSolution& reaction_wheel_single_body() {
  static const DirectSolution single = [] {
    ReorientationProblem q;
    q.inertia_body = testing::reaction_wheel_effective_inertia();
    q.torque_max = Vec3::Constant(0.1);
    q.attitude_final = Quat(Eigen::AngleAxisd(1.0, Vec3::UnitZ()));
    q.objective = Objective::minimum_energy;
    q.final_time = 10.0;
    CollocationOptions options;
    options.mesh_tolerance = 1e-9;
    return solve_direct(q, options);
  }();
  return single;
}

void BM_ReactionWheel(benchmark::State& state) {
  const int intervals = static_cast<int>(state.range(1));
  const MultibodyProblem p = testing::reaction_wheel(1.0, 10.0, 0.1, intervals);
  MultibodyOptions options;
  options.coordinates = coordinates(state);
  MultibodyOptimum o;
  for (auto _ : state)
    o = solve_multibody(p, options);
  const DirectSolution& single = reaction_wheel_single_body();
  if (!o.converged || !single.converged) {
    state.SkipWithError(o.converged ? single.status.c_str() : o.status.c_str());
    return;
  }
  const MultibodyReplay replay = replay_controls(p, o, 64);
  state.counters["iterations"] = o.nlp_iterations;
  state.counters["wall_s"] = o.wall_seconds;
  state.counters["relative_to_single_body"] = o.cost / single.cost - 1.0;
  std::printf(
      "reaction wheel, coordinates %s, N = %d: cost %.12g (%d iterations, %.2f s wall), single body %.12g "
      "(%zu "
      "nodes), relative %.3g; replay: attitude %.3g rad, rates %.3g rad/s, joint gap %.3g m, momentum change "
      "%.3g\n",
      state.range(0) == 0 ? "rotation_matrix" : "minimal", intervals, o.cost, o.nlp_iterations,
      o.wall_seconds, single.cost, single.node_time.size(), o.cost / single.cost - 1.0, replay.attitude_error,
      replay.velocity_error, replay.max_joint_gap, replay.max_momentum_change);
}
BENCHMARK(BM_ReactionWheel)
    ->ArgsProduct({{0, 1}, {8, 16, 32}})
    ->ArgNames({"minimal", "N"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

void BM_FallingCat(benchmark::State& state) {
  const bool no_twist = state.range(0) == 1;
  const int intervals = static_cast<int>(state.range(1));
  MultibodyProblem p = testing::falling_cat(0.5, std::numbers::pi, 1.0, intervals);
  if (no_twist) p.no_twist = {testing::falling_cat_no_twist()};
  MultibodyOptions options;
  options.max_nlp_iterations = 500;
  options.stabilisation_step = testing::kCatStabilisationStep;
  MultibodyOptimum o;
  for (auto _ : state)
    o = solve_multibody(p, options);
  const MultibodyReplay replay = replay_controls(p, o, 256);
  state.counters["converged"] = o.converged ? 1.0 : 0.0;
  state.counters["iterations"] = o.nlp_iterations;
  state.counters["wall_s"] = o.wall_seconds;
  state.counters["stabilisation_step"] = o.stabilisation_step;
  std::printf(
      "falling cat half turn%s N = %d, naive guess: %s, cost %.10g (%d iterations, %.1f s, stabilisation "
      "%.3g "
      "of its bound); replay: attitude %.3g rad, joint gap %.3g m, momentum change %.3g\n",
      no_twist ? " without twist" : "", intervals, o.status.c_str(), o.cost, o.nlp_iterations, o.wall_seconds,
      o.stabilisation_step, replay.attitude_error, replay.max_joint_gap, replay.max_momentum_change);
}
BENCHMARK(BM_FallingCat)
    ->ArgsProduct({{0, 1}, {6, 12}})
    ->ArgNames({"no_twist", "N"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

void BM_FallingCatMinimal(benchmark::State& state) {
  const bool rigid = state.range(0) == 1;
  const int intervals = static_cast<int>(state.range(1));
  const MultibodyProblem p = testing::falling_cat(0.5, std::numbers::pi, 1.0, intervals);
  const MultibodyOptimum guess = testing::falling_cat_rigid_turn(0.5, std::numbers::pi, 1.0, intervals);
  MultibodyOptions options;
  options.coordinates = MultibodyCoordinates::minimal;
  options.max_nlp_iterations = 500;
  if (rigid) options.warm_start = &guess;
  MultibodyOptimum o;
  for (auto _ : state)
    o = solve_multibody(p, options);
  const MultibodyReplay replay = replay_controls(p, o, 128);
  state.counters["converged"] = o.converged ? 1.0 : 0.0;
  state.counters["iterations"] = o.nlp_iterations;
  state.counters["wall_s"] = o.wall_seconds;
  std::printf(
      "falling cat half turn, minimal coordinates, N = %d, from the %s: %s, cost %.10g (%d iterations, %.1f "
      "s); "
      "replay: attitude %.3g rad, joint gap %.3g m, momentum change %.3g\n",
      intervals, rigid ? "rigid turn" : "naive guess", o.status.c_str(), o.cost, o.nlp_iterations,
      o.wall_seconds, replay.attitude_error, replay.max_joint_gap, replay.max_momentum_change);
}
BENCHMARK(BM_FallingCatMinimal)
    ->ArgsProduct({{0, 1}, {6, 12, 24}})
    ->ArgNames({"rigid_turn", "N"})
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
