#pragma once
/// @file mass_properties.hpp
/// Mass properties of a rigid body: mass m (kg), centre of mass c (m) and the classical inertia tensor J
/// about the centre of mass (kg·m²), both expressed in one frame F named by the caller (the part's own frame,
/// the body frame of a composite, ...).
///
/// Definitions (docs/conventions.md, conventions table). With X the position relative to the reference point,
///   J = ∫ρ (|X|² I − X⊗X) dV          (products of inertia are the off-diagonal entries, J_xy = −∫ρ x y),
///   K = ∫ρ X⊗X dV = tr(J)/2·I − J      (Poinsot / second-moment tensor; J = tr(K)·I − K).
/// K is singular for plane laminae: it is never inverted here.
///
/// Parallel-axis theorem (Goldstein, Classical Mechanics, 3rd ed., §5.3; Kane & Levinson 1985, §3.7): about a
/// point P with d = c − P,  J_P = J_c + m (|d|² I − d⊗d).  Re-expression in a frame B rotated from F by R_B_F
/// (x_B = R_B_F x_F):  J_B = R_B_F J_F R_B_Fᵀ.  Composite bodies add the masses, the first moments m c and
/// the tensors about one common point; voids subtract them (Kane & Levinson §3.8).

#include "poinsot/core/types.hpp"

namespace poinsot::inertia {

/// J → K = tr(J)/2·I − J (kg·m²), about the same point and in the same frame.
Mat3 poinsot_from_inertia(const Mat3& J);
/// K → J = tr(K)·I − K (kg·m²), about the same point and in the same frame.
Mat3 inertia_from_poinsot(const Mat3& K);

/// Parallel-axis theorem, centre of mass → point: J about `point` (m) for a body of `mass` (kg) whose centre
/// of mass is `com` and whose tensor about it is `J_com` (kg·m²), all in one frame: J_com + m(|d|² I − d⊗d),
/// d = com − point. Throws InvalidInput for a negative or non-finite mass or non-finite input.
Mat3 shift_from_com(const Mat3& J_com, double mass, const Vec3& com, const Vec3& point);
/// Parallel-axis theorem, point → centre of mass: the inverse of shift_from_com,
/// J_com = J_point − m(|d|² I − d⊗d), d = com − point. Same throws.
Mat3 shift_to_com(const Mat3& J_point, double mass, const Vec3& com, const Vec3& point);
/// Re-expression of a tensor (J or K, kg·m²) given in frame F in a frame B, x_B = R_B_F x_F: R J Rᵀ. The
/// result is symmetrised (round-off). Throws InvalidInput unless R_B_F is a rotation to 1e-9.
Mat3 reexpress(const Mat3& tensor_F, const Mat3& R_B_F);

/// Mass properties in a frame F: mass (kg), centre of mass (m) and J about the centre of mass (kg·m²).
struct MassProperties {
  double mass = 0.0;                ///< kg, >= 0
  Vec3 com = Vec3::Zero();          ///< centre of mass in F, m
  Mat3 inertia_com = Mat3::Zero();  ///< J about the centre of mass, axes of F, kg·m²

  /// J about `point` (given in F, m), axes of F (kg·m²): the parallel-axis theorem.
  Mat3 inertia_about(const Vec3& point) const;
  /// K = tr(J)/2·I − J about the centre of mass, axes of F (kg·m²).
  Mat3 poinsot_com() const;
  /// The same body described in a parent frame P where this part has pose (R_P_F, position_P):
  /// x_P = R_P_F x_F + position_P (m). The centre of mass moves with the pose, J is re-expressed.
  MassProperties placed(const Mat3& R_P_F, const Vec3& position_P) const;
};

/// Mass properties from a tensor known about a point: `J_point` about `point`, mass and centre of mass, all
/// in frame F. Inverse of MassProperties::inertia_about.
MassProperties from_inertia_about(double mass, const Vec3& com, const Mat3& J_point, const Vec3& point);

/// The union of two bodies in one frame: masses add, centres of mass average by mass, tensors add about a
/// common point and are shifted to the new centre of mass (Kane & Levinson §3.8). Throws InvalidInput if the
/// total mass is not positive.
MassProperties combine(const MassProperties& a, const MassProperties& b);
/// `whole` with the part `removed` taken out (a hole or void, given with the mass of the removed material):
/// m = m_w − m_r, c = (m_w c_w − m_r c_r)/m, J about c from the difference of the tensors about a common
/// point. Throws InvalidInput when the removed mass is not less than the whole's (message gives both). The
/// result is not validated: a void that does not lie inside the whole can give an invalid tensor; use
/// check_inertia (validity.hpp) on it.
MassProperties subtract(const MassProperties& whole, const MassProperties& removed);

}  // namespace poinsot::inertia
