#include "poinsot/so3/euler_angles.hpp"

#include <cctype>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "rotation_check.hpp"

namespace poinsot::so3 {
namespace {

/// Wraps an angle into (−π, π].
double wrap(double a) {
  a = std::remainder(a, 2.0 * std::numbers::pi);  // [−π, π]
  return a <= -std::numbers::pi ? a + 2.0 * std::numbers::pi : a;
}

}  // namespace

EulerSequence EulerSequence::parse(std::string_view name) {
  const auto fail = [&] {
    return InvalidInput(
        fmt::format("euler: sequence \"{}\" is not valid; expected three letters of X, Y, Z with no "
                    "two consecutive equal, e.g. \"ZYX\" or \"ZXZ\"",
                    name));
  };
  if (name.size() != 3) throw fail();
  std::array<int, 3> axes{};
  for (std::size_t i = 0; i < 3; ++i) {
    const char c = static_cast<char>(std::toupper(static_cast<unsigned char>(name[i])));
    if (c < 'X' || c > 'Z') throw fail();
    axes[i] = c - 'X';
  }
  if (axes[0] == axes[1] || axes[1] == axes[2]) throw fail();
  return EulerSequence(axes);
}

std::string EulerSequence::name() const {
  std::string s(3, ' ');
  for (std::size_t i = 0; i < 3; ++i)
    s[i] = static_cast<char>('X' + axes_[i]);
  return s;
}

Mat3 rotation_from_euler(const EulerSequence& sequence, const Vec3& angles) {
  require_finite(fmt::format("euler {}: angles (rad)", sequence.name()), angles);
  Mat3 R = Mat3::Identity();
  for (int i = 0; i < 3; ++i)
    R = R * exp(angles[i] * Vec3::Unit(sequence.axes()[i]));
  return R;
}

Vec3 euler_from_rotation(const EulerSequence& sequence, const Mat3& R) {
  require_rotation(fmt::format("euler {}", sequence.name()), R, kRotationInputTolerance);
  const Quat q = detail::quaternion_of_rotation_unchecked(R);
  // Bernardes & Viollet (2022) work with extrinsic sequences; the intrinsic sequence (a, b, c) is the
  // extrinsic (c, b, a) with the angles in reverse order.
  const int i = sequence.axes()[2];
  const int j = sequence.axes()[1];
  const bool proper = sequence.is_proper();
  const int k = proper ? 3 - i - j : sequence.axes()[0];
  const double sign = static_cast<double>((i - j) * (j - k) * (k - i) / 2);  // +1 for a cyclic (i, j, k)
  const double qv[3] = {q.x(), q.y(), q.z()};
  double a, b, c, d;
  if (proper) {
    a = q.w();
    b = qv[i];
    c = qv[j];
    d = qv[k] * sign;
  } else {
    a = q.w() - qv[j];
    b = qv[i] + qv[k] * sign;
    c = qv[j] + q.w();
    d = qv[k] * sign - qv[i];
  }
  double second = 2.0 * std::atan2(std::hypot(c, d), std::hypot(a, b));  // ∈ [0, π]
  const double half_sum = std::atan2(b, a);
  const double half_diff = std::atan2(d, c);
  // Extrinsic angles (first about axis i, last about axis k); at gimbal lock the intrinsic last angle
  // (= extrinsic first) is set to zero.
  double first;
  double third;
  constexpr double kLock = 1e-9;  // rad; below this the two outer axes are aligned to round-off
  if (second <= kLock) {
    first = 0.0;
    third = 2.0 * half_sum;
  } else if (second >= std::numbers::pi - kLock) {
    first = 0.0;
    third = 2.0 * half_diff;
  } else {
    first = half_sum - half_diff;
    third = half_sum + half_diff;
  }
  if (!proper) {
    third *= sign;
    second -= 0.5 * std::numbers::pi;
  }
  // Intrinsic order is the reverse of the extrinsic one.
  return Vec3(wrap(third), second, wrap(first));
}

}  // namespace poinsot::so3
