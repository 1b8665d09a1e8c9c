// Free-body theory (free_body_theory.hpp): regimes, the gap |L|² − 2T I2, and the flip interval 2K(k)/ω_p and
// period 4K(k)/ω_p against sign changes of ω2 measured on an independent long-double integration.
#include "poinsot/dynamics/free_body_theory.hpp"

#include <gtest/gtest.h>
#include <cmath>
#include <vector>

#include "free_body_reference.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::dynamics {
namespace {

/// Times of the sign changes of ω2 in (0, t_end], located on the reference integration: a crossing is
/// bracketed by fixed steps, then found by bisection on the length of a single RKF78 step from the bracket's
/// start (each trial step as accurate as the integration itself).
std::vector<double> omega2_crossings(const RigidBody& body, const Vec3& w0, double t_end, double h) {
  const test::FreeBodyReference ref(body.inertia());
  State s;
  s.omega_body = w0;
  std::vector<double> times;
  for (double t = 0.0; t < t_end; t += h) {
    const State next = ref.integrate(s, t + h, 1);
    if ((s.omega_body[1] < 0.0) != (next.omega_body[1] < 0.0)) {
      double lo = 0.0, hi = h;
      for (int i = 0; i < 60; ++i) {
        const double mid = 0.5 * (lo + hi);
        const State m = ref.integrate(s, t + mid, 1);
        ((m.omega_body[1] < 0.0) == (s.omega_body[1] < 0.0) ? lo : hi) = mid;
      }
      times.push_back(t + 0.5 * (lo + hi));
    }
    s = next;
  }
  return times;
}

TEST(FreeBodyTheory, FlipIntervalMatchesMeasuredSignChangesOfOmega2) {
  struct Case {
    Vec3 I, w;
    FreeBodyRegime regime;
  };
  for (const Case& c :
       {Case{Vec3(1.0, 2.0, 2.5), Vec3(0.3, 1.0, 0.6), FreeBodyRegime::largest_axis},
        Case{Vec3(1.0, 2.0, 2.5), Vec3(1.0, 0.8, 0.1), FreeBodyRegime::smallest_axis},
        Case{Vec3(0.0015, 0.0160, 0.0170), Vec3(0.05, 4.0, 0.05), FreeBodyRegime::smallest_axis}}) {
    const RigidBody body = RigidBody::from_principal_moments(c.I);
    const FreeBodyTheory th = free_body_theory(c.I, c.w);
    ASSERT_EQ(th.regime, c.regime);
    const double flip = th.flip_interval();
    ASSERT_GT(flip, 0.0);
    EXPECT_DOUBLE_EQ(th.omega_period(), 2.0 * flip);
    const std::vector<double> t = omega2_crossings(body, c.w, 4.2 * flip, 0.01 * flip);
    ASSERT_GE(t.size(), 4u);
    // The mean interval over three flips to 1e-8 relative ; the crossings are located to ~1e-15 s.
    EXPECT_NEAR((t[3] - t[0]) / 3.0, flip, 1e-8 * flip);
    for (std::size_t i = 1; i < t.size(); ++i)
      EXPECT_NEAR(t[i] - t[i - 1], flip, 1e-10 * flip);
    // ω repeats after the period 4K/ω_p.
    State s0;
    s0.omega_body = c.w;
    const State later = test::FreeBodyReference(body.inertia()).integrate(s0, th.omega_period(), 4000);
    EXPECT_LE(test::max_abs_diff(later.omega_body, c.w), 1e-11 * c.w.norm());
  }
}

// Near the separatrix the flip interval grows as (2/ω_p) ln(4/k') (K(k) ≈ ln(4/k') for k' → 0).
TEST(FreeBodyTheory, FlipIntervalDivergesLogarithmicallyAtTheSeparatrix) {
  const Vec3 I(1.0, 2.0, 2.25);  // ω1 = 0.75 ω3 is the separatrix
  for (double eps : {1e-6, 1e-9, 1e-12}) {
    const FreeBodyTheory th = free_body_theory(I, Vec3(0.75 * (1.0 + eps), 0.3, 1.0));
    ASSERT_EQ(th.regime, FreeBodyRegime::smallest_axis);
    const double kc = std::sqrt(th.modulus_complement2);
    EXPECT_NEAR(th.quarter_period, std::log(4.0 / kc), 10.0 * kc * kc * std::log(4.0 / kc) + 1e-13);
  }
  EXPECT_EQ(free_body_theory(I, Vec3(0.75, 0.3, 1.0)).regime, FreeBodyRegime::separatrix);
  EXPECT_EQ(free_body_theory(I, Vec3(0.75, 0.3, 1.0)).flip_interval(), 0.0);
}

TEST(FreeBodyTheory, RegimesAndInvariants) {
  const Vec3 I(1.0, 2.0, 3.0);
  EXPECT_EQ(free_body_theory(I, Vec3::Zero()).regime, FreeBodyRegime::rest);
  EXPECT_EQ(free_body_theory(Vec3(2, 2, 2), Vec3(1, 2, 3)).regime, FreeBodyRegime::sphere);
  EXPECT_EQ(free_body_theory(Vec3(1, 1, 1.5), Vec3(1, 2, 3)).regime, FreeBodyRegime::axisymmetric);
  EXPECT_EQ(free_body_theory(Vec3(1, 1.5, 1.5), Vec3(1, 2, 3)).regime, FreeBodyRegime::axisymmetric);
  EXPECT_EQ(free_body_theory(I, Vec3(0, 2, 0)).regime, FreeBodyRegime::principal_rotation);
  EXPECT_EQ(free_body_theory(I, Vec3(0.1, 0.1, 1)).regime, FreeBodyRegime::largest_axis);
  EXPECT_EQ(free_body_theory(I, Vec3(1, 0.1, 0.1)).regime, FreeBodyRegime::smallest_axis);
  // Axisymmetric: ω precesses in the body at |C/A − 1||μ| (docs/conventions.md C11); period 2π over that.
  const FreeBodyTheory ax = free_body_theory(Vec3(1, 1, 1.8), Vec3(1.0, 0.5, -2.0));
  EXPECT_NEAR(ax.omega_p, 0.8 * 2.0, 1e-15);
  EXPECT_NEAR(ax.omega_period(), 2.0 * std::numbers::pi / 1.6, 1e-14);
  EXPECT_EQ(ax.flip_interval(), 0.0);
  for (int trial = 0; trial < 50; ++trial) {
    Vec3 J(test::uniform(0.5, 2.0), test::uniform(0.5, 2.0), test::uniform(0.5, 2.0));
    std::sort(J.data(), J.data() + 3);
    const Vec3 w = test::random_vector(3.0);
    const FreeBodyTheory th = free_body_theory(J, w);
    const Vec3 L = J.cwiseProduct(w);
    const double T = 0.5 * w.dot(L);
    EXPECT_NEAR(th.energy, T, 1e-15 * T);
    EXPECT_NEAR(th.momentum, L.norm(), 1e-15 * L.norm());
    EXPECT_NEAR(th.separatrix_gap, L.squaredNorm() - 2.0 * T * J[1], 1e-13 * L.squaredNorm());
    EXPECT_NEAR(th.modulus * th.modulus + th.modulus_complement2, 1.0, 1e-13);
    EXPECT_GE(th.modulus, 0.0);
    EXPECT_LE(th.modulus, 1.0);
  }
  // Same theory from a body with a non-diagonal tensor and ω in its body frame.
  const Mat3 Q = test::random_rotation();
  const RigidBody body = RigidBody::from_inertia(Q * I.asDiagonal() * Q.transpose());
  const Vec3 w_principal(0.3, 1.0, 0.6);
  const Vec3 w_body = body.principal_axes() * w_principal;
  EXPECT_NEAR(free_body_theory(body, w_body).flip_interval(),
              free_body_theory(I, w_principal).flip_interval(), 1e-13);
}

TEST(FreeBodyTheory, RejectsInvalidInput) {
  EXPECT_THROW(free_body_theory(Vec3(2, 1, 3), Vec3(1, 1, 1)), InvalidInput);
  EXPECT_THROW(free_body_theory(Vec3(0, 1, 1), Vec3(1, 1, 1)), InvalidInput);
  EXPECT_THROW(free_body_theory(Vec3(1, 2, 3), Vec3(1, std::nan(""), 1)), InvalidInput);
  EXPECT_STREQ(to_string(FreeBodyRegime::separatrix), "separatrix");
}

}  // namespace
}  // namespace poinsot::dynamics
