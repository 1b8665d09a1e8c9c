#include "poinsot/so3/euler_angles.hpp"

#include <numbers>
#include <vector>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::so3 {
namespace {
using test::kEps;

std::vector<EulerSequence> all_sequences() {
  std::vector<EulerSequence> out;
  for (const char* s : {"XYZ", "XZY", "YXZ", "YZX", "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"}) {
    out.push_back(EulerSequence::parse(s));
  }
  return out;
}

/// Independent oracle: the product of three elementary rotations by Eigen's AngleAxis.
Mat3 oracle(const EulerSequence& s, const Vec3& a) {
  Mat3 R = Mat3::Identity();
  for (int i = 0; i < 3; ++i)
    R = R * Eigen::AngleAxisd(a[i], Vec3::Unit(s.axes()[i])).toRotationMatrix();
  return R;
}

TEST(EulerAngles, AnglesToMatrixIsTheIntrinsicProduct) {
  for (const auto& s : all_sequences()) {
    for (int i = 0; i < 200; ++i) {
      const Vec3 a = test::random_vector(std::numbers::pi);
      EXPECT_LE(test::max_abs_diff(rotation_from_euler(s, a), oracle(s, a)), 8 * kEps) << s.name();
    }
  }
}

TEST(EulerAngles, ZYXIsYawPitchRoll) {
  const Vec3 a(0.3, -0.2, 0.1);
  const Mat3 expected = Eigen::AngleAxisd(0.3, Vec3::UnitZ()).toRotationMatrix() *
                        Eigen::AngleAxisd(-0.2, Vec3::UnitY()).toRotationMatrix() *
                        Eigen::AngleAxisd(0.1, Vec3::UnitX()).toRotationMatrix();
  EXPECT_LE(test::max_abs_diff(rotation_from_euler(EulerSequence::ZYX(), a), expected), 4 * kEps);
}

TEST(EulerAngles, ClassicalZXZOfTopsPutsTheSymmetryAxisAtPolarAngleTheta) {
  // For R = Rz(φ) Rx(θ) Rz(ψ) the body z axis (the top's axis) is at polar angle θ and azimuth φ − π/2.
  const double phi = 0.7, theta = 0.4, psi = 2.1;
  const Vec3 axis = rotation_from_euler(EulerSequence::ZXZ(), Vec3(phi, theta, psi)) * Vec3::UnitZ();
  EXPECT_NEAR(std::acos(axis.z()), theta, 4 * kEps);
  EXPECT_NEAR(std::atan2(axis.y(), axis.x()), phi - std::numbers::pi / 2, 4 * kEps);
}

TEST(EulerAngles, GimbalLockStillReproducesTheMatrix) {
  for (const auto& s : all_sequences()) {
    const std::vector<double> locks = s.is_proper()
                                          ? std::vector<double>{0.0, std::numbers::pi}
                                          : std::vector<double>{-std::numbers::pi / 2, std::numbers::pi / 2};
    for (double lock : locks) {
      const Vec3 a(0.4, lock, -1.1);
      const Mat3 R = rotation_from_euler(s, a);
      const Vec3 back = euler_from_rotation(s, R);
      EXPECT_LE(test::max_abs_diff(rotation_from_euler(s, back), R), 1e-8) << s.name() << " lock " << lock;
      EXPECT_EQ(back[2], 0.0) << s.name();
    }
  }
}

TEST(EulerAngles, ParseAcceptsValidNamesAndRejectsOthers) {
  EXPECT_EQ(EulerSequence::parse("zyx").name(), "ZYX");
  EXPECT_TRUE(EulerSequence::parse("ZXZ").is_proper());
  EXPECT_FALSE(EulerSequence::parse("XYZ").is_proper());
  for (const char* bad : {"ZZX", "XYY", "AB", "XYZW", "ZQZ", ""}) {
    EXPECT_THROW(EulerSequence::parse(bad), InvalidInput) << bad;
  }
  EXPECT_THROW(rotation_from_euler(EulerSequence::ZYX(), Vec3(0, NAN, 0)), InvalidInput);
}

}  // namespace
}  // namespace poinsot::so3
