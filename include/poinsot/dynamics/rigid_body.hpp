#pragma once
/// @file rigid_body.hpp
/// The constant model of a rotating rigid body: its inertia and, for a heavy top, its mass and the vector
/// from the fixed pivot to the centre of mass. Separate from the mutable State (Pinocchio/MuJoCo style): a
/// RigidBody is built once, validated, and shared read-only by integrators, torques and analyses.
///
/// Frames and points. `inertia_com()` is J about the centre of mass in the body frame (kg·m²). The body
/// rotates about its *rotation point*: the centre of mass for a free body, the pivot for a top. `inertia()`
/// is J about the rotation point, `J = J_com + m(|d|² I − d⊗d)` (parallel-axis theorem) with d =
/// pivot_to_com_body; it is the J of Euler's equations `J ω̇ + ω × J ω = τ_body` and of the Poinsot tensor `K
/// = tr(J)/2·I − J` (docs/conventions.md).

#include "poinsot/core/types.hpp"

namespace poinsot::dynamics {

class RigidBody {
 public:
  /// A free body whose body frame is its principal frame: `J = diag(moments)` (kg·m²). Throws InvalidInput
  /// unless the moments are finite, non-negative, not all zero, and satisfy the triangle inequality.
  static RigidBody from_principal_moments(const Vec3& moments);
  /// A free body with the full inertia tensor J about its centre of mass in the body frame (kg·m²). Throws
  /// InvalidInput unless J is symmetric, positive semi-definite and satisfies the triangle inequality.
  static RigidBody from_inertia(const Mat3& inertia_com_body);

  /// The same body held at a fixed pivot: `mass` (kg) and the vector from the pivot to the centre of mass in
  /// the body frame (m). Gravity then acts through TorqueModel::gravity. Throws InvalidInput for mass <= 0 or
  /// non-finite input.
  RigidBody with_pivot(double mass, const Vec3& pivot_to_com_body) const;

  const Mat3& inertia_com() const { return inertia_com_; }  ///< J about the centre of mass, body frame
  const Mat3& inertia() const { return inertia_; }          ///< J about the rotation point, body frame
  const Mat3& inertia_inverse() const {
    return inertia_inverse_;
  }  ///< J⁻¹ (J is invertible: no point masses)
  /// K = tr(J)/2·I − J about the rotation point, body frame (kg·m²). Singular for plane laminae: never
  /// inverted.
  const Mat3& poinsot() const { return poinsot_; }
  /// Eigenvalues of inertia(), ascending (kg·m²).
  const Vec3& principal_moments() const { return principal_moments_; }
  /// Columns: the principal axes of inertia() in the body frame, a proper rotation (det = +1).
  const Mat3& principal_axes() const { return principal_axes_; }
  /// True when inertia() is diagonal in the body frame (off-diagonal entries exactly zero).
  bool is_diagonal() const { return diagonal_; }
  double mass() const { return mass_; }                       ///< kg; 0 for a free body given by inertia only
  const Vec3& pivot_to_com() const { return pivot_to_com_; }  ///< body frame, m; zero for a free body
  bool has_pivot() const { return has_pivot_; }

 private:
  RigidBody() = default;
  void derive();  // fills inertia_, inverse, poinsot_, principal data from inertia_com_, mass_, pivot_to_com_

  Mat3 inertia_com_ = Mat3::Identity();
  Mat3 inertia_ = Mat3::Identity();
  Mat3 inertia_inverse_ = Mat3::Identity();
  Mat3 poinsot_ = 0.5 * Mat3::Identity();
  Vec3 principal_moments_ = Vec3::Ones();
  Mat3 principal_axes_ = Mat3::Identity();
  bool diagonal_ = true;
  double mass_ = 0.0;
  Vec3 pivot_to_com_ = Vec3::Zero();
  bool has_pivot_ = false;
};

}  // namespace poinsot::dynamics
