#pragma once
/// @file validity.hpp
/// Is a tensor the inertia tensor J of a physical body, and if not, which is the nearest one that is?
///
/// J (kg·m², about any point) is physical when it is symmetric and its principal moments I1 <= I2 <= I3
/// satisfy
///   I1 >= 0 (positive semi-definite)   and   Ii + Ij >= Ik for every permutation (triangle inequality).
/// Both follow from J = tr(K)·I − K with K = ∫ρ X⊗X positive semi-definite: the principal values of K are
/// (Ij + Ik − Ii)/2 >= 0 (docs/conventions.md conventions; Kane & Levinson 1985, §3.5). The triangle
/// inequalities imply I1 >= 0, so the valid moments form the convex cone C = {I : Ii + Ij >= Ik}. Each
/// condition is tested with a tolerance `rel_tol · tr(J)` (default 1e-10 · tr J), so that a lamina computed
/// in floating point (I1 + I2 = I3 up to round-off) is valid.
///
/// Repair (explicit, never silent): the nearest valid tensor in the Frobenius norm with the same principal
/// axes is Q diag(μ) Qᵀ, where Q are the axes of the symmetric part and μ is the Euclidean projection of the
/// moments onto C (computed exactly by enumerating the faces of C). The distance reported is
/// ‖J − J_repaired‖_F, which includes the removed antisymmetric part.

#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"

namespace poinsot::inertia {

/// Default relative tolerance of the validity test (times the trace).
inline constexpr double kDefaultValidityTolerance = 1e-10;

/// Outcome of check_inertia.
struct InertiaCheck {
  bool valid = true;
  /// Which condition fails: "" when valid, else "non-finite", "not symmetric",
  /// "negative moment" or "triangle inequality".
  std::string condition;
  double amount = 0.0;          ///< by how much it fails (kg·m²): asymmetry, negative moment, or shortfall
  std::string message;          ///< one line, e.g. "inertia: principal moments (1, 1, 5) kg·m² violate ..."
  Vec3 moments = Vec3::Zero();  ///< principal moments of the symmetric part, ascending (kg·m²)
};

/// Tests J (kg·m²) for finiteness, symmetry, I1 >= 0 and the triangle inequalities,
/// each to `rel_tol · tr(J)` (symmetry: to rel_tol times the largest entry). Never throws for a bad tensor:
/// the result says what fails; throws InvalidInput only for a bad `rel_tol`. `what` prefixes the message.
/// A zero tensor (point mass) is valid.
InertiaCheck check_inertia(const Mat3& J, double rel_tol = kDefaultValidityTolerance,
                           std::string_view what = "inertia");

/// Throws InvalidInput with check_inertia's message unless J is valid.
void require_valid_inertia(const Mat3& J, std::string_view what = "inertia",
                           double rel_tol = kDefaultValidityTolerance);

/// Result of repair_inertia.
struct InertiaRepair {
  Mat3 inertia = Mat3::Zero();         ///< the nearest valid tensor (kg·m²)
  Vec3 moments_before = Vec3::Zero();  ///< ascending principal moments of the symmetric part of the input
  Vec3 moments_after = Vec3::Zero();   ///< the same axes' moments after the repair (ascending)
  double distance = 0.0;               ///< ‖J − repaired‖_F (kg·m²); 0 when J was already valid
};

/// The nearest physically valid tensor to J (see the file comment). Throws InvalidInput for non-finite J.
InertiaRepair repair_inertia(const Mat3& J);

/// Euclidean projection of three moments (any order, kg·m²) onto the cone Ii + Ij >= Ik (returned in the same
/// order as given).
Vec3 project_moments_to_valid(const Vec3& moments);

}  // namespace poinsot::inertia
