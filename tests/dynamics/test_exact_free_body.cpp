// The closed-form free rigid body (exact_free_body.hpp) against an independent reference: Euler's equations
// and Ṙ = R j(ω) integrated in long double by RKF 7(8) (free_body_reference.hpp, error < 1e-14 at 100 s),
// against the paper's axisymmetric closed form (eq. 4.2), and against its own invariants.
#include "poinsot/dynamics/exact_free_body.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <string>

#include "free_body_reference.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::dynamics {
namespace {

using test::max_abs_diff;

State make_state(const Mat3& R, const Vec3& w, double t = 0.0) {
  State s;
  s.time = t;
  s.R_space_body = R;
  s.omega_body = w;
  return s;
}

/// Exact vs reference at time t: ω to `tol`·|ω|, R to `tol` (max entry; R's entries are ≤ 1).
void expect_matches_reference(const RigidBody& body, const State& s0, double t, double tol, const char* what,
                              int fixed_steps = 0) {
  const ExactFreeBody exact(body, s0);
  const int steps =
      fixed_steps > 0
          ? fixed_steps
          : static_cast<int>(std::ceil(std::abs(t - s0.time) * std::max(1.0, s0.omega_body.norm()) / 2e-2));
  const State ref = test::FreeBodyReference(body.inertia()).integrate(s0, t, std::max(steps, 10));
  const State ex = exact.state_at(t);
  SCOPED_TRACE(std::string(what) + " regime " + to_string(exact.regime()));
  EXPECT_LE(max_abs_diff(ex.omega_body, ref.omega_body), tol * std::max(1.0, s0.omega_body.norm()));
  EXPECT_LE(max_abs_diff(ex.R_space_body, ref.R_space_body), tol);
  EXPECT_EQ(ex.time, t);
}

// The accuracy target: 1e-12 in ω and R at t = 100 s, both regimes, random bodies and states.
TEST(ExactFreeBody, MatchesReferenceAtHundredSecondsBothRegimes) {
  int largest = 0, smallest = 0;
  for (int trial = 0; trial < 6; ++trial) {
    Vec3 I(test::uniform(1.0, 2.0), test::uniform(1.0, 2.0), test::uniform(1.0, 2.0));
    std::sort(I.data(), I.data() + 3);
    const RigidBody body = RigidBody::from_principal_moments(I);
    const State s0 = make_state(test::random_rotation(), test::random_vector(1.0));
    const ExactFreeBody exact(body, s0);
    largest += exact.regime() == FreeBodyRegime::largest_axis;
    smallest += exact.regime() == FreeBodyRegime::smallest_axis;
    expect_matches_reference(body, s0, 100.0, 1e-12, "random");
  }
  EXPECT_GT(largest, 0);
  EXPECT_GT(smallest, 0);
}

TEST(ExactFreeBody, MatchesReferenceBackwardsInTime) {
  for (int trial = 0; trial < 3; ++trial) {
    Vec3 I(test::uniform(0.5, 3.0), test::uniform(0.5, 3.0), test::uniform(0.5, 3.0));
    std::sort(I.data(), I.data() + 3);
    if (I[0] + I[1] < I[2]) I[2] = I[0] + I[1];
    const RigidBody body = RigidBody::from_principal_moments(I);
    expect_matches_reference(body, make_state(test::random_rotation(), test::random_vector(2.0), 3.0), -60.0,
                             1e-12, "backwards");
  }
}

// A body whose J is not diagonal: the closed form works in the principal frame and rotates back.
TEST(ExactFreeBody, NonDiagonalInertiaMatchesReference) {
  for (int trial = 0; trial < 3; ++trial) {
    const Mat3 Q = test::random_rotation();
    const Vec3 I(1.0 + 0.3 * trial, 1.7, 2.2);
    const RigidBody body = RigidBody::from_inertia(Q * I.asDiagonal() * Q.transpose());
    ASSERT_FALSE(body.is_diagonal());
    expect_matches_reference(body, make_state(test::random_rotation(), test::random_vector(1.5)), 100.0,
                             1e-12, "non-diagonal");
  }
}

// The tennis racket: spun about its intermediate axis with a small wobble, its handle flips over every
// 2K(k)/ω_p seconds. Its orientation at t = 100 s to 1e-12 (the headline figure of docs/exact.md).
TEST(ExactFreeBody, TennisRacketAtHundredSeconds) {
  const RigidBody racket = RigidBody::from_principal_moments(Vec3(0.0015, 0.0160, 0.0170));  // kg·m²
  const State s0 = make_state(Mat3::Identity(), Vec3(0.05, 4.0, 0.05));                      // rad/s
  const ExactFreeBody exact(racket, s0);
  EXPECT_EQ(exact.regime(), FreeBodyRegime::smallest_axis);
  // Near the separatrix (k'² = 5e-5) the flow amplifies any error by ~1/k'²: the reference's own round-off
  // (long double, 1e-19 a step) reaches 1e-12 beyond ~8e4 steps. 25000 steps (ω h = 0.016) keep its
  // truncation below 1e-15 and its round-off near 1e-13: measured, 2e4 and 4e4 steps agree to 8e-14.
  expect_matches_reference(racket, s0, 100.0, 1e-12, "tennis racket", 25000);
  const State end = exact.state_at(100.0);
  const State ref = test::FreeBodyReference(racket.inertia()).integrate(s0, 100.0, 25000);
  EXPECT_LE(so3::angle_between(end.R_space_body, ref.R_space_body), 1e-12);  // rad
}

// Separatrix data exact in binary: I = (1, 2, 9/4), ω1 = (3/4) ω3 gives |L|² − 2T I2 = 0 exactly.
TEST(ExactFreeBody, SeparatrixMatchesReferenceAndTendsToTheIntermediateAxis) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.25));
  for (const Vec3& w :
       {Vec3(0.75, 0.3, 1.0), Vec3(-0.75, 0.3, 1.0), Vec3(0.75, -0.3, -1.0), Vec3(-1.5, 0.0, 2.0)}) {
    const State s0 = make_state(test::random_rotation(), w);
    const ExactFreeBody exact(body, s0);
    ASSERT_EQ(exact.regime(), FreeBodyRegime::separatrix);
    EXPECT_EQ(exact.flip_interval(), 0.0);
    // The separatrix is unstable: a perturbation grows as exp(ω_p t) near the saddle, so the reference keeps
    // 1e-12 only while ω_p t stays below ~9 (ω_p ≈ 0.41 rad/s here); compare at ±10 s.
    expect_matches_reference(body, s0, 10.0, 1e-12, "separatrix forward");
    expect_matches_reference(body, s0, -10.0, 1e-12, "separatrix backward");
    // As t → ±∞, ω → ±√(2T/I2) e2: the unstable steady rotation about the intermediate axis.
    const double T = kinetic_energy(body, s0);
    for (double t : {400.0, -400.0}) {
      const State s = exact.state_at(t);
      EXPECT_NEAR(std::abs(s.omega_body[1]), std::sqrt(2.0 * T / 2.0), 1e-13);
      EXPECT_NEAR(s.omega_body[0], 0.0, 1e-13);
      EXPECT_NEAR(s.omega_body[2], 0.0, 1e-13);
    }
  }
}

