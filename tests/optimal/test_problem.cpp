#include "poinsot/optimal/problem.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

// Throws InvalidInput whose one-line message contains `needle`.
void expect_invalid(const ReorientationProblem& p, const std::string& needle) {
  POINSOT_EXPECT_THROWS_MESSAGE(validate(p), InvalidInput, needle);
}

TEST(Problem, ValidProblemsPass) {
  EXPECT_NO_THROW(validate(testing::betts_problem()));
  EXPECT_NO_THROW(validate(testing::sphere_energy_problem(1.0, 1.0, Vec3::UnitZ(), 5.0)));
}

TEST(Problem, RejectsEachBadField) {
  auto p = testing::betts_problem();
  p.inertia_body = Vec3(1.0, 1.0, 5.0).asDiagonal();  // triangle inequality violated
  expect_invalid(p, "optimal_control.inertia");
  p = testing::betts_problem();
  p.torque_max[1] = 0.0;
  expect_invalid(p, "optimal_control.torque_max");
  p = testing::betts_problem();
  p.rate_max = -1.0;
  expect_invalid(p, "optimal_control.rate_max");
  p = testing::betts_problem();
  p.omega_initial = Vec3(0.6, 0.0, 0.0);  // above the rate bound 0.5
  expect_invalid(p, "is below |omega_initial|");
  p = testing::betts_problem();
  p.attitude_final = Quat(1.0, 1.0, 0.0, 0.0);
  expect_invalid(p, "final attitude");
  p = testing::betts_problem();
  p.energy_weight = 1e-3;  // only for the regularised objective
  expect_invalid(p, "energy_weight");
  p.objective = Objective::minimum_time_regularised;
  p.energy_weight = -1.0;
  expect_invalid(p, "energy_weight");
  EXPECT_THROW(parse_objective("fastest"), InvalidInput);
  EXPECT_EQ(parse_objective("minimum_energy"), Objective::minimum_energy);
}

// The lower bound on the duration: for a sphere J = j I at rest, ‖L‖ ≤ ū min(t, T − t) gives
// Θ ≤ ū T²/(4 j), i.e. T ≥ 2√(Θ j/ū): exactly the eigenaxis time with a norm bound.
TEST(Problem, MinimumDurationBoundIsTheNormBoundEigenaxisTime) {
  ReorientationProblem p;
  p.inertia_body = 3.0 * Mat3::Identity();
  p.bound = TorqueBound::norm;
  p.torque_max = Vec3(2.0, 0.0, 0.0);
  p.attitude_final = Quat(Eigen::AngleAxisd(2.5, Vec3(1, 1, 0).normalized()));
  EXPECT_NEAR(minimum_duration_bound(p), 2.0 * std::sqrt(2.5 * 3.0 / 2.0), 1e-10);
}

TEST(Problem, RejectsAMinimumEnergyTimeTooShortForTheBounds) {
  auto p = testing::sphere_energy_problem(1.0, std::numbers::pi, Vec3::UnitX(), 0.5);
  p.torque_max = Vec3::Ones();  // per-axis 1 N·m: ū = √3, T ≥ 2√(π/√3) ≈ 2.69 s
  expect_invalid(p, "optimal_control.final_time: 0.5 s is too short");
  p.final_time = -1.0;
  expect_invalid(p, "optimal_control.final_time");
}

}  // namespace
}  // namespace poinsot::optimal
