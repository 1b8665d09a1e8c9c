#pragma once
// Test helpers shared by every layer's tests: tolerances scaled by the problem's magnitude (as MuJoCo's test
// utilities do), a reproducible random source, random rotations uniform on SO(3), and a check of error
// messages.
#include <cmath>
#include <initializer_list>
#include <limits>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/types.hpp"

namespace poinsot::test {

inline constexpr double kEps = std::numeric_limits<double>::epsilon();  // 2.22e-16

/// A random engine with a fixed seed, so a failure is reproducible.
inline std::mt19937_64& rng() {
  static std::mt19937_64 engine(20261121);
  return engine;
}

inline double uniform(double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng());
}

inline Vec3 random_vector(double scale = 1.0) {
  return Vec3(uniform(-scale, scale), uniform(-scale, scale), uniform(-scale, scale));
}

/// A unit vector uniformly distributed on the sphere.
inline Vec3 random_unit_vector() {
  std::normal_distribution<double> n(0.0, 1.0);
  Vec3 v(n(rng()), n(rng()), n(rng()));
  return v.normalized();
}

/// A unit quaternion uniformly distributed on S³, i.e. a rotation uniform on SO(3) (Haar measure).
inline Quat random_quaternion() {
  std::normal_distribution<double> n(0.0, 1.0);
  Quat q(n(rng()), n(rng()), n(rng()), n(rng()));
  q.normalize();
  return q;
}

inline Mat3 random_rotation() {
  return random_quaternion().toRotationMatrix();
}

/// Max-norm of a difference of matrices or vectors.
template <class A, class B>
double max_abs_diff(const A& a, const B& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

/// EXPECTs every piece to occur in `message` (the parts of a one-line error: file, key, value, expectation).
inline void expect_has(const std::string& message, std::initializer_list<std::string> pieces) {
  for (const auto& p : pieces) {
    EXPECT_NE(message.find(p), std::string::npos) << "expected \"" << p << "\" in: " << message;
  }
}

}  // namespace poinsot::test

/// EXPECT that |a − b| ≤ tol · max(1, |scale|): an absolute tolerance for quantities of order one, a relative
/// one for larger ones.
#define POINSOT_EXPECT_SCALED_NEAR(a, b, tol, scale) \
  EXPECT_LE(std::abs((a) - (b)), (tol)*std::max(1.0, std::abs(scale)))
