#include "poinsot/dynamics/axis_tracker.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/axis_angle.hpp"

namespace poinsot::dynamics {
namespace {

/// A synthetic top: R(t) = Rz(Ω t) Rx(θ(t)), θ(t) = θ0 + a sin(ν t). Its z axis precesses about space z at
/// exactly Ω and nutates with angular frequency ν (the oracle).
Mat3 attitude(double t, double Omega, double theta0, double a, double nu) {
  return so3::rotation_from_axis_angle(Vec3::UnitZ(), Omega * t) *
         so3::rotation_from_axis_angle(Vec3::UnitX(), theta0 + a * std::sin(nu * t));
}

TEST(AxisTracker, RecoversPrecessionAndNutationRates) {
  const double Omega = 0.7, nu = 9.0, theta0 = 0.4, a = 0.05;
  AxisTracker tr(Vec3::UnitZ(), Vec3(0, 0, 2));     // not unit: normalised
  const double h = 2 * std::numbers::pi / nu / 64;  // 64 samples per nutation period
  const int n = 4000;
  for (int i = 0; i <= n; ++i)
    tr.add(i * h, attitude(i * h, Omega, theta0, a, nu));
  // The azimuth is exactly Ω t (up to round-off in the atan2 sum over 4000 samples).
  ASSERT_TRUE(tr.precession_rate_mean());
  EXPECT_NEAR(*tr.precession_rate_mean(), Omega, 1e-12);
  // Minima located by a parabola through three samples: the vertex is off by O(h²)·θ'''/θ'' relative to the
  // period, about (2π/64)²/6 ≈ 2e-3 of a sample, and errors at the two ends of the span do not accumulate.
  ASSERT_TRUE(tr.nutation_frequency());
  EXPECT_NEAR(*tr.nutation_frequency(), nu, 1e-4 * nu);
  EXPECT_NEAR(tr.theta_min(), theta0 - a, 1e-3 * a);
  EXPECT_NEAR(tr.theta_max(), theta0 + a, 1e-3 * a);
}

TEST(AxisTracker, ClockwisePrecessionIsNegative) {
  AxisTracker tr(Vec3::UnitZ(), Vec3::UnitZ());
  for (int i = 0; i <= 100; ++i)
    tr.add(0.01 * i, attitude(0.01 * i, -2.0, 0.3, 0.0, 1.0));
  EXPECT_NEAR(*tr.precession_rate_mean(), -2.0, 1e-12);
}

TEST(AxisTracker, SteadyPrecessionHasNoNutation) {
  AxisTracker tr(Vec3::UnitZ(), Vec3::UnitZ());
  for (int i = 0; i <= 1000; ++i)
    tr.add(0.01 * i, attitude(0.01 * i, 1.0, 0.3, 0.0, 1.0));
  EXPECT_FALSE(tr.nutation_frequency());  // θ constant up to round-off: below the amplitude threshold
}

TEST(AxisTracker, TooFewSamplesGiveNothing) {
  AxisTracker tr(Vec3::UnitZ(), Vec3::UnitZ());
  EXPECT_FALSE(tr.precession_rate_mean());
  tr.add(0.0, Mat3::Identity());
  EXPECT_FALSE(tr.precession_rate_mean());
  EXPECT_FALSE(tr.nutation_frequency());
  EXPECT_THROW(AxisTracker(Vec3::Zero(), Vec3::UnitZ()), InvalidInput);
}

}  // namespace
}  // namespace poinsot::dynamics
