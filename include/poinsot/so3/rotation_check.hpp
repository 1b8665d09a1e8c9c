#pragma once
/// @file rotation_check.hpp
/// "Is R a rotation?": the one predicate of the library, with its tolerances, on the one orthogonality metric
/// (like Drake's RotationMatrix::IsValid).
///
/// The metric is `orthogonality_error(R) = ‖RᵀR − I‖_F` (projection.hpp), the Frobenius norm, because it does
/// not depend on the frame: ‖Qᵀ(RᵀR − I)Q‖_F = ‖RᵀR − I‖_F for any rotation Q, so a body's error is the same
/// whichever frame its inertia was written in (the largest entry is not). For R = U(I + S) (polar factor U,
/// S symmetric and small), RᵀR − I = 2S + S², so the metric is twice the Frobenius distance ‖R − U‖_F to the
/// nearest rotation, to first order. It is what every report, summary, diagnostic and test prints.
///
/// R is a rotation when it is finite, orthogonality_error(R) ≤ tolerance and det R > 0.

#include <string_view>

#include "poinsot/core/types.hpp"
#include "poinsot/so3/projection.hpp"

namespace poinsot::so3 {

/// The tolerance for a rotation that is used as it is (an initial state, a model's fixed relative rotation,
/// the state checked before an integration): 1e-9. Integrators keep RᵀR − I at round-off (1e-15 to 1e-12
/// after 10⁶ steps), so a state they wrote and a matrix printed with 17 digits pass with a margin of 10³;
/// and an error of 1e-9 changes the energy and |L| of a body by about 1e-9 relative, below the accuracy any
/// run is asked for, while a typing error in the 9th digit is caught.
inline constexpr double kRotationTolerance = 1e-9;

/// The tolerance for a matrix typed by a user (a scenario file's orientation, an argument of so3's
/// conversions), which is then projected onto SO(3) or whose result is only as accurate as it: 1e-6. A matrix
/// whose entries are rounded to 7 significant digits (error ≤ 5e-8 each) has ‖RᵀR − I‖_F ≤ 6·√3·5e-8 ≈
/// 5e-7 and passes; one wrong digit in the first six does not.
inline constexpr double kRotationInputTolerance = 1e-6;

/// True when R is finite, ‖RᵀR − I‖_F ≤ tolerance and det R > 0.
bool is_rotation(const Mat3& R, double tolerance = kRotationTolerance);

/// Throws InvalidInput unless is_rotation(R, tolerance), with a one-line message naming `what`, the matrix,
/// its error and the tolerance (or its determinant).
void require_rotation(std::string_view what, const Mat3& R, double tolerance = kRotationTolerance);

}  // namespace poinsot::so3