TEST(ExactFreeBody, SphereAndSteadyRotations) {
  const RigidBody sphere = RigidBody::from_principal_moments(Vec3(2.0, 2.0, 2.0));
  const State s0 = make_state(test::random_rotation(), Vec3(0.3, -1.1, 0.7));
  EXPECT_EQ(ExactFreeBody(sphere, s0).regime(), FreeBodyRegime::sphere);
  expect_matches_reference(sphere, s0, 100.0, 1e-12, "sphere");

  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
  for (const Vec3& w : {Vec3(0.0, 0.0, 2.0), Vec3(0.0, -3.0, 0.0), Vec3(1.5, 0.0, 0.0)}) {
    const State s = make_state(test::random_rotation(), w);
    const ExactFreeBody exact(body, s);
    EXPECT_EQ(exact.regime(), FreeBodyRegime::principal_rotation);
    const State e = exact.state_at(37.0);
    EXPECT_EQ(e.omega_body, w);
    EXPECT_LE(max_abs_diff(e.R_space_body, s.R_space_body * so3::exp(37.0 * w)), 1e-15);
  }
  // Just off a steady rotation (tiny polhode): the elliptic form with tiny amplitudes still holds.
  expect_matches_reference(body, make_state(test::random_rotation(), Vec3(1e-9, 2e-9, 2.0)), 100.0, 1e-12,
                           "near axis 3");
  expect_matches_reference(body, make_state(test::random_rotation(), Vec3(1.5, -1e-9, 3e-9)), 100.0, 1e-12,
                           "near axis 1");
  const State rest = make_state(test::random_rotation(), Vec3::Zero());
  EXPECT_EQ(ExactFreeBody(body, rest).regime(), FreeBodyRegime::rest);
  EXPECT_EQ(ExactFreeBody(body, rest).state_at(-5.0).R_space_body, rest.R_space_body);
}

