// Detection of a top and its predictions (top_prediction.hpp) against values computed here by hand from the
// definitions: the disc top of docs/conventions.md B3 (I3 = M r²/2, I1 = M r²/4 + M l² about the pivot),
// the fast-top formulas M g l/(I3 ω3) and I3 ω3/I1, the sleeping-top threshold 4 I1 M g l/I3², and the free
// symmetric top's precession |L|/I1; the exact heavy-top values are those of top_motion(), tested against a
// direct integration in test_top_theory.cpp.
#include "poinsot/dynamics/top_prediction.hpp"

#include <gtest/gtest.h>
#include <cmath>

#include "poinsot/dynamics/top_theory.hpp"

namespace poinsot::dynamics {
namespace {

constexpr double kM = 1.0, kR = 0.05, kL = 0.1;  // kg, m (disc radius), m (pivot to centre of mass)
const Vec3 kG(0.0, 0.0, -9.81);                  // m/s²

RigidBody disc_on_pivot() {
  return RigidBody::from_principal_moments(Vec3(0.25 * kM * kR * kR, 0.25 * kM * kR * kR, 0.5 * kM * kR * kR))
      .with_pivot(kM, Vec3(0, 0, kL));
}

State tilted(double omega3) {
  State s;
  s.R_space_body = Eigen::AngleAxisd(1.0, Vec3::UnitX()).toRotationMatrix();  // axis 1 rad from the vertical
  s.omega_body = Vec3(0.0, 0.0, omega3);
  return s;
}

TEST(TopPrediction, HeavyDiscTopMatchesTheFormulasByHand) {
  const RigidBody body = disc_on_pivot();
  const double omega3 = 150.0;
  const auto top = predict_top(body, *TorqueModel::gravity(body, kG), kG, tilted(omega3));
  ASSERT_TRUE(top.has_value());
  EXPECT_EQ(top->kind, TopKind::heavy);
  EXPECT_EQ(to_string(top->kind), "heavy top");
  EXPECT_NEAR((top->axis_body - Vec3::UnitZ()).norm(), 0.0, 1e-15);
  EXPECT_NEAR((top->direction_space - Vec3::UnitZ()).norm(), 0.0, 1e-15);
  const double I3 = 0.5 * kM * kR * kR, I1 = 0.25 * kM * kR * kR + kM * kL * kL, mgl = kM * 9.81 * kL;
  EXPECT_NEAR(top->moment_axial, I3, 1e-15);
  EXPECT_NEAR(top->moment_transverse, I1, 1e-15);
  EXPECT_DOUBLE_EQ(top->spin, omega3);
  EXPECT_NEAR(*top->precession_rate_theory, mgl / (I3 * omega3), 1e-12);
  EXPECT_NEAR(*top->nutation_frequency_fast_top, I3 * omega3 / I1, 1e-12);
  EXPECT_EQ(*top->sleeping, omega3 * omega3 > 4.0 * I1 * mgl / (I3 * I3));
  // Symmetric and tilted: the exact quadrature's values are there, and near the fast-top ones at this spin
  // (relative error of order I1 M g l/(I3 ω3)², docs/conventions.md B3).
  const TopMotion m = top_motion(heavy_top_from(body, kG), 1.0, 0.0, 0.0, omega3);
  EXPECT_DOUBLE_EQ(*top->precession_rate_exact, m.mean_precession_rate);
  EXPECT_DOUBLE_EQ(*top->nutation_frequency_theory, m.nutation_frequency);
  EXPECT_DOUBLE_EQ(*top->theta_min_theory, m.theta_min);
  EXPECT_DOUBLE_EQ(*top->theta_max_theory, m.theta_max);
  EXPECT_NEAR(*top->precession_rate_exact / *top->precession_rate_theory, 1.0, 0.05);
}

TEST(TopPrediction, SleepingCriterionOnBothSidesOfTheThreshold) {
  const RigidBody body = disc_on_pivot();
  const double I3 = 0.5 * kM * kR * kR, I1 = 0.25 * kM * kR * kR + kM * kL * kL;
  const double threshold = std::sqrt(4.0 * I1 * kM * 9.81 * kL) / I3;
  const auto torque = TorqueModel::gravity(body, kG);
  EXPECT_TRUE(*predict_top(body, *torque, kG, tilted(1.01 * threshold))->sleeping);
  EXPECT_FALSE(*predict_top(body, *torque, kG, tilted(0.99 * threshold))->sleeping);
}

TEST(TopPrediction, AsymmetricHeavyTopHasOnlyTheFastTopFormulas) {
  const RigidBody body =
      RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5)).with_pivot(1.0, Vec3(0, 0, 0.1));
  const auto top = predict_top(body, *TorqueModel::gravity(body, kG), kG, tilted(20.0));
  ASSERT_TRUE(top.has_value());
  EXPECT_EQ(top->kind, TopKind::heavy);
  EXPECT_TRUE(top->precession_rate_theory.has_value());
  EXPECT_TRUE(top->sleeping.has_value());
  EXPECT_FALSE(top->precession_rate_exact.has_value());
  EXPECT_FALSE(top->theta_min_theory.has_value());
}

