// The scenario loop (multibody::simulate): the rows it hands over, checked on the compound pendulum example
// against the period of the large-amplitude pendulum; its measurements, stop and failure. The files of a run
// are tested in tests/io/run/test_multibody_run.cpp.
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "poinsot/core/error.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

/// examples/multibody/compound_pendulum.toml built directly: a rod (1 kg, 1 m, radius 1 cm, along body x)
/// hinged at one end about space y, released 0.3 rad from the vertical (the file is read in tests/io).
Scenario compound_pendulum() {
  const double m = 1, l = 1, r = 0.01, th = 0.3;
  Scenario sc;
  sc.system.add_body("rod", m, Vec3(m * l * l / 12, m * r * r / 4, m * r * r / 4).asDiagonal());
  sc.system.set_gravity(Vec3(0, 0, -9.81));
  BodyState b;
  b.R_space_body = Eigen::AngleAxisd(std::numbers::pi / 2 + th, Vec3::UnitY()).toRotationMatrix();
  b.x_space = b.R_space_body * Vec3(l / 2, 0, 0);  // the pivot at the origin
  sc.initial.bodies.push_back(b);
  sc.system.add_hinge("pivot", 0, Vec3(-l / 2, 0, 0), Vec3::UnitY(), kWorld, Vec3::Zero(), Vec3::UnitY());
  sc.dt = 1e-3;
  return sc;
}

/// Every row simulate() hands over, in order.
std::vector<State> rows_of(const Scenario& sc, RunSummary* summary = nullptr) {
  std::vector<State> rows;
  const RunSummary s = simulate(sc, [&](const State& st) {
    rows.push_back(st);
    return true;
  });
  if (summary != nullptr) *summary = s;
  return rows;
}

TEST(Run, CompoundPendulumExampleHasTheTextbookPeriod) {
  // The example starts at 0.3 rad: the period is T0 (1 + θ0²/16 + 11 θ0⁴/3072 + ...) (Jacobi elliptic
  // series), 2π √(I/(m g d)) (1.005653...) — checked here to 1e-4 with the first crossing of the bottom.
  Scenario sc = compound_pendulum();
  sc.duration = 1.0;
  sc.output_every = 1;
  RunSummary s;
  const std::vector<State> rows = rows_of(sc, &s);
  ASSERT_EQ(rows.size(), 1001u);
  double crossing = -1;
  for (std::size_t k = 1; k < rows.size() && crossing < 0; ++k) {
    const double t_prev = rows[k - 1].time, x_prev = rows[k - 1].bodies[0].x_space.x();
    const double t = rows[k].time, x = rows[k].bodies[0].x_space.x();
    if (x_prev < 0 && x >= 0) crossing = t_prev + (t - t_prev) * (-x_prev) / (x - x_prev);
  }
  const double m = 1, l = 1, r = 0.01, g = 9.81, th = 0.3;
  const double T0 = 2 * std::numbers::pi * std::sqrt((m * l * l / 3 + m * r * r / 4) / (m * g * l / 2));
  const double T = T0 * (1 + th * th / 16 + 11 * std::pow(th, 4) / 3072);
  EXPECT_NEAR(crossing, T / 4, 1e-4 * T);  // from −0.3 rad to the bottom: a quarter period
  EXPECT_EQ(s.steps, 1000);
  EXPECT_FALSE(s.interrupted);
  EXPECT_TRUE(s.failure.empty());
  EXPECT_EQ(s.final_state.time, rows.back().time);
  EXPECT_EQ(s.final_state.bodies[0].x_space, rows.back().bodies[0].x_space);
}

