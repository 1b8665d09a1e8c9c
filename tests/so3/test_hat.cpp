#include "poinsot/so3/hat.hpp"

#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

TEST(Hat, IsTheCrossProduct) {
  for (int i = 0; i < 2000; ++i) {
    const Vec3 u = test::random_vector(10.0);
    const Vec3 v = test::random_vector(10.0);
    // Each entry of hat(u) v is a sum of two products: error ≤ 2 ulp of the largest product.
    EXPECT_LE(test::max_abs_diff(hat(u) * v, u.cross(v)), 4 * kEps * 100.0);
  }
}

TEST(Hat, TimesHatIsTheProductWithHat) {
  for (int i = 0; i < 2000; ++i) {
    const Mat3 A = test::random_rotation() * test::uniform(0.1, 10.0);
    const Vec3 u = test::random_vector(10.0);
    // Column k of A j(u) is A (u × e_k), a sum of two products of entries ≤ 10 · 10 in both forms (the zero
    // entry of hat(u) adds nothing): the two differ by a few ulp of 100.
    EXPECT_LE(test::max_abs_diff(times_hat(A, u), A * hat(u)), 4 * kEps * 100.0);
    // and it is A j(u) applied to any vector: A (u × v)
    const Vec3 v = test::random_vector(1.0);
    EXPECT_LE(test::max_abs_diff(times_hat(A, u) * v, A * u.cross(v)), 16 * kEps * 100.0);
  }
}

TEST(Hat, IsSkewSymmetricAndVeeInvertsIt) {
  for (int i = 0; i < 2000; ++i) {
    const Vec3 u = test::random_vector(5.0);
    const Mat3 m = hat(u);
    EXPECT_EQ(m + m.transpose(), Mat3::Zero());
    EXPECT_EQ(vee(m), u);  // exact: no arithmetic but halving a doubled number
  }
}

TEST(Hat, VeeOfAGeneralMatrixIsItsSkewPart) {
  Mat3 m;
  m << 1, 2, 3, 4, 5, 6, 7, 8, 10;
  const Mat3 skew = 0.5 * (m - m.transpose());
  EXPECT_EQ(hat(vee(m)), skew);
}

TEST(Hat, ConjugationByARotation) {
  // R j(u) Rᵀ = j(R u): the identity behind Ṙ = R j(ω) = j(Rω) R.
  for (int i = 0; i < 1000; ++i) {
    const Mat3 R = test::random_rotation();
    const Vec3 u = test::random_vector();
    EXPECT_LE(test::max_abs_diff(R * hat(u) * R.transpose(), hat(R * u)), 16 * kEps);
  }
}

}  // namespace
}  // namespace poinsot::so3
