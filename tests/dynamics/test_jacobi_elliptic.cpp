// Jacobi elliptic functions from the complementary modulus (jacobi_elliptic.hpp) against Boost.Math's
// independent implementation, their identities and derivatives, and the separatrix limit.
#include "poinsot/dynamics/jacobi_elliptic.hpp"

#include <gtest/gtest.h>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <cmath>
#include <limits>
#include <numbers>

namespace poinsot::dynamics {
namespace {

TEST(JacobiElliptic, AgreesWithBoost) {
  for (double k : {0.0, 0.1, 0.5, 0.9, 0.99}) {
    const JacobiElliptic je(k * k, (1.0 - k) * (1.0 + k));
    const double K = je.complete();
    EXPECT_NEAR(K, boost::math::ellint_1(k), 4e-16 * K) << k;
    // Boost's dn is wrong at u = ±K exactly in Boost 1.74 (it forms dn = cn(φ0)/cos(φ1 − φ0) = 0/0 there and
    // returns 0.86399 for k = 0.5 instead of k' = 0.86603), so the comparison stays inside (−K, K); the
    // identities test covers u = K.
    for (double u = -0.95 * K; u <= 0.95 * K; u += K / 7.0) {
      double sn, cn, dn, bcn, bdn;
      je.evaluate(u, sn, cn, dn);
      const double bsn = boost::math::jacobi_elliptic(k, u, &bcn, &bdn);
      EXPECT_NEAR(sn, bsn, 1e-15) << k << " " << u;
      EXPECT_NEAR(cn, bcn, 1e-15) << k << " " << u;
      EXPECT_NEAR(dn, bdn, 1e-15) << k << " " << u;
    }
  }
}

TEST(JacobiElliptic, IdentitiesAndDerivatives) {
  for (double kc2 : {0.7, 1e-3, 1e-9, 1e-30}) {
    const JacobiElliptic je(1.0 - kc2, kc2);
    const double K = je.complete();
    for (double u : {-0.99 * K, -0.3 * K, 0.0, 0.5, 0.8 * K, K}) {
      double sn, cn, dn;
      je.evaluate(u, sn, cn, dn);
      // Each function is accurate to a few ulps of itself (they are not the sine and cosine of one angle on
      // every path), so the identities hold to a few ulps.
      EXPECT_NEAR(sn * sn + cn * cn, 1.0, 8 * std::numeric_limits<double>::epsilon());
      EXPECT_NEAR(dn * dn, cn * cn + kc2 * sn * sn, 8 * std::numeric_limits<double>::epsilon());
      // d sn/du = cn dn (central difference, error ~ h² + eps/h ≈ 1e-10 at h = 1e-5).
      const double h = 1e-5;
      double sp, cp, dp, sm, cm, dm;
      je.evaluate(u + h, sp, cp, dp);
      je.evaluate(u - h, sm, cm, dm);
      if (std::abs(u) + h <= K) {
        EXPECT_NEAR((sp - sm) / (2 * h), cn * dn, 1e-9) << kc2 << " " << u;
      }
    }
  }
}

// Near the separatrix K = ln(4/k') + O(k'² ln k') and sn(u) → tanh u: the complementary modulus keeps both
// (Boost, given k = √(1 − k'²) = 1 in double, would return K = ∞).
TEST(JacobiElliptic, SeparatrixLimit) {
  const double kc = 1e-12;
  const JacobiElliptic je(1.0, kc * kc);
  EXPECT_NEAR(je.complete(), std::log(4.0 / kc), 1e-13);
  // sn − tanh u and cn − sech u are O(k'² cosh² u) relative (DLMF 22.10(ii)): below 1e-20 here up to u = 10.
  for (double u : {0.5, 3.0, 10.0}) {
    double sn, cn, dn;
    je.evaluate(u, sn, cn, dn);
    const double sech = 1.0 / std::cosh(u);
    EXPECT_NEAR(sn, std::tanh(u), 4e-16);
    EXPECT_NEAR(cn, sech, 4e-16 * sech);
    EXPECT_NEAR(dn, sech, 4e-16 * sech);
  }
  const JacobiElliptic circle(0.0, 1.0);  // k = 0: sn = sin
  double sn, cn, dn;
  circle.evaluate(1.2, sn, cn, dn);
  EXPECT_DOUBLE_EQ(sn, std::sin(1.2));
  EXPECT_DOUBLE_EQ(circle.complete(), std::numbers::pi / 2);
}

// Near u = ±K, cn and dn fall to 0 and k': each must keep its own relative precision there, not a few ulps of
// 1 (the Carlson form of Π in exact_free_body.cpp takes cn² and dn² and is as sensitive to them as log). The
// oracle is Boost.Math's implementation in 50 digits at the same double u, with k from k'² in 50 digits. The
// bound is the functions' own conditioning at u: |δcn| ≤ 8ε(|cn| + |u·∂cn/∂u|), ∂cn/∂u = −sn dn, and
// |δdn| ≤ 8ε(|dn| + |u·∂dn/∂u|), ∂dn/∂u = −k² sn cn (u is exact; K is known to an ulp, whence the u·∂
// term). A transformation accurate only to ulps of 1 misses it by k'·K/ε-scale factors (10¹⁰ at k'² = 1e-20).
TEST(JacobiElliptic, RelativePrecisionNearTheQuarterPeriod) {
  using Real50 = boost::multiprecision::cpp_bin_float_50;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  for (double kc2 : {0.9, 0.3, 1e-6, 1e-12, 1e-20}) {
    const JacobiElliptic je(1.0 - kc2, kc2);
    const double K = je.complete();
    const Real50 k = sqrt(Real50(1) - Real50(kc2));
    for (double v : {0.0, 1e-9, 1e-3, 0.2, 1.0}) {
      for (double sign : {1.0, -1.0}) {
        const double u = sign * (K - v * K / 2);
        double sn, cn, dn;
        je.evaluate(u, sn, cn, dn);
        Real50 rcn, rdn;
        const Real50 rsn = boost::math::jacobi_elliptic(k, Real50(u), &rcn, &rdn);
        const double s = static_cast<double>(rsn), c = static_cast<double>(rcn), d = static_cast<double>(rdn);
        const double k2 = 1.0 - kc2;
        EXPECT_NEAR(sn, s, 8 * eps * (std::abs(s) + std::abs(u * c * d))) << kc2 << " " << u;
        EXPECT_NEAR(cn, c, 8 * eps * (std::abs(c) + std::abs(u * s * d))) << kc2 << " " << u;
        EXPECT_NEAR(dn, d, 8 * eps * (std::abs(d) + std::abs(u * k2 * s * c))) << kc2 << " " << u;
      }
    }
  }
}

}  // namespace
}  // namespace poinsot::dynamics
