#include "poinsot/ensemble/dispersion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "ks.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::ensemble {
namespace {

constexpr std::size_t kN = 5000;

std::vector<double> standardized(const ScalarDispersion& d, double nominal, double sigma) {
  std::vector<double> z;
  for (std::size_t i = 0; i < kN; ++i) {
    SampleStream s(11, i, Stream::moments);
    z.push_back((disperse(d, nominal, nominal, s) - nominal) / sigma);
  }
  return z;
}

TEST(Dispersion, NormalUniformAndTruncatedNormalMatchTheirLaws) {
  // Relative normal, σ = 5 % of 2.0.
  EXPECT_LT(test::ks_statistic(standardized({Law::normal, 0.05, true}, 2.0, 0.1), test::normal_cdf),
            test::ks_critical_0001(kN));
  // Absolute uniform of half-width 0.3 on [x0 − 0.3, x0 + 0.3]: standardized by 0.3 it is U(−1, 1).
  EXPECT_LT(test::ks_statistic(standardized({Law::uniform, 0.3, false}, 2.0, 0.3),
                               [](double x) { return std::clamp(0.5 * (x + 1.0), 0.0, 1.0); }),
            test::ks_critical_0001(kN));
  // Truncated at 1.5 σ: Φ conditioned on |z| ≤ 1.5, and no value outside.
  const double c = 1.5;
  const auto z = standardized({Law::truncated_normal, 0.2, false, c}, 1.0, 0.2);
  for (double x : z)
    EXPECT_LE(std::abs(x), c + 1e-12);
  const double mass = test::normal_cdf(c) - test::normal_cdf(-c);
  EXPECT_LT(test::ks_statistic(z,
                               [&](double x) {
                                 return std::clamp((test::normal_cdf(x) - test::normal_cdf(-c)) / mass, 0.0,
                                                   1.0);
                               }),
            test::ks_critical_0001(kN));
}

TEST(Dispersion, ConeRotationsAreUniformWithinTheHalfAngle) {
  const double alpha = 0.3;
  std::vector<double> angle, axis_z;
  for (std::size_t i = 0; i < kN; ++i) {
    SampleStream s(5, i, Stream::axes);
    const Vec3 v = draw_rotation_vector({RotationLaw::cone, alpha}, s);
    angle.push_back(v.norm());
    axis_z.push_back(v.normalized().z());
    EXPECT_LE(v.norm(), alpha * (1 + 1e-15));
  }
  // Haar measure restricted to the ball of radius α: the angle has CDF (θ − sin θ)/(α − sin α).
  const double norm = alpha - std::sin(alpha);
  EXPECT_LT(test::ks_statistic(angle, [&](double t) { return (t - std::sin(t)) / norm; }),
            test::ks_critical_0001(kN));
  // The axis is uniform on the sphere: its z component is uniform on [−1, 1].
  EXPECT_LT(test::ks_statistic(axis_z, [](double x) { return 0.5 * (x + 1.0); }), test::ks_critical_0001(kN));
}

TEST(Dispersion, NormalRotationVectorsHaveAMaxwellAngle) {
  const double sigma = 0.02;
  std::vector<double> angle;
  for (std::size_t i = 0; i < kN; ++i) {
    SampleStream s(6, i, Stream::attitude);
    angle.push_back(draw_rotation_vector({RotationLaw::normal, sigma}, s).norm());
  }
  // |v|/σ is χ with 3 degrees of freedom: F(r) = erf(r/√2) − √(2/π) r e^{−r²/2}.
  const auto chi3 = [&](double t) {
    const double r = t / sigma;
    return std::erf(r / std::sqrt(2.0)) - std::sqrt(2.0 / std::numbers::pi) * r * std::exp(-0.5 * r * r);
  };
  EXPECT_LT(test::ks_statistic(angle, chi3), test::ks_critical_0001(kN));
}

TEST(Dispersion, ThetaMinusSinIsAccurateOnBothSidesOfTheSeriesSwitch) {
  for (double t : {1e-6, 1e-3, 0.05, 0.5, 0.999, 1.0, 3.0}) {
    // Oracle: the series to many more terms in long double.
    long double term = static_cast<long double>(t) * t * t / 6, sum = 0;
    for (int k = 1; k < 40; ++k) {
      sum += term;
      term *= -static_cast<long double>(t) * t / ((2 * k + 2) * (2 * k + 3));
    }
    EXPECT_NEAR(theta_minus_sin(t), static_cast<double>(sum), 2e-15 * static_cast<double>(sum)) << t;
  }
}

TEST(Dispersion, RejectsNegativeWidthsAndBadLaws) {
  POINSOT_EXPECT_THROWS_MESSAGE(validate(ScalarDispersion{Law::normal, -0.1, true}, "[ensemble] moments"),
                                InvalidInput, "[ensemble] moments", "-0.1", ">= 0");
  EXPECT_THROW(validate(RotationDispersion{RotationLaw::cone, 4.0}, "[ensemble] axes"), InvalidInput);
  EXPECT_THROW(validate(RotationDispersion{RotationLaw::normal, -1.0}, "[ensemble] axes"), InvalidInput);
  EXPECT_THROW(validate(ScalarDispersion{Law::truncated_normal, 0.1, false, 0.2}, "x"), InvalidInput);
  EXPECT_THROW(law_from_string("gauss", "[ensemble] moments.law"), InvalidInput);
  EXPECT_EQ(law_from_string("truncated_normal", "x"), Law::truncated_normal);
}

}  // namespace
}  // namespace poinsot::ensemble