// docs/conventions.md cases b (prolate, A = 2, C = 1) and c (oblate, A = 1, C = 1.8), symmetry axis e3: the
// automatic route (paper eq. 4.2), the Jacobi-elliptic route at k = 0 and the reference all agree.
TEST(ExactFreeBody, AxisymmetricClosedFormAgreesWithEllipticAndReference) {
  struct Case {
    double A, C;
    Vec3 w;
  };
  for (const Case& c : {Case{2.0, 1.0, Vec3(0.3, -0.4, 1.2)}, Case{1.0, 1.8, Vec3(1.0, 0.5, -2.0)}}) {
    const RigidBody body = RigidBody::from_principal_moments(Vec3(c.A, c.A, c.C));
    const State s0 = make_state(test::random_rotation(), c.w, 0.5);
    const ExactFreeBody closed(body, s0);
    const ExactFreeBody elliptic(body, s0, ExactMethod::elliptic);
    EXPECT_EQ(closed.regime(), FreeBodyRegime::axisymmetric);
    EXPECT_NE(elliptic.regime(), FreeBodyRegime::axisymmetric);
    EXPECT_EQ(elliptic.theory().modulus, 0.0);  // k² ∝ the difference of the two equal moments
    // The forced elliptic form's ω period 4K/ω_p = 2π/ω_p equals eq. (4.2)'s precession period.
    EXPECT_NEAR(elliptic.omega_period(), closed.omega_period(), 1e-13 * closed.omega_period());
    expect_matches_reference(body, s0, 100.0, 1e-12, "axisymmetric");
    for (double t : {-40.0, 3.0, 100.0}) {
      const State a = closed.state_at(t);
      const State b = elliptic.state_at(t);
      EXPECT_LE(max_abs_diff(a.omega_body, b.omega_body), 1e-12 * c.w.norm());
      EXPECT_LE(max_abs_diff(a.R_space_body, b.R_space_body), 1e-12);
    }
    // Eq. (4.2) directly, at t = 0 of the paper (R0 = I): ω(t) = E(t) ω0 precesses about e3 at (C/A − 1) μ.
    const State paper =
        axisymmetric_free_motion(c.A, c.C, Vec3::UnitZ(), make_state(Mat3::Identity(), c.w), 7.5);
    const double nu = (c.C / c.A - 1.0) * c.w[2];
    EXPECT_LE(max_abs_diff(paper.omega_body, so3::exp(7.5 * nu * Vec3::UnitZ()) * c.w), 1e-15);
  }
}

// Eq. (4.2) for an axis that is not a coordinate axis: J = A·1 + (C − A) e⊗e.
TEST(ExactFreeBody, AxisymmetricFormulaWithGeneralAxisMatchesReference) {
  const Vec3 e = Vec3(1.0, -2.0, 0.5).normalized();
  const double A = 1.3, C = 2.1;
  const Mat3 J = A * Mat3::Identity() + (C - A) * e * e.transpose();
  const State s0 = make_state(test::random_rotation(), Vec3(0.4, 0.9, -0.6), -2.0);
  const State ref = test::FreeBodyReference(J).integrate(s0, 50.0, 8000);
  const State cf = axisymmetric_free_motion(A, C, e, s0, 50.0);
  EXPECT_LE(max_abs_diff(cf.omega_body, ref.omega_body), 1e-12);
  EXPECT_LE(max_abs_diff(cf.R_space_body, ref.R_space_body), 1e-12);
}

// Nearly symmetric bodies (two moments 1e-13 … 1e-9 apart, beyond the symmetry tolerance): the characteristic
// N of Π would be ~1/(I2 − I1) for one choice of the attitude frame's polar axis; the other choice keeps it
// bounded (their product is k²). Without that choice these cases lost up to 8e-10 in R.
TEST(ExactFreeBody, NearlySymmetricBodiesKeepFullPrecision) {
  for (const Vec3& I :
       {Vec3(1.0, 1.0 + 1e-9, 1.5), Vec3(1.0, 1.5, 1.5 + 1e-9), Vec3(1.0, 1.0 + 1e-13, 1.5)}) {
    for (const Vec3& w : {Vec3(0.9, 0.4, 1e-6), Vec3(1e-6, 0.4, 0.9), Vec3(0.7, 0.7, 0.0)}) {
      const RigidBody body = RigidBody::from_principal_moments(I);
      expect_matches_reference(body, make_state(test::random_rotation(), w), 100.0, 1e-12,
                               "nearly symmetric");
    }
  }
}