TEST(Run, ProjectedRk4RunsTheSameScenarioToFourthOrder) {
  // The same pendulum with method = rk4: the joint holds, and the energy error is O(h⁴) against RATTLE's
  // O(h²) (measured by `poinsot run examples/multibody/compound_pendulum.toml --t-end 1 [--method rk4]`:
  // 5.8e-13 J against 8.2e-7 J at h = 1e-3; the pendulum's energy is m g l/2 (1 − cos 0.3) ≈ 0.22 J above the
  // bottom).
  Scenario sc = compound_pendulum();
  sc.duration = 1.0;
  const RunSummary rattle = simulate(sc);
  sc.method = MultibodyMethod::projected_rk4;
  const RunSummary rk4 = simulate(sc);
  EXPECT_EQ(rk4.kkt_method, KktMethod::tree);  // a hinge: Baraff's tree order
  EXPECT_GT(rk4.mean_newton_iterations, 0.0);  // the joint projections were counted
  EXPECT_LT(rk4.max_joint_gap, 2e-13);
  EXPECT_LT(rk4.max_joint_angle, 1.5e-13);
  EXPECT_LT(rk4.max_energy_error, 1e-3 * rattle.max_energy_error);
  EXPECT_GT(rattle.max_energy_error,
            1e-8);  // RATTLE's error is well above round-off: the ratio means something
}

TEST(Run, SampleTimesAreExactMultiplesOfTheStep) {
  // dt = 0.01 s has no exact binary form: adding it 50 times gives 0.5000000000000002, not 0.5.
  Scenario sc = compound_pendulum();
  sc.dt = 0.01;
  sc.duration = 0.5;
  sc.output_every = 1;
  const std::vector<State> rows = rows_of(sc);
  ASSERT_EQ(rows.size(), 51u);
  for (std::size_t k = 0; k < rows.size(); ++k)
    EXPECT_EQ(rows[k].time, static_cast<double>(k) * 0.01) << "row " << k;
  EXPECT_EQ(rows.back().time, 0.5);
}

TEST(Run, RowsAreEveryOutputEveryStepsAndTheLast) {
  Scenario sc = compound_pendulum();
  sc.duration = 0.503;
  sc.output_every = 7;
  const std::vector<State> rows = rows_of(sc);
  ASSERT_EQ(rows.size(), 1u + 503u / 7u + 1u);  // t0, every 7th step, the 503rd
  EXPECT_EQ(rows[1].time, 7 * sc.dt);
  EXPECT_EQ(rows.back().time, 503 * sc.dt);
}

TEST(Run, ObserverStopsTheRunAtItsRow) {
  // The observer says stop at the third row (t = 2 × 5 steps): the loop ends there, marked interrupted, its
  // measurements taken over the 10 steps it made.
  Scenario sc = compound_pendulum();
  sc.output_every = 5;
  int calls = 0;
  const RunSummary s = simulate(sc, [&](const State&) { return ++calls < 3; });
  EXPECT_EQ(calls, 3);
  EXPECT_TRUE(s.interrupted);
  EXPECT_EQ(s.steps, 10);
  EXPECT_EQ(s.final_state.time, 10 * sc.dt);
  EXPECT_GT(s.max_energy_error, 0.0);
  // Stopping at the last row is no interruption: the run was complete.
  calls = 0;
  sc.duration = 10 * sc.dt;
  EXPECT_FALSE(simulate(sc, [&](const State&) { return ++calls < 3; }).interrupted);
}

TEST(Run, FailureIsRecordedWithTheMeasurementsSoFar) {
  // A spin far too fast for the step: h|ω| ≥ 1 stops the run before its first output row with
  // ComputationFailed, whose message the summary keeps; the observer saw the initial row only, and the final
  // time is the last completed step's.
  Scenario sc;
  sc.system.add_body_from_inertia("a", 1.0, Vec3(1, 2, 3).asDiagonal());
  sc.initial.bodies.resize(1);
  sc.initial.bodies[0].omega_body = Vec3(0, 0, 20);
  sc.dt = 0.1;
  sc.duration = 1.0;
  RunSummary s;
  const std::vector<State> rows = rows_of(sc, &s);
  EXPECT_EQ(rows.size(), 1u);
  EXPECT_FALSE(s.failure.empty());
  EXPECT_LT(s.steps, sc.output_every);
  EXPECT_EQ(s.final_state.time, static_cast<double>(s.steps) * sc.dt);
  EXPECT_EQ(s.energy_initial, 600.0);  // ½ J₃ ω₃² = ½ · 3 · 20² J
}

}  // namespace
}  // namespace poinsot::multibody
