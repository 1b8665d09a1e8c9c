// Integrators of the dynamics layer, one free body, one core, double precision.
// Run: build/release/bench/bench_dynamics [--benchmark_filter=...]
//
// * BM_Step/<method>: ns per step on the tumbling tennis racket (h = 1 ms; adaptive methods at rtol = atol =
//   1e-10 with their own step, reported per accepted step). BM_OdeintRk4Step is the baseline run in the same
//   process: Boost.Odeint's runge_kutta4 on the same equations (ω and quaternion, no renormalisation, no
//   rotation matrix output).
// * BM_AccuracyAt100s/<method>/<n>: the tennis racket, I = (0.00121, 0.01638, 0.01748) kg·m², ω0 = (0.01, 2,
//   0.01) rad/s (mostly about the intermediate axis; 11 flips in 100 s), R0 = I, integrated to t = 100 s. The
//   counters give the orientation error (rad, angle to the exact solution) and the relative energy error at
//   t = 100 s; the time per iteration is the wall time of the whole run (accuracy per cost).
// * BM_LongRun/<method>: 10⁶ steps at h = 1/200 of the rotation period 2π/|ω0|; counters: max relative
//   energy error, max relative L_space error, ‖RᵀR − I‖_F at the end.
#include <array>
#include <cmath>
#include <memory>

#include <benchmark/benchmark.h>
#include <boost/numeric/odeint.hpp>

#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/projection.hpp"

