#pragma once
/// @file sin_cos.hpp
/// sin θ and cos θ − 1 to within an ulp, fast for small angles: Taylor polynomials for |θ| ≤ 1/4 (the
/// truncation errors θ¹⁵/15! and θ¹⁶/16! are below 1e-18), the C library beyond. The rotation angles h Πᵢ/Iᵢ
/// of the splitting methods are small at useful steps, and five library calls would dominate the cost of a
/// step. Shared by dynamics/dlm.cpp and the batched dlm of the ensemble layer, which must round identically.
#include <cmath>

namespace poinsot::dynamics {

/// True when sin_cosm1 evaluates its polynomials (|θ| ≤ 1/4), false when it calls the C library.
inline bool sin_cos_uses_polynomial(double x) {
  return !(std::abs(x) > 0.25);
}

/// sin θ and cos θ − 1 by their Taylor polynomials (rad), each accurate to an ulp for |θ| ≤ 1/4. cos θ − 1
/// (= −2 sin²(θ/2)) is returned as such, without the 1: a planar rotation applied as the increment
/// x ← x + ((cos θ − 1) x + sin θ y) then rounds only the sum, whose error is unbiased, instead of cos θ
/// itself, whose rounding is the same step after step when θ varies slowly and makes the norm drift linearly.
inline __attribute__((always_inline)) void sin_cosm1_polynomial(double x, double& s, double& cm1) {
  const double z = x * x;
  s = x *
      (1.0 + z * (-1.0 / 6 +
                  z * (1.0 / 120 + z * (-1.0 / 5040 + z * (1.0 / 362880 + z * (-1.0 / 39916800 +
                                                                               z * (1.0 / 6227020800.0)))))));
  cm1 = z * (-0.5 + z * (1.0 / 24 +
                         z * (-1.0 / 720 +
                              z * (1.0 / 40320 + z * (-1.0 / 3628800 +
                                                      z * (1.0 / 479001600 + z * (-1.0 / 87178291200.0)))))));
}

/// sin θ and cos θ − 1 (θ in rad): the polynomials for |θ| ≤ 1/4, else the C library's sin θ and
/// −2 sin²(θ/2).
inline void sin_cosm1(double x, double& s, double& cm1) {
  if (!sin_cos_uses_polynomial(x)) {
    const double half = std::sin(0.5 * x);
    s = std::sin(x);
    cm1 = -2.0 * half * half;
    return;
  }
  sin_cosm1_polynomial(x, s, cm1);
}

}  // namespace poinsot::dynamics
