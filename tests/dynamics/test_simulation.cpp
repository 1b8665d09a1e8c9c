// simulate: samples on the sample times, early stop by the observer, invariant tracking, the intermediate-
// axis flips against the closed-form interval 2K(k)/ω_p (K(k) from Boost.Math as an independent oracle),
// failures reported with time, step and cause, and no allocation per step.
#include "poinsot/dynamics/simulation.hpp"

#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <boost/math/special_functions/ellint_1.hpp>

#include "dynamics_test_util.hpp"
#include "poinsot/dynamics/dlm.hpp"
#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/dynamics/rk4.hpp"
#include "poinsot_test.hpp"

#include "allocation_counter.hpp"

namespace poinsot::test {
namespace {

using dynamics::make_integrator;
using dynamics::simulate;
using dynamics::SimulationOptions;

const RigidBody kRacket = RigidBody::from_principal_moments(Vec3(0.00121, 0.01638, 0.01748));  // kg·m²

State racket_state() {
  State s;
  s.omega_body = Vec3(0.01, 2.0, 0.01);  // rad/s, mostly about the intermediate axis
  return s;
}

/// The interval between flips 2K(k)/ω_p for I1 < I2 < I3 (Landau & Lifshitz, Mechanics §37), with K from
/// Boost.Math (independent of the library's own theory).
double flip_interval_theory(const Vec3& I, const Vec3& w) {
  const double E2 = I.dot(w.cwiseProduct(w));         // 2T
  const double L2 = I.cwiseProduct(w).squaredNorm();  // |L|²
  double wp = 0.0, k2 = 0.0;
  if (L2 > E2 * I[1]) {
    wp = std::sqrt((I[2] - I[1]) * (L2 - E2 * I[0]) / (I[0] * I[1] * I[2]));
    k2 = (I[1] - I[0]) * (E2 * I[2] - L2) / ((I[2] - I[1]) * (L2 - E2 * I[0]));
  } else {
    wp = std::sqrt((I[1] - I[0]) * (E2 * I[2] - L2) / (I[0] * I[1] * I[2]));
    k2 = (I[2] - I[1]) * (L2 - E2 * I[0]) / ((I[1] - I[0]) * (E2 * I[2] - L2));
  }
  return 2.0 * boost::math::ellint_1(std::sqrt(k2)) / wp;
}

IntegratorOptions tight(double tol, double dt) {
  IntegratorOptions o;
  o.rtol = tol;
  o.atol = tol;
  o.dt = dt;
  return o;
}

TEST(Simulation, FixedStepSamplesLandOnTheSampleTimes) {
  auto rk4 = make_integrator("rk4", kBody, TorqueModel::none(), tight(1e-10, 0.003));
  SimulationOptions o;
  o.t_end = 0.105;
  o.sample_dt = 0.01;
  std::vector<double> times;
  std::vector<State> samples;
  const auto r = simulate(kBody, TorqueModel::none(), tumbling(), *rk4, o, [&](const State& s) {
    times.push_back(s.time);
    samples.push_back(s);
    return true;
  });
  ASSERT_EQ(times.size(), 12u);  // 0, 0.01, ..., 0.1 and t_end
  for (std::size_t i = 0; i + 1 < times.size(); ++i)
    EXPECT_EQ(times[i], 0.01 * static_cast<double>(i));
  EXPECT_EQ(times.back(), 0.105);
  EXPECT_EQ(r.steps, 10 * 4 + 2);  // each 0.01 s interval cut into 4 steps of 2.5 ms ≤ 3 ms; 5 ms into 2
  // Samples are states of the method at those times: compare with stepping by hand.
  dynamics::Rk4Integrator by_hand(kBody, TorqueModel::none());
  const State s = run_fixed(by_hand, tumbling(), 0.05, 20);
  EXPECT_LT(max_abs_diff(samples[5].omega_body, s.omega_body), 1e-14);
  EXPECT_FALSE(r.interrupted);
  EXPECT_EQ(r.final_state.time, 0.105);
}

TEST(Simulation, AdaptiveSamplesComeFromTheDenseOutput) {
  auto m = make_integrator("dop853", kBody, TorqueModel::none(), tight(1e-11, 1.0));
  SimulationOptions o;
  o.t_end = 5.0;
  o.sample_dt = 0.1;
  double worst = 0.0;
  int count = 0;
  const auto r = simulate(kBody, TorqueModel::none(), tumbling(), *m, o, [&](const State& s) {
    EXPECT_NEAR(s.time, 0.1 * count, 1e-12);
    ++count;
    if (count % 7 == 0)
      worst = std::max(worst, state_error(s, reference(kBody, TorqueModel::none(), tumbling(), s.time)));
    return true;
  });
  EXPECT_EQ(count, 51);
  EXPECT_LT(r.steps, 50);  // large steps: the samples are interpolated, not stepped to
  EXPECT_LT(worst, 30 * 1e-11);
  EXPECT_EQ(r.final_state.time, 5.0);
}

// The adaptive methods' largest step is IntegratorOptions::max_step, by default none: on the tennis racket of
// examples/tennis_racket.toml (100 s, 36 flips), with dt = 1e-3 and the default tolerances, the tolerance
// alone sets the steps (dop853 1 942, dopri5 14 931, where max_step = dt takes 100 000), and the samples
// (dense output) agree with the closed form (ExactFreeBody) as closely as the steps capped at dt do. The
// global error (state_error) is the tolerance (1e-10 per step) amplified by the passages near the
// separatrix: measured 8.2e-8 (dop853) and 3.6e-7 (dopri5) uncapped, 9.1e-8 and 5.7e-8 capped at dt; the
// bound 3e-6 is about ten times the worst of them.
TEST(Simulation, AdaptiveStepsAreSetByTheToleranceNotByDt) {
  State s0;
  s0.omega_body = Vec3(0.05, 6.2832, 0.05);  // rad/s
  const dynamics::ExactFreeBody exact(kRacket, s0);
  SimulationOptions o;
  o.t_end = 100.0;
  o.sample_dt = 0.005;
  o.locate_flips = false;
  const auto run = [&](const std::string& method, double max_step, double& worst) {
    IntegratorOptions io;  // dt = 1e-3, rtol = 1e-10, atol = 1e-12
    io.max_step = max_step;
    auto m = make_integrator(method, kRacket, TorqueModel::none(), io);
    int count = 0;
    worst = 0.0;
    const auto r = simulate(kRacket, TorqueModel::none(), s0, *m, o, [&](const State& s) {
      if (count++ % 50 == 0) worst = std::max(worst, state_error(s, exact.state_at(s.time)));
      return true;
    });
    EXPECT_EQ(count, 20001) << method;
    return r.steps;
  };
  for (const std::string method : {"dopri5", "dop853"}) {
    double free_error = 0.0, capped_error = 0.0;
    const long long free_steps = run(method, std::numeric_limits<double>::infinity(), free_error);
    const long long capped_steps = run(method, 1e-3, capped_error);
    EXPECT_EQ(capped_steps, 100000) << method;  // every step at its cap: the tolerance asks for more
    EXPECT_LT(free_steps, capped_steps / 5) << method;
    EXPECT_LT(free_error, 3e-6) << method;
    EXPECT_LT(capped_error, 3e-6) << method;
  }
}

TEST(Simulation, ObserverCanStopTheRun) {
  auto m = make_integrator("dlm", kBody, TorqueModel::none(), tight(1e-10, 0.001));
  SimulationOptions o;
  o.t_end = 10.0;
  o.sample_dt = 0.1;
  int count = 0;
  const auto r =
      simulate(kBody, TorqueModel::none(), tumbling(), *m, o, [&](const State&) { return ++count < 3; });
  EXPECT_TRUE(r.interrupted);
  EXPECT_EQ(count, 3);
  EXPECT_NEAR(r.final_state.time, 0.2, 1e-15);
}

TEST(Simulation, TracksTheInvariantErrors) {
  SimulationOptions o;
  o.t_end = 20.0;
  o.sample_dt = 0.5;
  auto dlm = make_integrator("dlm", kBody, TorqueModel::none(), tight(1e-10, 0.01));
  const auto a = simulate(kBody, TorqueModel::none(), tumbling(), *dlm, o);
  EXPECT_LT(a.errors.L_space_rel_max, 1e-13);    // conserved by every sub-flow
  EXPECT_LT(a.errors.orthogonality_max, 1e-13);  // round-off of 2000 steps of planar rotations
  EXPECT_GT(a.errors.energy_rel_max, 1e-8);      // O(h²) oscillation, visible
  EXPECT_LT(a.errors.energy_rel_max, 1e-3);
  // The energy error recorded is the one measured directly at the end (a lower bound of the max).
  const double E0 = dynamics::kinetic_energy(kBody, tumbling());
  EXPECT_GE(a.errors.energy_rel_max, std::abs(dynamics::kinetic_energy(kBody, a.final_state) - E0) / E0);
  // With a torque that is not conservative, L and E are not invariants and are not tracked.
  const auto tau = TorqueModel::constant_body(Vec3(0.1, 0, 0));
  auto rk4 = make_integrator("rk4", kBody, tau, tight(1e-10, 0.01));
  const auto b = simulate(kBody, tau, tumbling(), *rk4, o);
  EXPECT_EQ(b.errors.L_space_rel_max, 0.0);
  EXPECT_EQ(b.errors.energy_rel_max, 0.0);
}

TEST(Simulation, HeavyTopTotalEnergyIsTracked) {
  const RigidBody top =
      RigidBody::from_principal_moments(Vec3(0.002, 0.002, 0.004)).with_pivot(1.0, Vec3(0, 0, 0.1));
  const Vec3 g(0, 0, -9.81);
  const auto gravity = TorqueModel::gravity(top, g);
  State s;
  s.R_space_body = so3::exp(Vec3(M_PI / 3, 0, 0));
  s.omega_body = Vec3(0, 0, 50.0);
  SimulationOptions o;
  o.t_end = 2.0;
  o.sample_dt = 0.05;
  auto rattle = make_integrator("rattle", top, gravity, tight(1e-10, 5e-4));
  const auto r = simulate(top, gravity, s, *rattle, o);
  EXPECT_GT(r.errors.energy_rel_max, 0.0);
  EXPECT_LT(r.errors.energy_rel_max, 1e-4);  // O(h²) bounded oscillation at h = 0.5 ms
  EXPECT_EQ(r.errors.L_space_rel_max, 0.0);  // not an invariant under gravity
}

TEST(Simulation, FlipIntervalsFromDop853MatchTheClosedForm) {
  // The tennis racket, ω0 = (0.01, 2, 0.01) rad/s (near the separatrix: k² = 1 − 1.3e-6), 100 s.
  const double theory = flip_interval_theory(kRacket.principal_moments(), racket_state().omega_body);
  auto m = make_integrator("dop853", kRacket, TorqueModel::none(), tight(1e-13, 1.0));
  SimulationOptions o;
  o.t_end = 100.0;
  o.sample_dt = 1.0;
  const auto r = simulate(kRacket, TorqueModel::none(), racket_state(), *m, o);
  ASSERT_GE(r.flip_times.size(), 10u);
  std::printf("racket: %zu flips in 100 s, interval theory %.12g s\n", r.flip_times.size(), theory);
  for (std::size_t i = 1; i < r.flip_times.size(); ++i) {
    // Flip times from the order-7 dense output at rtol = 1e-13; the near-separatrix motion amplifies the
    // state error into the flip time by ~|ln(1 − k²)|, still far below 1e-8 of the interval.
    EXPECT_NEAR((r.flip_times[i] - r.flip_times[i - 1]) / theory, 1.0, 1e-8) << "flip " << i;
  }
}

TEST(Simulation, FlipsFromFixedStepMethodsAgreeWithDop853) {
  auto ref = make_integrator("dop853", kRacket, TorqueModel::none(), tight(1e-12, 1.0));
  SimulationOptions o;
  o.t_end = 20.0;
  o.sample_dt = 1.0;
  const auto r0 = simulate(kRacket, TorqueModel::none(), racket_state(), *ref, o);
  ASSERT_GE(r0.flip_times.size(), 2u);
  for (const char* name : {"rk4", "dlm", "rattle"}) {
    auto m = make_integrator(name, kRacket, TorqueModel::none(), tight(1e-10, 2e-3));
    const auto r = simulate(kRacket, TorqueModel::none(), racket_state(), *m, o);
    ASSERT_EQ(r.flip_times.size(), r0.flip_times.size()) << name;
    for (std::size_t i = 0; i < r.flip_times.size(); ++i) {
      // h = 2 ms, hω = 4e-3: the order-2 methods shift the flips by O(h²) relative, amplified near the
      // separatrix; rk4 by O(h⁴). The Hermite interpolant adds O(h⁴).
      EXPECT_NEAR(r.flip_times[i], r0.flip_times[i], 1e-3 * r0.flip_times[i]) << name << " flip " << i;
    }
  }
}

TEST(Simulation, ExactMethodRunsThroughTheDriver) {
  auto exact = make_integrator("exact", kRacket, TorqueModel::none());
  SimulationOptions o;
  o.t_end = 30.0;
  o.sample_dt = 0.5;
  const auto r = simulate(kRacket, TorqueModel::none(), racket_state(), *exact, o);
  auto ref = make_integrator("dop853", kRacket, TorqueModel::none(), tight(1e-13, 1.0));
  const auto r0 = simulate(kRacket, TorqueModel::none(), racket_state(), *ref, o);
  EXPECT_LT(state_error(r.final_state, r0.final_state), 1e-9);
  ASSERT_EQ(r.flip_times.size(), r0.flip_times.size());
  for (std::size_t i = 0; i < r.flip_times.size(); ++i)
    EXPECT_NEAR(r.flip_times[i], r0.flip_times[i], 1e-8 * r0.flip_times[i]);
}

TEST(Simulation, NonFiniteStateStopsWithTimeStepAndCause) {
  const auto bad = TorqueModel::callback(
      [](double t, const Mat3&, const Vec3&) {
        return t > 0.5 ? Vec3::Constant(std::numeric_limits<double>::infinity()) : Vec3::Zero();
      },
      false, "infinite after 0.5 s");
  auto rk4 = make_integrator("rk4", kBody, bad, tight(1e-10, 0.01));
  SimulationOptions o;
  o.t_end = 1.0;
  o.sample_dt = 0.1;
  // The step from 0.49 to 0.5 s evaluates t > 0.5: step 50.
  POINSOT_EXPECT_THROWS_MESSAGE(simulate(kBody, bad, tumbling(), *rk4, o), ComputationFailed, "non-finite",
                                "step 50 ", "t = 0.5");
  auto dopri = make_integrator("dopri5", kBody, bad, tight(1e-8, 0.01));
  POINSOT_EXPECT_THROWS_MESSAGE(simulate(kBody, bad, tumbling(), *dopri, o), ComputationFailed,
                                "dopri5 failed at step", "too small");
}

// A method's own advance (rk4: n steps on its quaternion, one conversion) and the default advance (n calls of
// step) give the driver the same steps: the same final state, flip times and energy error, bit for bit.
TEST(Simulation, OwnAdvanceAndStepByStepAdvanceGiveTheSameRun) {
  // rk4 behind the default Integrator::advance: one step() per step.
  class StepByStep final : public dynamics::Integrator {
   public:
    explicit StepByStep(std::unique_ptr<dynamics::Integrator> m) : m_(std::move(m)) {}
    std::string_view name() const override { return m_->name(); }
    int order() const override { return m_->order(); }
    double nominal_step() const override { return m_->nominal_step(); }
    dynamics::StepResult step(State& s, double dt) override { return m_->step(s, dt); }

   private:
    std::unique_ptr<dynamics::Integrator> m_;
  };
  SimulationOptions o;
  o.t_end = 20.0;
  o.sample_dt = 0.25;
  auto own = make_integrator("rk4", kRacket, TorqueModel::none(), tight(1e-10, 2e-3));
  StepByStep by_step(make_integrator("rk4", kRacket, TorqueModel::none(), tight(1e-10, 2e-3)));
  const auto a = simulate(kRacket, TorqueModel::none(), racket_state(), *own, o);
  const auto b = simulate(kRacket, TorqueModel::none(), racket_state(), by_step, o);
  ASSERT_GE(a.flip_times.size(), 2u);
  EXPECT_EQ(a.flip_times, b.flip_times);
  EXPECT_EQ(a.steps, b.steps);
  EXPECT_EQ(a.errors.energy_rel_max, b.errors.energy_rel_max);
  EXPECT_EQ(a.final_state.time, b.final_state.time);
  EXPECT_TRUE(a.final_state.R_space_body == b.final_state.R_space_body);
  EXPECT_TRUE(a.final_state.omega_body == b.final_state.omega_body);
}

TEST(Simulation, NonFiniteStateOfATorqueFreeBodyStopsWithTimeAndStep) {
  // rk4 far beyond its stability limit (h|ω| = 1.7e3): ω overflows within a few steps of the first interval.
  auto rk4 = make_integrator("rk4", kBody, TorqueModel::none(), tight(1e-10, 1.0));
  State s = tumbling();
  s.omega_body = Vec3(1e3, 1e3, -1e3);
  SimulationOptions o;
  o.t_end = 100.0;
  o.sample_dt = 50.0;
  POINSOT_EXPECT_THROWS_MESSAGE(simulate(kBody, TorqueModel::none(), s, *rk4, o), ComputationFailed,
                                "rk4 produced a non-finite state at step ", "t = ");
}

TEST(Simulation, RejectsBadOptions) {
  auto m = make_integrator("rk4", kBody, TorqueModel::none());
  SimulationOptions o;
  o.t_end = 0.0;
  EXPECT_THROW(simulate(kBody, TorqueModel::none(), tumbling(), *m, o), InvalidInput);
  o.t_end = 1.0;
  o.sample_dt = 0.0;
  EXPECT_THROW(simulate(kBody, TorqueModel::none(), tumbling(), *m, o), InvalidInput);
  State bad = tumbling();
  bad.R_space_body(0, 0) += 0.1;
  o.sample_dt = 0.1;
  EXPECT_THROW(simulate(kBody, TorqueModel::none(), bad, *m, o), InvalidInput);
}

TEST(Simulation, AllocatesNothingPerStep) {
  // The same run with 100 and 1000 steps (same samples, no flips) allocates the same number of times.
  const auto count = [](double dt) {
    auto m = make_integrator("rattle", kBody, TorqueModel::constant_space(Vec3(0.1, 0, 0)), tight(1e-10, dt));
    SimulationOptions o;
    o.t_end = 1.0;
    o.sample_dt = 0.25;
    o.locate_flips = false;
    const long long before = allocation_count();
    const auto r = simulate(kBody, TorqueModel::constant_space(Vec3(0.1, 0, 0)), tumbling(), *m, o,
                            [](const State&) { return true; });
    return std::make_pair(allocation_count() - before, r.steps);
  };
  const auto few = count(1e-2);
  const auto many = count(1e-3);
  EXPECT_EQ(few.second, 100);
  EXPECT_EQ(many.second, 1000);
  EXPECT_EQ(few.first, many.first);
  // Each method's own step and dense output allocate nothing: the contract suite,
  // test_integrator_contract.cpp (StepsWithoutAllocating), on every entry of the registry.
}

}  // namespace
}  // namespace poinsot::test