namespace {
using poinsot::Mat3;
using poinsot::Quat;
using poinsot::Vec3;
using namespace poinsot::dynamics;

const Vec3 kMoments(0.00121, 0.01638, 0.01748);  // kg·m², tennis racket
const Vec3 kOmega0(0.01, 2.0, 0.01);             // rad/s

RigidBody racket() {
  return RigidBody::from_principal_moments(kMoments);
}
State racket_state() {
  State s;
  s.omega_body = kOmega0;
  return s;
}

IntegratorOptions options(double dt, double tol) {
  IntegratorOptions o;
  o.dt = dt;
  o.rtol = tol;
  o.atol = tol;
  return o;
}

const char* const kMethods[] = {"rk4", "dlm", "rattle", "dopri5", "dop853", "exact"};

// ---------------------------------------------------------------------------------------------- per step
void BM_Step(benchmark::State& st) {
  const char* name = kMethods[st.range(0)];
  const bool adaptive = st.range(0) == 3 || st.range(0) == 4;
  auto m = make_integrator(name, racket(), TorqueModel::none(), options(adaptive ? 1.0 : 1e-3, 1e-10));
  State s = racket_state();
  double h = adaptive ? 0.05 : 1e-3;
  for (auto _ : st) {
    const auto r = m->step(s, h);
    if (adaptive) h = r.dt_next;
    benchmark::DoNotOptimize(s);
  }
  st.SetLabel(name);
}
BENCHMARK(BM_Step)->DenseRange(0, 5);

// Boost.Odeint's classical RK4 on the same equations (y = (q, ω)), the baseline.
using Y = std::array<double, 7>;
struct EulerQuaternionRhs {
  double I1, I2, I3;
  void operator()(const Y& y, Y& d, double) const {
    const double w1 = y[4], w2 = y[5], w3 = y[6];
    d[0] = -0.5 * (y[1] * w1 + y[2] * w2 + y[3] * w3);
    d[1] = 0.5 * (y[0] * w1 + y[2] * w3 - y[3] * w2);
    d[2] = 0.5 * (y[0] * w2 + y[3] * w1 - y[1] * w3);
    d[3] = 0.5 * (y[0] * w3 + y[1] * w2 - y[2] * w1);
    d[4] = (I2 - I3) / I1 * w2 * w3;
    d[5] = (I3 - I1) / I2 * w3 * w1;
    d[6] = (I1 - I2) / I3 * w1 * w2;
  }
};

Y odeint_initial() {
  return Y{1, 0, 0, 0, kOmega0.x(), kOmega0.y(), kOmega0.z()};
}

void BM_OdeintRk4Step(benchmark::State& st) {
  boost::numeric::odeint::runge_kutta4<Y> stepper;
  const EulerQuaternionRhs f{kMoments.x(), kMoments.y(), kMoments.z()};
  Y y = odeint_initial();
  double t = 0.0;
  for (auto _ : st) {
    stepper.do_step(f, y, t, 1e-3);
    t += 1e-3;
    benchmark::DoNotOptimize(y);
  }
}
BENCHMARK(BM_OdeintRk4Step);

// rk4 advanced n steps at a time (Integrator::advance, the simulation driver's path for a torque-free body:
// one conversion to a State per n steps), ns per step; beside BM_Step/0 (one step() per step: the state
// checked against the last one produced and converted to R on every step) and BM_OdeintRk4Step. Compare them
// in one process: --benchmark_filter='BM_Step/0$|Rk4Advance|OdeintRk4Step' --benchmark_repetitions=9
// --benchmark_enable_random_interleaving=true.
void BM_Rk4Advance(benchmark::State& st) {
  const long long n = st.range(0);
  auto m = make_integrator("rk4", racket(), TorqueModel::none(), options(1e-3, 1e-10));
  State s = racket_state();
  for (auto _ : st) {
    m->advance(s, 1e-3, n);
    benchmark::DoNotOptimize(s);
  }
  st.SetItemsProcessed(st.iterations() * n);
  st.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(st.iterations() * n),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Rk4Advance)->Arg(10)->Arg(100);

// The simulation driver (dynamics::simulate, what `poinsot run`, Python's simulate and the ensemble's scalar
// path call) on the racket with rk4, h = 1 ms, a sample every 10 ms to an observer that keeps nothing, flips
// located: 10⁴ steps per iteration; the counter is ns per step.
void BM_SimulateRk4(benchmark::State& st) {
  auto m = make_integrator("rk4", racket(), TorqueModel::none(), options(1e-3, 1e-10));
  SimulationOptions o;
  o.t_end = 10.0;
  o.sample_dt = 0.01;
  long long steps = 0;
  for (auto _ : st) {
    const auto r =
        simulate(racket(), TorqueModel::none(), racket_state(), *m, o, [](const State&) { return true; });
    steps += r.steps;
    benchmark::DoNotOptimize(r.final_state);
  }
  st.counters["ns_per_step"] = benchmark::Counter(static_cast<double>(steps),
                                                  benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_SimulateRk4)->Unit(benchmark::kMillisecond);

// ------------------------------------------------------------------------------------- accuracy per cost
State exact_at_100() {
  auto m = make_integrator("exact", racket(), TorqueModel::none());
  State s = racket_state();
  m->step(s, 100.0);
  return s;
}

void report_errors(benchmark::State& st, const Mat3& R, const Vec3& w, long long steps) {
  static const State ref = exact_at_100();
  const RigidBody body = racket();
  State s;
  s.R_space_body = R;
  s.omega_body = w;
  const double E0 = kinetic_energy(body, racket_state());
  st.counters["angle_err_rad"] = poinsot::so3::angle_between(R, ref.R_space_body);
  st.counters["energy_rel_err"] = std::abs(kinetic_energy(body, s) - E0) / E0;
  st.counters["steps"] = static_cast<double>(steps);
}

// range(0): method; range(1): steps (fixed-step methods) or −log10(tol) (adaptive).
void BM_AccuracyAt100s(benchmark::State& st) {
  const char* name = kMethods[st.range(0)];
  const bool adaptive = st.range(0) == 3 || st.range(0) == 4;
  const double tol = std::pow(10.0, -static_cast<double>(st.range(1)));
  const long long n = adaptive ? 0 : st.range(1);
  State s;
  long long steps = 0;
  for (auto _ : st) {
    auto m = make_integrator(name, racket(), TorqueModel::none(),
                             options(adaptive ? 10.0 : 100.0 / static_cast<double>(n), tol));
    s = racket_state();
    steps = 0;
    if (adaptive) {
      double h = 0.05;
      while (s.time < 100.0) {
        const double rem = 100.0 - s.time;
        const auto r = m->step(s, std::min(h, rem));
        h = r.dt_next;
        ++steps;
      }
    } else {
      const double h = 100.0 / static_cast<double>(n);
      for (long long i = 0; i < n; ++i)
        m->step(s, h);
      steps = n;
    }
    benchmark::DoNotOptimize(s);
  }
  report_errors(st, s.R_space_body, s.omega_body, steps);
  st.SetLabel(adaptive ? std::string(name) + " tol=1e-" + std::to_string(st.range(1)) : name);
}
BENCHMARK(BM_AccuracyAt100s)
    ->ArgsProduct({{0}, {10000, 100000, 1000000}})
    ->ArgsProduct({{1, 2}, {10000, 100000, 1000000}})
    ->ArgsProduct({{3, 4}, {6, 9, 12}})
    ->Args({5, 1})
    ->Unit(benchmark::kMicrosecond);

void BM_OdeintRk4AccuracyAt100s(benchmark::State& st) {
  const long long n = st.range(0);
  Y y{};
  for (auto _ : st) {
    boost::numeric::odeint::runge_kutta4<Y> stepper;
    const EulerQuaternionRhs f{kMoments.x(), kMoments.y(), kMoments.z()};
    y = odeint_initial();
    const double h = 100.0 / static_cast<double>(n);
    double t = 0.0;
    for (long long i = 0; i < n; ++i) {
      stepper.do_step(f, y, t, h);
      t += h;
    }
    benchmark::DoNotOptimize(y);
  }
  Quat q(y[0], y[1], y[2], y[3]);
  q.normalize();
  report_errors(st, q.toRotationMatrix(), Vec3(y[4], y[5], y[6]), n);
}
BENCHMARK(BM_OdeintRk4AccuracyAt100s)->Arg(10000)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMicrosecond);

// ------------------------------------------------------------------------------------ 10⁶-step invariants
void BM_LongRun(benchmark::State& st) {
  const char* name = kMethods[st.range(0)];
  const RigidBody body = racket();
  const double h = 2.0 * M_PI / kOmega0.norm() / 200.0;
  const long long n = 1000000;
  double e_max = 0.0, L_max = 0.0, orth = 0.0;
  for (auto _ : st) {
    auto m = make_integrator(name, body, TorqueModel::none(), options(h, 1e-10));
    State s = racket_state();
    const double E0 = kinetic_energy(body, s);
    const Vec3 L0 = angular_momentum_space(body, s);
    e_max = L_max = 0.0;
    for (long long i = 0; i < n; ++i) {
      m->step(s, h);
      if (i % 16 == 0 || i == n - 1) {
        e_max = std::max(e_max, std::abs(kinetic_energy(body, s) - E0) / E0);
        L_max = std::max(L_max, (angular_momentum_space(body, s) - L0).norm() / L0.norm());
      }
    }
    orth = poinsot::so3::orthogonality_error(s.R_space_body);
  }
  st.counters["energy_rel_max"] = e_max;
  st.counters["L_space_rel_max"] = L_max;
  st.counters["orthogonality"] = orth;
  st.SetLabel(name);
}
BENCHMARK(BM_LongRun)->DenseRange(0, 2)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
