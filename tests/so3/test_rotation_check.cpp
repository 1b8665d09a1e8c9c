// The one rotation predicate: its tolerances at their boundaries, reflections and non-finite matrices refused
// with a one-line message, and the metric's independence of the frame.
#include "poinsot/so3/rotation_check.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {

using poinsot::test::expect_has;
using poinsot::test::message_of;
using poinsot::test::random_rotation;

// R (I + ε S) with S symmetric, ‖S‖_F = 1: RᵀR − I = 2εS + ε²S², so orthogonality_error = 2ε (1 + O(ε)).
Mat3 perturbed(const Mat3& R, double eps) {
  Mat3 S;
  S << 1, 2, 0, 2, -1, 1, 0, 1, 3;
  S /= S.norm();
  return R * (Mat3::Identity() + eps * S);
}

TEST(RotationCheck, TolerancesAtTheirBoundaries) {
  const Mat3 R = random_rotation();
  EXPECT_TRUE(is_rotation(R));
  for (const double tol : {kRotationTolerance, kRotationInputTolerance}) {
    EXPECT_TRUE(is_rotation(perturbed(R, 0.45 * tol), tol));   // error 0.9 tol
    EXPECT_FALSE(is_rotation(perturbed(R, 0.55 * tol), tol));  // error 1.1 tol
    EXPECT_NO_THROW(require_rotation("r", perturbed(R, 0.45 * tol), tol));
  }
  EXPECT_FALSE(is_rotation(perturbed(R, 1e-7)));  // the default is the state tolerance
}

TEST(RotationCheck, RefusesReflectionsAndNonFiniteMatricesInOneLine) {
  EXPECT_FALSE(is_rotation(-Mat3::Identity()));
  Mat3 nan = Mat3::Identity();
  nan(0, 1) = std::nan("");
  EXPECT_FALSE(is_rotation(nan));
  expect_has(message_of<InvalidInput>([] { require_rotation("weld", -Mat3::Identity()); }),
             {"weld: matrix", "has determinant -1; expected a proper rotation (det = +1)"});
  const std::string far =
      message_of<InvalidInput>([] { require_rotation("so3::log", 2.0 * Mat3::Identity()); });
  expect_has(far, {"so3::log: matrix", "is not a rotation (|R^T R - I| = 5.2 > 1e-09); expected"});
  EXPECT_EQ(far.find('\n'), std::string::npos);
  EXPECT_THROW(require_rotation("r", nan), InvalidInput);
}

TEST(RotationCheck, MetricDoesNotDependOnTheFrame) {
  // ‖Qᵀ(RᵀR − I)Q‖_F = ‖RᵀR − I‖_F: the same matrix seen in a turned frame has the same error (the largest
  // entry would change).
  const Mat3 M = perturbed(random_rotation(), 1e-3);
  const Mat3 Q = random_rotation();
  const double e = orthogonality_error(M);
  EXPECT_NEAR(orthogonality_error(M * Q), e, 1e-15);
  EXPECT_NEAR(orthogonality_error(Q.transpose() * M * Q), e, 1e-15);
  EXPECT_NEAR(e, 2e-3, 2e-6);  // 2ε to first order
}

}  // namespace
}  // namespace poinsot::so3
