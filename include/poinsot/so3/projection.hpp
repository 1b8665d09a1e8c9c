#pragma once
/// @file projection.hpp
/// Orthogonality error and the projection of a nearly orthogonal matrix onto SO(3).
///
/// The nearest rotation to M in the Frobenius norm is the orthogonal factor of its polar decomposition
/// `M = Q S` (Higham 1986): with the SVD `M = U Σ Vᵀ`, `Q = U diag(1, 1, det(U Vᵀ)) Vᵀ`.

#include "poinsot/core/types.hpp"

namespace poinsot::so3 {

/// `‖RᵀR − I‖_F`: zero for a rotation, a measure of the drift of a numerically propagated one.
double orthogonality_error(const Mat3& R);

/// `RᵀR − I`, the orthogonality defect of a nearly orthogonal matrix (its Frobenius norm is
/// orthogonality_error(R)).
inline Mat3 orthogonality_defect(const Mat3& R) {
  return R.transpose() * R - Mat3::Identity();
}

/// One Björck–Bowie (Newton–Schulz) step towards the nearest rotation, `R ← R − ½ R E` with
/// `E = RᵀR − I` = orthogonality_defect(R): writing R = U(I + S) (polar decomposition), E = 2S + S² and the
/// step leaves E′ ≈ −¾E², so from ‖E‖ = δ one step leaves O(δ²) and moves R by O(δ). The integrators apply it
/// to remove the rounding their updates accumulate in RᵀR = I.
inline void bjorck_step(Mat3& R, const Mat3& E) {
  R -= 0.5 * (R * E);
}
inline void bjorck_step(Mat3& R) {
  bjorck_step(R, orthogonality_defect(R));
}

/// The rotation nearest to M (Frobenius norm). Throws InvalidInput when M has non-finite entries, det M ≤ 0
/// (a reflection or a singular matrix has no meaningful nearest rotation), or `orthogonality_error(M)`
/// exceeds `max_orthogonality_error` (the matrix is not a rotation with noise but something else).
Mat3 project_to_so3(const Mat3& M, double max_orthogonality_error = 0.1);

}  // namespace poinsot::so3
