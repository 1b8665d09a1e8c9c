#pragma once
// The closed form of the damped linear oscillator, the oracle of the joint springs' tests.
#include <cmath>

namespace poinsot::test {

/// x(t) of ẍ + 2ζω ẋ + ω² x = 0 from x(0) = x0 at rest, underdamped (ζ < 1).
inline double damped_oscillator(double x0, double omega, double zeta, double t) {
  const double omega_d = omega * std::sqrt(1.0 - zeta * zeta);
  return x0 * std::exp(-zeta * omega * t) *
         (std::cos(omega_d * t) + zeta * omega / omega_d * std::sin(omega_d * t));
}

}  // namespace poinsot::test
