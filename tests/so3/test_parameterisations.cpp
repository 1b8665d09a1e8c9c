// One property suite run over every parameterisation of rotations in so3/ (the rotation vector of exp/log,
// the unit quaternion, axis and angle, the Cayley vector, and Euler angles in each of the twelve sequences):
//  - matrix → parameters → matrix gives back a random rotation (Haar-distributed), and the parameters land
//    in the canonical domain that the header states;
//  - parameters → matrix → parameters gives back parameters drawn inside that domain, to the conditioning
//    of the inverse map there;
//  - the matrix of any parameters is a rotation (RᵀR = I, det R = +1) to round-off;
//  - the derivative by central differences along every coordinate is tangent to SO(3) (Rᵀ ∂R skew, to the
//    differences' O(h²) truncation and ε/h rounding) and of rank 3 away from the parameterisation's
//    singularities, so the map is a local chart there.
// Special values (half-turns, gimbal lock, tiny angles, bad input) stay in each parameterisation's own file.
#include <gtest/gtest.h>
#include <numbers>
#include <string>

#include "poinsot/core/linear_solvers.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/cayley.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot/so3/rotation_check.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;
constexpr double kPi = std::numbers::pi;
using Coords = Eigen::VectorXd;

// Each parameterisation: its coordinates as a vector, to_matrix and from_matrix, a draw inside its canonical
// domain (away from its singular set), the domain test, and the round-trip tolerance at given coordinates.

struct RotationVector {
  static constexpr const char* kName = "rotation vector (exp/log)";
  static Mat3 to_matrix(const Coords& p) { return exp(Vec3(p)); }
  static Coords from_matrix(const Mat3& R) { return log(R); }
  static Coords draw() { return test::random_unit_vector() * test::uniform(0.0, kPi * (1 - 1e-9)); }
  static bool in_domain(const Coords& p) { return p.norm() <= kPi; }
  static double tolerance(const Coords& p) { return 16 * kEps * std::max(1.0, p.norm()); }
  static double matrix_tolerance(const Coords&) { return 16 * kEps; }
};

struct UnitQuaternion {
  static constexpr const char* kName = "unit quaternion";
  static Mat3 to_matrix(const Coords& p) {
    return rotation_from_quaternion(quaternion_wxyz(p[0], p[1], p[2], p[3]));
  }
  static Coords from_matrix(const Mat3& R) {
    const Quat q = quaternion_from_rotation(R);
    return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
  }
  static Coords draw() {
    const Quat q = canonical_unit_quaternion(test::random_quaternion());
    return Eigen::Vector4d(q.w(), q.x(), q.y(), q.z());
  }
  static bool in_domain(const Coords& p) { return p[0] >= 0.0 && std::abs(p.norm() - 1.0) <= 2 * kEps; }
  static double tolerance(const Coords&) { return 8 * kEps; }
  static double matrix_tolerance(const Coords&) { return 16 * kEps; }
};

struct AxisAndAngle {
  static constexpr const char* kName = "axis and angle";
  static Mat3 to_matrix(const Coords& p) { return rotation_from_axis_angle(p.head<3>(), p[3]); }
  static Coords from_matrix(const Mat3& R) {
    const AxisAngle a = axis_angle_from_rotation(R);
    return Eigen::Vector4d(a.axis.x(), a.axis.y(), a.axis.z(), a.angle);
  }
  static Coords draw() {
    const Vec3 n = test::random_unit_vector();
    return Eigen::Vector4d(n.x(), n.y(), n.z(), test::uniform(1e-6, kPi - 1e-6));
  }
  static bool in_domain(const Coords& p) {
    return p[3] >= 0.0 && p[3] <= kPi && std::abs(p.head<3>().norm() - 1.0) <= 4 * kEps;
  }
  // The axis of the angle θ is determined to ~ε/sin θ.
  static double tolerance(const Coords& p) { return 8 * kEps / std::sin(p[3]) + 8 * kEps; }
  static double matrix_tolerance(const Coords&) { return 16 * kEps; }
};

struct CayleyVector {
  static constexpr const char* kName = "Cayley vector";
  static Mat3 to_matrix(const Coords& p) { return cayley(Vec3(p)); }
  static Coords from_matrix(const Mat3& R) { return cayley_inverse(R); }
  static Coords draw() { return test::random_vector(10.0); }
  static bool in_domain(const Coords& p) { return p.allFinite(); }
  // |c| = tan(θ/2): the inverse's conditioning grows as 1/(1 + tr R) = (1 + |c|²)/4, unbounded near the
  // half-turns, where Haar-random rotations fall now and then.
  static double tolerance(const Coords& p) { return 64 * kEps * (1.0 + p.squaredNorm()); }
  static double matrix_tolerance(const Coords& p) { return 16 * kEps * (1.0 + p.squaredNorm()); }
};

