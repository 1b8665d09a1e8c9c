#include "poinsot/so3/cayley.hpp"

#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

TEST(Cayley, EqualsTheDefinitionWithAMatrixInverse) {
  for (int i = 0; i < 2000; ++i) {
    const Vec3 c = test::random_vector(3.0);
    const Mat3 definition = (Mat3::Identity() - hat(c)).inverse() * (Mat3::Identity() + hat(c));
    EXPECT_LE(test::max_abs_diff(cayley(c), definition), 64 * kEps);
  }
}

TEST(Cayley, IsTheRotationByTwiceTheArctangent) {
  for (int i = 0; i < 2000; ++i) {
    const Vec3 c = test::random_vector(5.0);
    const double angle = 2.0 * std::atan(c.norm());
    EXPECT_LE(test::max_abs_diff(cayley(c), exp(angle * c.normalized())), 16 * kEps);
    EXPECT_LE(orthogonality_error(cayley(c)), 16 * kEps);
  }
}

TEST(Cayley, IdentityHasTheZeroVector) {
  EXPECT_EQ(cayley_inverse(Mat3::Identity()), Vec3::Zero());
}

TEST(Cayley, HalfTurnHasNoCayleyVector) {
  EXPECT_THROW(cayley_inverse(exp(std::numbers::pi * Vec3::UnitY())), InvalidInput);
}

}  // namespace
}  // namespace poinsot::so3
