#include "poinsot/analysis/multipliers.hpp"

#include <Eigen/Eigenvalues>

#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"
#include "reference_motion.hpp"

namespace poinsot::analysis {
namespace {
using dynamics::RigidBody;
using dynamics::State;
using test::kEps;

// A physical body with a random principal frame: moments drawn so that the triangle inequality holds.
RigidBody random_body() {
  Vec3 m;
  do {
    m = Vec3(test::uniform(0.2, 3.0), test::uniform(0.2, 3.0), test::uniform(0.2, 3.0));
  } while (m[0] + m[1] < m[2] || m[1] + m[2] < m[0] || m[0] + m[2] < m[1]);
  const Mat3 Q = test::random_rotation();
  return RigidBody::from_inertia(Q * m.asDiagonal() * Q.transpose());
}

State random_state(double speed = 2.0) {
  State s;
  s.time = test::uniform(0.0, 5.0);
  s.R_space_body = test::random_rotation();
  s.omega_body = test::random_vector(speed);
  return s;
}

// Λ = Rᵀ R̈ K with R̈ from a central second difference of R along the reference trajectory (RK4 steps of h
// on either side). Truncation h²/12·|R⁗| ~ 1e-9 and round-off 4ε/h² ~ 1e-8 at h = 1e-4 for |ω| ≲ 2 rad/s.
Mat3 lambda_by_finite_differences(const RigidBody& body, const dynamics::TorqueModel* torque,
                                  const State& s) {
  const double h = 1e-4;
  const State plus = test::rk4_step(body, torque, s, h);
  const State minus = test::rk4_step(body, torque, s, -h);
  const Mat3 Rdd = (plus.R_space_body - 2.0 * s.R_space_body + minus.R_space_body) / (h * h);
  return s.R_space_body.transpose() * Rdd * body.poinsot();
}

TEST(Multipliers, EqualsRtRddotKByFiniteDifferencesFreeBody) {
  for (int i = 0; i < 50; ++i) {
    const RigidBody body = random_body();
    const State s = random_state();
    const Mat3 lambda = lambda_from_state(body, s);
    const Mat3 fd = lambda_by_finite_differences(body, nullptr, s);
    EXPECT_LE(test::max_abs_diff(lambda, fd), 1e-6 * std::max(1.0, lambda.norm()));
  }
}

TEST(Multipliers, EqualsRtRddotKByFiniteDifferencesWithTorque) {
  const auto torque = dynamics::TorqueModel::constant_space(Vec3(0.3, -0.7, 1.1));
  for (int i = 0; i < 50; ++i) {
    const RigidBody body = random_body();
    const State s = random_state();
    const Mat3 lambda = lambda_from_state(body, s, torque.get());
    const Mat3 fd = lambda_by_finite_differences(body, torque.get(), s);
    EXPECT_LE(test::max_abs_diff(lambda, fd), 1e-6 * std::max(1.0, lambda.norm()));
    // The skew part is the torque, j(τ_body) (Λ − Λᵀ = j(Jω̇ + ω × Jω)); the state formula has it to
    // round-off.
    const Vec3 tau = torque->torque_body(s.time, s.R_space_body, s.omega_body);
    EXPECT_LE(symmetry_error(lambda, tau), 64 * kEps * std::max(1.0, lambda.norm()));
    EXPECT_GT(symmetry_error(lambda), 0.1);  // without the torque term the matrix is visibly not symmetric
  }
}

TEST(Multipliers, FreeBodyLambdaIsSymmetricWithTraceMinusTwoT) {
  for (int i = 0; i < 1000; ++i) {
    const RigidBody body = random_body();
    const State s = random_state(5.0);
    const Mat3 lambda = lambda_from_state(body, s);
    const double scale = std::max(1.0, lambda.norm());
    EXPECT_LE(symmetry_error(lambda), 64 * kEps * scale);
    EXPECT_NEAR(lambda.trace(), -2.0 * dynamics::kinetic_energy(body, s), 64 * kEps * scale);
  }
}

TEST(Multipliers, TraceIsMinusTwoTUnderTorqueToo) {
  const auto torque = dynamics::TorqueModel::constant_body(Vec3(2.0, -1.0, 0.5));
  for (int i = 0; i < 200; ++i) {
    const RigidBody body = random_body();
    const State s = random_state(3.0);
    const Mat3 lambda = lambda_from_state(body, s, torque.get());
    EXPECT_NEAR(lambda.trace(), -2.0 * dynamics::kinetic_energy(body, s),
                64 * kEps * std::max(1.0, lambda.norm()));
  }
}

TEST(Multipliers, MinusLambdaIsPositiveSemiDefiniteProperty1) {
  // docs/conventions.md C2: max eigenvalue ≤ 0 up to round-off, for physical bodies and plane laminae alike.
  for (int i = 0; i < 2000; ++i) {
    RigidBody body = random_body();
    if (i % 4 == 0) {  // a lamina: I3 = I1 + I2
      const double a = test::uniform(0.2, 2.0), b = test::uniform(0.2, 2.0);
      body = RigidBody::from_principal_moments(Vec3(a, b, a + b));
    }
    const State s = random_state(4.0);
    const Mat3 lambda = lambda_from_state(body, s);
    EXPECT_LE(sorted_eigenvalues(lambda)[2], 32 * kEps * lambda.norm());
  }
}

TEST(Multipliers, SteadySpinAboutAPrincipalAxisHasAZeroEigenvalue) {
  // V ∥ ω is an eigenvector with λ = 0 when ṘV = 0 (docs/conventions.md C2).
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  State s;
  s.omega_body = Vec3(0.0, 1.7, 0.0);
  const Mat3 lambda = lambda_from_state(body, s);
  EXPECT_LE((lambda * s.omega_body).norm(), 8 * kEps * lambda.norm());
  EXPECT_LE(std::abs(sorted_eigenvalues(lambda)[2]), 8 * kEps * lambda.norm());
}

TEST(Multipliers, CovariantUnderAChangeOfBodyFrame) {
  // J' = Q J Qᵀ, ω' = Q ω  ⇒  Λ' = Q Λ Qᵀ: another formulation of the same body.
  for (int i = 0; i < 200; ++i) {
    const RigidBody body = random_body();
    const Mat3 Q = test::random_rotation();
    const RigidBody rotated = RigidBody::from_inertia(Q * body.inertia() * Q.transpose());
    State s = random_state();
    State s2 = s;
    s2.omega_body = Q * s.omega_body;
    s2.R_space_body = s.R_space_body * Q.transpose();
    const Mat3 lambda = lambda_from_state(body, s);
    EXPECT_LE(test::max_abs_diff(lambda_from_state(rotated, s2), Q * lambda * Q.transpose()),
              256 * kEps * std::max(1.0, lambda.norm()));
  }
}

TEST(Multipliers, LaminaNeedsNoInverseOfK) {
  // J = diag(1, 2, 3) is a plane lamina: K = diag(2, 1, 0) singular (docs/conventions.md A3, C2). Λ = M K has
  // a zero third column, is finite and matches the finite-difference oracle.
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
  EXPECT_EQ(body.poinsot()(2, 2), 0.0);
  for (int i = 0; i < 50; ++i) {
    const State s = random_state();
    const Mat3 lambda = lambda_from_state(body, s);
    EXPECT_TRUE(lambda.allFinite());
    EXPECT_LE(lambda.col(2).norm(), 16 * kEps * lambda.norm());
    EXPECT_LE(test::max_abs_diff(lambda, lambda_by_finite_differences(body, nullptr, s)),
              1e-6 * std::max(1.0, lambda.norm()));
    EXPECT_LE(sorted_eigenvalues(lambda)[2], 32 * kEps * lambda.norm());
  }
}

TEST(Multipliers, AsymmetricBodyEigenvaluesVaryErrataC3) {
  // docs/conventions.md C3 (printed to 4 decimals): J = diag(2,3,4), ω0 = (1, 0.5, 0.3): eig Λ(0) = (−2.2601,
  // −0.7605, −0.0894), eig Λ(3 s) = (−2.3779, −0.6791, −0.0530). The reference RK4 error (~1e-12) is far
  // below the 5e-5 rounding of the printed figures.
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  State s;
  s.omega_body = Vec3(1.0, 0.5, 0.3);
  const Vec3 e0 = sorted_eigenvalues(lambda_from_state(body, s));
  EXPECT_NEAR(e0[0], -2.2601, 5e-5);
  EXPECT_NEAR(e0[1], -0.7605, 5e-5);
  EXPECT_NEAR(e0[2], -0.0894, 5e-5);
  const State s3 = test::advance(body, nullptr, s, 3.0);
  const Vec3 e3 = sorted_eigenvalues(lambda_from_state(body, s3));
  EXPECT_NEAR(e3[0], -2.3779, 5e-5);
  EXPECT_NEAR(e3[1], -0.6791, 5e-5);
  EXPECT_NEAR(e3[2], -0.0530, 5e-5);
}

TEST(Multipliers, AngularAccelerationSatisfiesEuler) {
  const auto torque = dynamics::TorqueModel::constant_body(Vec3(0.1, 0.2, -0.3));
  for (int i = 0; i < 100; ++i) {
    const RigidBody body = random_body();
    const State s = random_state();
    const Vec3 wd = angular_acceleration_body(body, s, torque.get());
    const Vec3 residual =
        body.inertia() * wd + s.omega_body.cross(body.inertia() * s.omega_body) - Vec3(0.1, 0.2, -0.3);
    EXPECT_LE(residual.norm(), 1e-13);
  }
}

}  // namespace
}  // namespace poinsot::analysis