// Energy and L_space to 1e-14 relative, and R a rotation, at times near and far, both signs.
TEST(ExactFreeBody, InvariantsHoldAtAnyTime) {
  for (int trial = 0; trial < 20; ++trial) {
    Vec3 I(test::uniform(0.2, 5.0), test::uniform(0.2, 5.0), test::uniform(0.2, 5.0));
    std::sort(I.data(), I.data() + 3);
    if (I[0] + I[1] < I[2]) I[2] = I[0] + I[1];
    const RigidBody body = RigidBody::from_principal_moments(I);
    const State s0 = make_state(test::random_rotation(), test::random_vector(10.0));
    const ExactFreeBody exact(body, s0);
    const double T0 = kinetic_energy(body, s0);
    const Vec3 L0 = angular_momentum_space(body, s0);
    for (double t : {-1e6, -1e4, -100.0, 1e-3, 100.0, 1e4, 1e6}) {
      const State s = exact.state_at(t);
      EXPECT_LE(std::abs(kinetic_energy(body, s) - T0), 1e-14 * T0) << "t = " << t;
      EXPECT_LE((angular_momentum_space(body, s) - L0).norm(), 1e-14 * L0.norm()) << "t = " << t;
      EXPECT_LE((s.R_space_body.transpose() * s.R_space_body - Mat3::Identity()).norm(), 1e-14);
      EXPECT_GT(s.R_space_body.determinant(), 0.0);
    }
  }
}

// A flow: going from s0 to t1 and then from there to t2 is going from s0 to t2; t2 = t0 returns to s0.
TEST(ExactFreeBody, FlowPropertyAndTimeReversal) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 1.6, 2.3));
  for (const Vec3& w : {Vec3(0.3, 1.0, 0.9), Vec3(1.2, 0.4, -0.1)}) {
    const State s0 = make_state(test::random_rotation(), w, 2.0);
    const ExactFreeBody a(body, s0);
    EXPECT_LE(max_abs_diff(a.state_at(2.0).R_space_body, s0.R_space_body), 1e-15);
    EXPECT_LE(max_abs_diff(a.state_at(2.0).omega_body, w), 1e-15);
    const State s1 = a.state_at(130.0);
    const ExactFreeBody b(body, s1);
    for (double t : {-55.0, 2.0, 400.0}) {
      EXPECT_LE(max_abs_diff(b.state_at(t).omega_body, a.state_at(t).omega_body), 1e-12);
      EXPECT_LE(max_abs_diff(b.state_at(t).R_space_body, a.state_at(t).R_space_body), 1e-12);
    }
  }
}

// ω(t + 4K/ω_p) = ω(t) and ω2 changes sign at the flip interval.
TEST(ExactFreeBody, OmegaIsPeriodic) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 1.6, 2.3));
  const ExactFreeBody exact(body, make_state(Mat3::Identity(), Vec3(0.3, 1.0, 0.9)));
  const double P = exact.omega_period();
  ASSERT_GT(P, 0.0);
  EXPECT_DOUBLE_EQ(P, 2.0 * exact.flip_interval());
  for (double t : {0.0, 1.3, 17.0}) {
    EXPECT_LE(max_abs_diff(exact.state_at(t + P).omega_body, exact.state_at(t).omega_body), 1e-13);
    EXPECT_NEAR(exact.state_at(t + P / 2).omega_body[1], -exact.state_at(t).omega_body[1], 1e-13);
  }
}

TEST(ExactFreeBody, RejectsInvalidInput) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5));
  State bad = make_state(Mat3::Identity(), Vec3(1.0, 0.0, 0.0));
  bad.R_space_body(0, 0) = 2.0;
  EXPECT_THROW(ExactFreeBody(body, bad), InvalidInput);
  bad = make_state(Mat3::Identity(), Vec3(std::nan(""), 0.0, 0.0));
  EXPECT_THROW(ExactFreeBody(body, bad), InvalidInput);
  const RigidBody sphere = RigidBody::from_principal_moments(Vec3(1.0, 1.0, 1.0));
  EXPECT_THROW(ExactFreeBody(sphere, make_state(Mat3::Identity(), Vec3(1, 2, 3)), ExactMethod::elliptic),
               InvalidInput);
  const RigidBody oblate = RigidBody::from_principal_moments(Vec3(1.0, 1.0, 1.5));
  EXPECT_THROW(ExactFreeBody(oblate, make_state(Mat3::Identity(), Vec3(1, 2, 0)), ExactMethod::elliptic),
               InvalidInput);
}

}  // namespace
}  // namespace poinsot::dynamics
