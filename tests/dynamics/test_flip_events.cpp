// FlipDetector: the component e2ᵀJω and its rate against their definitions (rate against a finite
// difference along a dop853 reference), the Hermite root against a cubic with known roots, TOMS 748 against
// sin, and no intermediate axis for symmetric bodies.
#include "poinsot/dynamics/flip_events.hpp"

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::FlipDetector;

TEST(FlipDetector, ComponentIsTheIntermediateMomentumInThePrincipalFrame) {
  // Body frame rotated by Q from the principal frame: J = Q diag(1, 2, 3) Qᵀ, e2 = ±Q e2.
  const Mat3 Q = so3::exp(Vec3(0.2, 0.5, -0.3));
  const RigidBody body = RigidBody::from_inertia(Q * Vec3(1.0, 2.0, 3.0).asDiagonal() * Q.transpose());
  const FlipDetector d(body, TorqueModel::none());
  ASSERT_TRUE(d.applicable());
  State s;
  s.omega_body = Q * Vec3(0.3, -0.7, 0.2);
  EXPECT_NEAR(std::abs(d.component(s)), 2.0 * 0.7, 1e-14);
}

TEST(FlipDetector, RateIsTheDerivativeOfTheComponent) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
  const auto tau = TorqueModel::constant_space(Vec3(0.2, -0.4, 0.1));
  const FlipDetector d(body, tau);
  State s0;
  s0.R_space_body = so3::exp(Vec3(0.1, 0.2, 0.3));
  s0.omega_body = Vec3(1.0, 0.6, -0.8);
  const double h = 1e-4;
  const State a = reference(body, tau, s0, 1.0 - h);
  const State b = reference(body, tau, s0, 1.0 + h);
  const State m = reference(body, tau, s0, 1.0);
  // Central difference: error h²/6·s⃛ ~ 1e-9, plus the reference's 1e-13/h.
  EXPECT_NEAR(d.rate(m), (d.component(b) - d.component(a)) / (2 * h), 1e-7);
}

TEST(FlipDetector, HermiteRootOfAKnownCubic) {
  // s(t) = (t − 0.3)(t + 2)(t − 5): a cubic is its own Hermite interpolant, so the root is 0.3.
  const auto s = [](double t) { return (t - 0.3) * (t + 2) * (t - 5); };
  const auto ds = [](double t) { return (t + 2) * (t - 5) + (t - 0.3) * (t - 5) + (t - 0.3) * (t + 2); };
  EXPECT_NEAR(FlipDetector::hermite_root(0.0, 1.0, s(0.0), s(1.0), ds(0.0), ds(1.0)), 0.3, 1e-15);
  EXPECT_NEAR(FlipDetector::hermite_root(-1.0, 2.0, s(-1.0), s(2.0), ds(-1.0), ds(2.0)), 0.3, 1e-15);
}

TEST(FlipDetector, LocatesASignChangeToFullPrecision) {
  const auto g = [](double t, const void*) { return std::sin(t); };
  EXPECT_NEAR(dynamics::locate_sign_change(g, nullptr, 3.0, 3.5, std::sin(3.0), std::sin(3.5)), M_PI, 1e-15);
  EXPECT_TRUE(FlipDetector::sign_change(1.0, -1.0));
  EXPECT_TRUE(FlipDetector::sign_change(-1.0, 0.0));
  EXPECT_FALSE(FlipDetector::sign_change(0.0, 1.0));  // counted once, when s reached 0
  EXPECT_FALSE(FlipDetector::sign_change(2.0, 1.0));
}

TEST(FlipDetector, NotApplicableWithoutAnIntermediateAxis) {
  EXPECT_FALSE(
      FlipDetector(RigidBody::from_principal_moments(Vec3(1, 1, 1.5)), TorqueModel::none()).applicable());
  EXPECT_FALSE(
      FlipDetector(RigidBody::from_principal_moments(Vec3(1, 2, 2)), TorqueModel::none()).applicable());
  EXPECT_TRUE(
      FlipDetector(RigidBody::from_principal_moments(Vec3(1, 2, 2.5)), TorqueModel::none()).applicable());
}

}  // namespace
}  // namespace poinsot::test
