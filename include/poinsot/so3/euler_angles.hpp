#pragma once
/// @file euler_angles.hpp
/// Euler angles with the sequence always named. All twelve sequences are supported, as *intrinsic* rotations
/// (about the axes of the body as it turns): the sequence "ZYX" with angles (a1, a2, a3) is
///
///     R = R_z(a1) · R_y(a2) · R_x(a3),
///
/// which maps body to space (yaw a1, pitch a2, roll a3 of aerospace), and the classical "ZXZ" (3-1-3) of tops
/// (Goldstein §4.4) is `R = R_z(φ) R_x(θ) R_z(ψ)` with precession φ, nutation θ and spin ψ. An extrinsic
/// sequence (about fixed space axes) equals the reversed intrinsic one with the angles reversed.
///
/// Ranges of the angles returned: a1, a3 ∈ (−π, π]; a2 ∈ [0, π] for the six proper Euler sequences (first
/// axis = last axis) and a2 ∈ [−π/2, π/2] for the six Tait–Bryan ones. At gimbal lock (a2 = 0 or π for
/// proper, ±π/2 for Tait–Bryan) only a combination of a1 and a3 is defined; a3 = 0 is returned. The
/// extraction uses the quaternion method of Bernardes & Viollet (2022, PLoS ONE 17(11) e0276302), uniform
/// over the twelve sequences and free of the loss of accuracy of asin near ±π/2.

#include <array>
#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"

namespace poinsot::so3 {

/// An intrinsic rotation sequence: three axis indices (0 = x, 1 = y, 2 = z), consecutive ones different.
class EulerSequence {
 public:
  /// Parses "ZYX", "zxz", "XYZ", ... (case-insensitive, three letters of x, y, z, no two consecutive equal).
  /// Throws InvalidInput naming the string and the valid forms otherwise.
  static EulerSequence parse(std::string_view name);
  static EulerSequence ZYX() { return EulerSequence({2, 1, 0}); }  ///< yaw-pitch-roll (Tait–Bryan, 3-2-1)
  static EulerSequence ZXZ() { return EulerSequence({2, 0, 2}); }  ///< classical 3-1-3 of tops
  static EulerSequence XYZ() { return EulerSequence({0, 1, 2}); }  ///< Cardan 1-2-3

  const std::array<int, 3>& axes() const { return axes_; }
  /// True when the first and last axes are the same (proper Euler angles), false for Tait–Bryan angles.
  bool is_proper() const { return axes_[0] == axes_[2]; }
  /// "ZYX", upper case.
  std::string name() const;

 private:
  explicit EulerSequence(std::array<int, 3> axes) : axes_(axes) {}
  std::array<int, 3> axes_;
};

/// `R = R_{a}(angles[0]) R_{b}(angles[1]) R_{c}(angles[2])` for the sequence (a, b, c), angles in radians.
/// Throws InvalidInput for non-finite angles.
Mat3 rotation_from_euler(const EulerSequence& sequence, const Vec3& angles);

/// The angles of R in the sequence, in the ranges stated in the file comment. R must be a rotation
/// (see quaternion_from_rotation).
Vec3 euler_from_rotation(const EulerSequence& sequence, const Mat3& R);

}  // namespace poinsot::so3