template <char A, char B, char C>
struct Euler {
  static EulerSequence sequence() { return EulerSequence::parse(std::string{A, B, C}); }
  static constexpr const char* kName = "Euler angles";
  static Mat3 to_matrix(const Coords& p) { return rotation_from_euler(sequence(), Vec3(p)); }
  static Coords from_matrix(const Mat3& R) { return euler_from_rotation(sequence(), R); }
  static Coords draw() {
    const bool proper = sequence().is_proper();
    return Vec3(test::uniform(-kPi + 0.01, kPi - 0.01),
                proper ? test::uniform(0.01, kPi - 0.01) : test::uniform(-kPi / 2 + 0.01, kPi / 2 - 0.01),
                test::uniform(-kPi + 0.01, kPi - 0.01));
  }
  static bool in_domain(const Coords& p) {
    const bool middle =
        sequence().is_proper() ? p[1] >= 0.0 && p[1] <= kPi : std::abs(p[1]) <= kPi / 2 + 4 * kEps;
    return middle && std::abs(p[0]) <= kPi && std::abs(p[2]) <= kPi;
  }
  // The outer angles are determined to ~ε/sin(distance to gimbal lock), ≈ 100 ε for the draws above.
  static double tolerance(const Coords&) { return 400 * kEps; }
  static double matrix_tolerance(const Coords&) { return 16 * kEps; }
};

template <class P>
class Parameterisation : public ::testing::Test {};

using All =
    ::testing::Types<RotationVector, UnitQuaternion, AxisAndAngle, CayleyVector, Euler<'Z', 'Y', 'X'>,
                     Euler<'X', 'Y', 'Z'>, Euler<'X', 'Z', 'Y'>, Euler<'Y', 'X', 'Z'>, Euler<'Y', 'Z', 'X'>,
                     Euler<'Z', 'X', 'Y'>, Euler<'Z', 'X', 'Z'>, Euler<'X', 'Y', 'X'>, Euler<'X', 'Z', 'X'>,
                     Euler<'Y', 'X', 'Y'>, Euler<'Y', 'Z', 'Y'>, Euler<'Z', 'Y', 'Z'>>;
TYPED_TEST_SUITE(Parameterisation, All);

TYPED_TEST(Parameterisation, MatrixRoundTripLandsInTheCanonicalDomain) {
  for (int i = 0; i < 1000; ++i) {
    const Mat3 R = test::random_rotation();
    const Coords p = TypeParam::from_matrix(R);
    EXPECT_TRUE(TypeParam::in_domain(p)) << TypeParam::kName << ": " << p.transpose();
    EXPECT_LE(test::max_abs_diff(TypeParam::to_matrix(p), R), TypeParam::matrix_tolerance(p))
        << TypeParam::kName;
  }
}

TYPED_TEST(Parameterisation, ParametersRoundTripInsideTheDomain) {
  for (int i = 0; i < 1000; ++i) {
    const Coords p = TypeParam::draw();
    ASSERT_TRUE(TypeParam::in_domain(p));
    const Coords back = TypeParam::from_matrix(TypeParam::to_matrix(p));
    EXPECT_LE((back - p).cwiseAbs().maxCoeff(), TypeParam::tolerance(p))
        << TypeParam::kName << ": " << p.transpose();
  }
}

TYPED_TEST(Parameterisation, ResultIsARotation) {
  for (int i = 0; i < 1000; ++i) {
    Coords p = TypeParam::draw();
    if (i % 2 == 1) p *= 3.0;  // outside the canonical domain too (a quaternion is normalised first)
    const Mat3 R = TypeParam::to_matrix(p);
    EXPECT_LE(orthogonality_error(R), 16 * kEps) << TypeParam::kName << ": " << p.transpose();
    EXPECT_NEAR(R.determinant(), 1.0, 16 * kEps) << TypeParam::kName;
  }
}

TYPED_TEST(Parameterisation, DerivativeIsTangentToSO3AndOfRankThree) {
  // Central differences with h = 1e-5: truncation ~h² |∂³R| ≈ 1e-10, rounding ~ε/h ≈ 2e-11.
  constexpr double h = 1e-5, tangent_tolerance = 1e-8;
  for (int i = 0; i < 200; ++i) {
    const Coords p = TypeParam::draw();
    const Mat3 R = TypeParam::to_matrix(p);
    Eigen::Matrix<double, 3, Eigen::Dynamic> omegas(3, p.size());
    for (Eigen::Index k = 0; k < p.size(); ++k) {
      Coords step = Coords::Zero(p.size());
      step[k] = h;
      const Mat3 A =
          R.transpose() * (TypeParam::to_matrix(p + step) - TypeParam::to_matrix(p - step)) / (2 * h);
      EXPECT_LE((A + A.transpose()).cwiseAbs().maxCoeff(), tangent_tolerance * std::max(1.0, A.norm()))
          << TypeParam::kName << ": " << p.transpose() << ", coordinate " << k;
      omegas.col(k) = vee(A);
    }
    // The body angular velocities of the coordinate directions span R³: the smallest of the three singular
    // values is bounded away from 0 (sin 0.01 for Euler angles near gimbal lock, 2/(1 + |c|²) for Cayley).
    EXPECT_GT(right_singular_vectors(omegas).singular_values[2], 1e-3)
        << TypeParam::kName << ": " << p.transpose();
  }
}

}  // namespace
}  // namespace poinsot::so3
