// State and its invariants against sums over point masses (T = ½Σm|Ω × x|², L = Σ m x × ẋ, V = −Σ m gᵀx),
// the quaternion view against so3, and validate_state's errors.
#include "poinsot/dynamics/state.hpp"

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot_test.hpp"
#include "point_masses.hpp"

namespace poinsot::test {
namespace {

using dynamics::RigidBody;
using dynamics::State;

const std::vector<PointMass> kPoints = {{1.0, Vec3(0.3, 0.1, -0.2)},
                                        {0.5, Vec3(-0.4, 0.2, 0.1)},
                                        {2.0, Vec3(0.05, -0.3, 0.25)},
                                        {1.5, Vec3(-0.1, -0.05, 0.4)},
                                        {0.7, Vec3(0.2, 0.35, 0.0)}};

TEST(State, InvariantsAgreeWithSumsOverPointMasses) {
  // Treat the points as a body rotating about the origin (a "free body" whose J is about that point).
  const RigidBody body = RigidBody::from_inertia(inertia_about_origin(kPoints));
  State s;
  s.R_space_body = so3::exp(Vec3(0.4, -0.3, 1.1));
  s.omega_body = Vec3(1.5, -0.7, 2.2);
  const Vec3 Omega = s.R_space_body * s.omega_body;
  double T = 0.0;
  Vec3 L = Vec3::Zero();
  for (const auto& p : kPoints) {
    const Vec3 x = s.R_space_body * p.x;
    const Vec3 v = Omega.cross(x);  // ẋ = Ṙ X = R (ω × X) = Ω × x
    T += 0.5 * p.m * v.squaredNorm();
    L += p.m * x.cross(v);
  }
  EXPECT_NEAR(dynamics::kinetic_energy(body, s), T, 1e-14 * T);
  EXPECT_LT(max_abs_diff(dynamics::angular_momentum_space(body, s), L), 1e-14 * L.norm());
  EXPECT_LT(max_abs_diff(dynamics::angular_momentum_body(body, s), Vec3(s.R_space_body.transpose() * L)),
            1e-14 * L.norm());
  EXPECT_LT(max_abs_diff(s.omega_space(), Omega), 1e-15);
}

TEST(State, PotentialEnergyOfATopIsMinusMassTimesGravityDotCentreOfMass) {
  double mass = 0.0;
  Vec3 first = Vec3::Zero();
  for (const auto& p : kPoints) {
    mass += p.m;
    first += p.m * p.x;
  }
  const Vec3 d = first / mass;  // pivot (origin) → centre of mass
  Mat3 J_com =
      inertia_about_origin(kPoints) - mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  const RigidBody top = RigidBody::from_inertia(J_com).with_pivot(mass, d);
  State s;
  s.R_space_body = so3::exp(Vec3(-0.6, 0.2, 0.3));
  s.omega_body = Vec3(0.1, 0.2, 30.0);
  const Vec3 g(0, 0, -9.81);
  double V = 0.0;
  for (const auto& p : kPoints)
    V -= p.m * g.dot(s.R_space_body * p.x);
  EXPECT_NEAR(dynamics::potential_energy(top, s, g), V, 1e-13 * std::abs(V));
  EXPECT_NEAR(dynamics::total_energy(top, s, g), dynamics::kinetic_energy(top, s) + V, 1e-12);
  // A free body has no potential energy.
  EXPECT_EQ(dynamics::potential_energy(RigidBody::from_inertia(J_com), s, g), 0.0);
}

TEST(State, QuaternionViewIsTheCanonicalQuaternionOfR) {
  State s;
  s.R_space_body = random_rotation();
  const Quat q = s.quaternion();
  EXPECT_GE(q.w(), 0.0);
  EXPECT_LT(max_abs_diff(so3::rotation_from_quaternion(q), s.R_space_body), 1e-15);
}

TEST(State, ValidationNamesTheSource) {
  State s;
  EXPECT_NO_THROW(dynamics::validate_state(s, "initial state"));
  s.R_space_body(0, 1) = 0.01;
  POINSOT_EXPECT_THROWS_MESSAGE(dynamics::validate_state(s, "initial state"), InvalidInput,
                                "initial state: R is not a rotation");
  State n;
  n.omega_body.x() = std::nan("");
  EXPECT_THROW(dynamics::validate_state(n, "x"), InvalidInput);
  State reflection;
  reflection.R_space_body = -Mat3::Identity();
  EXPECT_THROW(dynamics::validate_state(reflection, "x"), InvalidInput);
}

}  // namespace
}  // namespace poinsot::test
