#pragma once
/// @file sin_cos.hpp
/// sin θ and cos θ to within an ulp, fast for small angles: Taylor polynomials for |θ| ≤ 1/4 (the truncation
/// errors θ¹⁵/15! and θ¹⁶/16! are below 1e-18), the C library beyond. The rotation angles h Πᵢ/Iᵢ of the
/// splitting methods are small at useful steps, and five library calls would dominate the cost of a step.
/// Shared by dynamics/dlm.cpp and the batched dlm of the ensemble layer, which must round identically.
#include <cmath>

namespace poinsot::dynamics {

/// True when sin_cos evaluates its polynomials (|θ| ≤ 1/4), false when it calls the C library.
inline bool sin_cos_uses_polynomial(double x) {
  return !(std::abs(x) > 0.25);
}

/// The Taylor polynomials of sin and cos (rad), accurate to an ulp for |θ| ≤ 1/4.
inline __attribute__((always_inline)) void sin_cos_polynomial(double x, double& s, double& c) {
  const double z = x * x;
  s = x *
      (1.0 + z * (-1.0 / 6 +
                  z * (1.0 / 120 + z * (-1.0 / 5040 + z * (1.0 / 362880 + z * (-1.0 / 39916800 +
                                                                               z * (1.0 / 6227020800.0)))))));
  c = 1.0 +
      z * (-0.5 + z * (1.0 / 24 +
                       z * (-1.0 / 720 +
                            z * (1.0 / 40320 + z * (-1.0 / 3628800 +
                                                    z * (1.0 / 479001600 + z * (-1.0 / 87178291200.0)))))));
}

/// sin θ and cos θ (θ in rad).
inline void sin_cos(double x, double& s, double& c) {
  if (!sin_cos_uses_polynomial(x)) {
    s = std::sin(x);
    c = std::cos(x);
    return;
  }
  sin_cos_polynomial(x, s, c);
}

}  // namespace poinsot::dynamics
