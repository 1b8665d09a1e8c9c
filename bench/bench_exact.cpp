// The exact free rigid body and the top theory, one core, double precision.
// Run: build/release/bench/bench_exact
//   BM_ExactStateAt*: one evaluation at an arbitrary time (the set-up done once); target <= 1 us.
//   BM_ExactTennisRacketAt100s: set-up + evaluation at t = 100 s (the orientation to ~1e-13 rad, see the
//   tests).
//   BM_JacobiElliptic/BM_BoostJacobiElliptic: sn, cn, dn at u spread over [−K, K] (k'² given by the argument
//   as 10^-arg), ours against Boost.Math's in the same process (the baseline).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <cmath>

#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/dynamics/exact_integrator.hpp"
#include "poinsot/dynamics/jacobi_elliptic.hpp"
#include "poinsot/dynamics/top_theory.hpp"

namespace {
using poinsot::Mat3;
using poinsot::Vec3;
using poinsot::dynamics::ExactFreeBody;
using poinsot::dynamics::RigidBody;
using poinsot::dynamics::State;
constexpr std::size_t kN = 1024;

std::vector<double> random_times(double lo, double hi) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(lo, hi);
  std::vector<double> out(kN);
  for (auto& t : out)
    t = u(rng);
  return out;
}

RigidBody racket() {
  return RigidBody::from_principal_moments(Vec3(0.0015, 0.0160, 0.0170));  // kg·m²
}

State racket_start() {
  State s;
  s.omega_body = Vec3(0.05, 4.0, 0.05);  // rad/s, spun about the intermediate axis
  return s;
}

void run_state_at(benchmark::State& st, const RigidBody& body, const State& s0) {
  const ExactFreeBody exact(body, s0);
  const std::vector<double> times = random_times(-1e3, 1e3);
  std::size_t i = 0;
  for (auto _ : st) {
    benchmark::DoNotOptimize(exact.state_at(times[i++ % kN]));
  }
}

void BM_ExactStateAtTennisRacket(benchmark::State& st) {
  run_state_at(st, racket(), racket_start());
}
BENCHMARK(BM_ExactStateAtTennisRacket);

void BM_ExactStateAtLargestAxis(benchmark::State& st) {
  State s;
  s.omega_body = Vec3(0.3, 1.0, 0.9);
  run_state_at(st, RigidBody::from_principal_moments(Vec3(1.0, 1.6, 2.3)), s);
}
BENCHMARK(BM_ExactStateAtLargestAxis);

void BM_ExactStateAtNonDiagonal(benchmark::State& st) {
  const Mat3 Q = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  State s;
  s.omega_body = Vec3(0.3, 1.0, 0.9);
  run_state_at(st, RigidBody::from_inertia(Q * Vec3(1.0, 1.6, 2.3).asDiagonal() * Q.transpose()), s);
}
BENCHMARK(BM_ExactStateAtNonDiagonal);

void BM_ExactStateAtAxisymmetric(benchmark::State& st) {
  State s;
  s.omega_body = Vec3(1.0, 0.5, -2.0);
  run_state_at(st, RigidBody::from_principal_moments(Vec3(1.0, 1.0, 1.8)), s);
}
BENCHMARK(BM_ExactStateAtAxisymmetric);

void BM_ExactSetUp(benchmark::State& st) {
  const RigidBody body = racket();
  const State s0 = racket_start();
  for (auto _ : st)
    benchmark::DoNotOptimize(ExactFreeBody(body, s0));
}
BENCHMARK(BM_ExactSetUp);

void BM_ExactTennisRacketAt100s(benchmark::State& st) {
  const RigidBody body = racket();
  const State s0 = racket_start();
  for (auto _ : st)
    benchmark::DoNotOptimize(ExactFreeBody(body, s0).state_at(100.0).R_space_body);
}
BENCHMARK(BM_ExactTennisRacketAt100s);

void BM_ExactIntegratorStep(benchmark::State& st) {
  auto integ = poinsot::dynamics::make_exact_integrator(racket(), nullptr);
  State s = racket_start();
  for (auto _ : st) {
    integ->step(s, 1e-3);
    benchmark::DoNotOptimize(s);
  }
}
BENCHMARK(BM_ExactIntegratorStep);

// Arguments spread over [−K, K] for k'² = 10^-e (e = st.range(0)).
std::vector<double> quarter_period_sweep(const poinsot::dynamics::JacobiElliptic& je) {
  std::vector<double> u = random_times(-1.0, 1.0);
  for (double& x : u)
    x *= je.complete();
  return u;
}

void BM_JacobiElliptic(benchmark::State& st) {
  const double kc2 = std::pow(10.0, -static_cast<double>(st.range(0)));
  const poinsot::dynamics::JacobiElliptic je(1.0 - kc2, kc2);
  const std::vector<double> u = quarter_period_sweep(je);
  std::size_t i = 0;
  double sn = 0.0, cn = 0.0, dn = 0.0;
  for (auto _ : st) {
    je.evaluate(u[i++ % kN], sn, cn, dn);
    benchmark::DoNotOptimize(sn + cn + dn);
  }
}
BENCHMARK(BM_JacobiElliptic)->Arg(0)->Arg(1)->Arg(4)->Arg(10);

void BM_BoostJacobiElliptic(benchmark::State& st) {
  const double kc2 = std::pow(10.0, -static_cast<double>(st.range(0)));
  const std::vector<double> u = quarter_period_sweep(poinsot::dynamics::JacobiElliptic(1.0 - kc2, kc2));
  const double k = std::sqrt(1.0 - kc2);
  std::size_t i = 0;
  double cn = 0.0, dn = 0.0;
  for (auto _ : st) {
    const double sn = boost::math::jacobi_elliptic(k, u[i++ % kN], &cn, &dn);
    benchmark::DoNotOptimize(sn + cn + dn);
  }
}
BENCHMARK(BM_BoostJacobiElliptic)->Arg(0)->Arg(1)->Arg(4)->Arg(10);

void BM_TopMotion(benchmark::State& st) {
  poinsot::dynamics::HeavyTop top;
  top.I1 = 0.010625;
  top.I3 = 0.00125;
  top.mass = 1.0;
  top.length = 0.1;
  for (auto _ : st)
    benchmark::DoNotOptimize(poinsot::dynamics::top_motion(top, 1.0, 0.0, 0.0, 400.0));
}
BENCHMARK(BM_TopMotion);

}  // namespace
