#pragma once
/// @file principal_axes.hpp
/// Principal moments and axes of a symmetric 3×3 tensor (J or K), and the symmetry class of a body.
///
/// Eigensolver. The cyclic Jacobi method (Jacobi 1846; Golub & Van Loan, Matrix Computations, 4th ed., §8.5;
/// rotation angle computed as in Rutishauser 1971 / Numerical Recipes §11.1): plane rotations annihilate the
/// off-diagonal entries until they are below the rounding level of the diagonal. It is backward stable, so
/// each eigenvalue is accurate to a few ulps of the trace also when two or three are nearly equal (the
/// closed-form cubic solution, e.g. Eigen's computeDirect, loses up to half the digits there). On a 2×2 block
/// with equal diagonal entries it produces the rotation by exactly π/4, so the lecture's square plate about
/// its corner (LEC, eq. for I about the corner) gives m a²·(1/12, 7/12, 2/3) and axes (1,1,0)/√2,
/// (1,−1,0)/√2, ±z to round-off.
///
/// Ordering and sign rule (deterministic). Moments ascending, I1 <= I2 <= I3. The axes are the columns a1,
/// a2, a3 of a proper rotation (det = +1): a1 and a2 each have their component of largest magnitude positive
/// (when several components agree in magnitude to 1e-12 relative, the first of them, in the order x, y, z, is
/// made positive); a3 = a1 × a2 (normalised). Degenerate moments (equal within the classification tolerance):
///  * two equal moments (prolate or oblate): the unique axis is the eigenvector of the distinct moment; the
///    first axis of the equal pair is the projection onto the plane ⟂ to it of the coordinate axis (x, y or
///    z, the first one with the smallest component along the unique axis), normalised; the second follows
///    from the right-hand rule; then the sign rule above is applied;
///  * three equal moments (spherical): the axes are the identity.
///
/// Classification with relative tolerance τ (default 1e-9), on the ascending moments and scale I3:
/// `spherical` if I3 − I1 <= τ I3; `oblate` (two equal moments smaller than the third) if I2 − I1 <= τ I3;
/// `prolate` (two equal moments larger than the third) if I3 − I2 <= τ I3; otherwise `asymmetric`.

#include <string>

#include "poinsot/core/types.hpp"

namespace poinsot::inertia {

/// Symmetry class of a body from its principal moments.
enum class Symmetry { asymmetric, prolate, oblate, spherical };

/// "asymmetric", "prolate", "oblate" or "spherical".
std::string to_string(Symmetry s);

/// Default relative tolerance of classify() and principal_axes().
inline constexpr double kDefaultSymmetryTolerance = 1e-9;

/// Eigen-decomposition of a symmetric 3×3 tensor (kg·m² for J or K).
struct PrincipalAxes {
  Vec3 moments = Vec3::Zero();              ///< eigenvalues, ascending (same unit as the tensor)
  Mat3 axes = Mat3::Identity();             ///< columns: unit eigenvectors, a proper rotation (det = +1)
  Symmetry symmetry = Symmetry::spherical;  ///< classification of `moments` with the tolerance used
};

/// Eigenvalues and eigenvectors of the symmetric matrix S by cyclic Jacobi sweeps (S is symmetrised first):
/// S = V diag(λ) Vᵀ with V a rotation. Unordered and without the sign rule (principal_axes() applies both).
/// Throws InvalidInput for non-finite entries.
void jacobi_eigen(const Mat3& S, Vec3& eigenvalues, Mat3& eigenvectors);

/// Classify ascending moments with relative tolerance `rel_tol` (see the file comment). Throws InvalidInput
/// for a negative or non-finite tolerance.
Symmetry classify(const Vec3& moments_ascending, double rel_tol = kDefaultSymmetryTolerance);

/// Principal moments and axes of the symmetric tensor `J` (see the file comment for order, signs and
/// degenerate cases). `rel_tol` is the symmetry tolerance. Throws InvalidInput for non-finite entries or a
/// tensor that is not symmetric to 1e-12 of its largest entry.
PrincipalAxes principal_axes(const Mat3& J, double rel_tol = kDefaultSymmetryTolerance);

}  // namespace poinsot::inertia