TEST(TopPrediction, NotSpinningHasNoFastTopRate) {
  const RigidBody body = disc_on_pivot();
  const auto top = predict_top(body, *TorqueModel::gravity(body, kG), kG, tilted(0.0));
  ASSERT_TRUE(top.has_value());
  EXPECT_FALSE(top->precession_rate_theory.has_value());
  EXPECT_FALSE(top->nutation_frequency_fast_top.has_value());
  EXPECT_FALSE(*top->sleeping);
}

TEST(TopPrediction, FreeSymmetricTopsPrecessAboutLAtLOverI1) {
  for (const Vec3& moments : {Vec3(1.0, 2.0, 2.0), Vec3(1.0, 1.0, 1.5)}) {  // prolate, oblate
    const RigidBody body = RigidBody::from_principal_moments(moments);
    State s;
    s.omega_body = Vec3(0.3, -0.4, 1.2);
    const auto top = predict_top(body, *TorqueModel::none(), Vec3::Zero(), s);
    ASSERT_TRUE(top.has_value());
    EXPECT_EQ(top->kind, TopKind::free_symmetric);
    const int unique = moments[0] == moments[1] ? 2 : 0;
    EXPECT_NEAR(std::abs(top->axis_body[unique]), 1.0, 1e-15);
    const Vec3 L = moments.asDiagonal() * s.omega_body;
    EXPECT_NEAR((top->direction_space - L.normalized()).norm(), 0.0, 1e-15);
    const double I1 = moments[unique == 2 ? 0 : 1];
    EXPECT_NEAR(top->moment_transverse, I1, 1e-15);
    EXPECT_NEAR(top->moment_axial, moments[unique], 1e-15);
    EXPECT_NEAR(*top->precession_rate_theory, L.norm() / I1, 1e-14);
    EXPECT_FALSE(top->sleeping.has_value());
  }
}

TEST(TopPrediction, NeitherKindIsNoTop) {
  State s;
  s.omega_body = Vec3(0.3, -0.4, 1.2);
  const RigidBody asymmetric = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5));
  EXPECT_FALSE(predict_top(asymmetric, *TorqueModel::none(), Vec3::Zero(), s).has_value());
  const RigidBody prolate = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.0));
  EXPECT_FALSE(predict_top(prolate, *TorqueModel::constant_body(Vec3(0, 0, 1)), Vec3::Zero(), s).has_value());
  State rest;
  EXPECT_FALSE(predict_top(prolate, *TorqueModel::none(), Vec3::Zero(), rest).has_value());  // L = 0
  const RigidBody on_com =
      RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.0)).with_pivot(1.0, Vec3::Zero());
  EXPECT_FALSE(is_heavy_top(on_com, true, kG));
  EXPECT_FALSE(is_heavy_top(disc_on_pivot(), true, Vec3::Zero()));
  EXPECT_FALSE(is_heavy_top(disc_on_pivot(), false, kG));
  EXPECT_TRUE(is_heavy_top(disc_on_pivot(), true, kG));
}

}  // namespace
}  // namespace poinsot::dynamics
