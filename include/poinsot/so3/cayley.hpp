#pragma once
/// @file cayley.hpp
/// The Cayley transform between 3-vectors and rotations, used by implicit Lie-group integrators (Newton on a
/// Cayley vector, Lee, Leok & McClamroch 2007):
///
///     cay(c) = (I − j(c))⁻¹ (I + j(c)) = I + 2/(1 + |c|²) · (j(c) + j(c)²),
///
/// the rotation by the angle 2·atan|c| about c/|c| (so |c| = tan(θ/2), the Gibbs–Rodrigues vector). Its
/// inverse is `c = vee(R − Rᵀ) / (1 + tr R)`, defined for every rotation except the half-turns (θ = π, tr R =
/// −1).

#include "poinsot/core/types.hpp"

namespace poinsot::so3 {

/// cay(c): the rotation of the Gibbs vector c (dimensionless). No validation, no allocation.
Mat3 cayley(const Vec3& c);

/// The Gibbs vector of R. Throws InvalidInput for a half-turn (1 + tr R ≤ 1e-12), which has none.
Vec3 cayley_inverse(const Mat3& R);

}  // namespace poinsot::so3
