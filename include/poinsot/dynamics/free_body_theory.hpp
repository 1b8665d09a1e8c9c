#pragma once
/// @file free_body_theory.hpp
/// Closed-form facts about the torque-free rigid body (Euler–Poinsot motion) from its principal moments and
/// its angular velocity: the regime, the elliptic modulus k, the frequency ω_p of the Jacobi-elliptic
/// solution, the interval between flips of the intermediate axis and the period of ω(t).
///
/// Principal moments I1 ≤ I2 ≤ I3 (kg·m²), body angular velocity ω in the principal frame (rad/s), kinetic
/// energy T = ½ Σ I_i ω_i² (J), |L|² = Σ I_i² ω_i² ((kg·m²/s)²). The gaps are evaluated without cancellation
/// as 2T I_j − |L|² = Σ_i I_i (I_j − I_i) ω_i². For an asymmetric body (Landau & Lifshitz, Mechanics §37):
///
///   |L|² > 2T I2 (ω circles the axis of I3):  ω1 = a1 cn(u), ω2 = a2 sn(u), ω3 = a3 dn(u),
///       ω_p² = (I3 − I2)(|L|² − 2T I1)/(I1 I2 I3),  k² = (I2 − I1)(2T I3 − |L|²)/((I3 − I2)(|L|² − 2T I1));
///   |L|² < 2T I2 (ω circles the axis of I1): the same with indices 1 and 3 exchanged:
///       ω1 = a1 dn(u), ω2 = a2 sn(u), ω3 = a3 cn(u),
///       ω_p² = (I2 − I1)(2T I3 − |L|²)/(I1 I2 I3),  k² = (I3 − I2)(|L|² − 2T I1)/((I2 − I1)(2T I3 − |L|²));
///   |L|² = 2T I2 (separatrix, k = 1): sn → tanh, cn, dn → sech, infinite period;
///
/// with u = ω_p (t − t0). sn has period 4K(k), so ω2 changes sign (the intermediate axis flips, the tennis
/// racket's handle turns over) every **2K(k)/ω_p** seconds, and ω(t) repeats after **4K(k)/ω_p** seconds
/// (ω1 or ω3, whichever follows cn, has period 4K; the one following dn has period 2K).
/// K(k) = ∫₀^{π/2} dθ/√(1 − k² sin²θ) is the complete elliptic integral of the first kind.

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"

namespace poinsot::dynamics {

/// The kinds of torque-free motion.
enum class FreeBodyRegime {
  rest,                ///< ω = 0
  sphere,              ///< I1 = I3: ω constant, any axis
  axisymmetric,        ///< I1 = I2 < I3 or I1 < I2 = I3: ω precesses uniformly about the symmetry axis
  principal_rotation,  ///< steady rotation about one principal axis of an asymmetric body
  largest_axis,        ///< |L|² > 2T I2: ω circles the axis of the largest moment I3
  separatrix,          ///< |L|² = 2T I2: ω tends to the intermediate axis as t → ±∞
  smallest_axis,       ///< |L|² < 2T I2: ω circles the axis of the smallest moment I1
};

/// "rest", "sphere", "axisymmetric", "principal rotation", "largest axis", "separatrix", "smallest axis".
const char* to_string(FreeBodyRegime regime);

/// Two principal moments are treated as equal when they differ by at most this fraction of I3: 32 ulps,
/// the noise of an eigen-decomposition. Over a time t the error of that choice is below 7e-15·|ω| t rad.
inline constexpr double kSymmetryTolerance = 32.0 * 2.220446049250313e-16;

struct FreeBodyTheory {
  Vec3 moments = Vec3::Ones();  ///< I1 ≤ I2 ≤ I3 (kg·m²)
  Vec3 omega = Vec3::Zero();    ///< ω in the principal frame (rad/s)
  double energy = 0.0;          ///< T (J)
  double momentum = 0.0;        ///< |L| (kg·m²/s)
  /// |L|² − 2T I2 ((kg·m²/s)²): its sign gives the regime. Evaluated as I3(I3 − I2)ω3² − I1(I2 − I1)ω1².
  double separatrix_gap = 0.0;
  FreeBodyRegime regime = FreeBodyRegime::rest;
  double modulus = 0.0;              ///< k ∈ [0, 1] (asymmetric regimes; 1 on the separatrix)
  double modulus_complement2 = 1.0;  ///< k'² = 1 − k², evaluated without cancellation
  /// rad/s. Asymmetric regimes: the frequency ω_p of u = ω_p t. Axisymmetric: |C/A − 1||μ|, the rate at which
  /// ω precesses about the symmetry axis in the body. 0 otherwise.
  double omega_p = 0.0;
  double quarter_period = 0.0;  ///< K(k) (dimensionless); asymmetric regimes off the separatrix only

  /// The interval between two successive sign changes of ω2 (flips of the intermediate axis), 2K(k)/ω_p (s),
  /// for the asymmetric regimes off the separatrix; 0 otherwise (no flips, or infinitely far apart).
  double flip_interval() const;
  /// The period of ω(t) (s): 4K(k)/ω_p for an asymmetric body off the separatrix (twice the flip interval),
  /// 2π/ω_p for an axisymmetric body with μ ≠ 0 and C ≠ A; 0 when ω is constant or on the separatrix.
  double omega_period() const;
};

/// The theory for principal moments (ascending, kg·m²) and ω in the principal frame (rad/s). Throws
/// InvalidInput for moments that are not positive and ascending or non-finite input.
FreeBodyTheory free_body_theory(const Vec3& principal_moments, const Vec3& omega_principal);
/// The same for a body (about its rotation point) and ω in the body frame: ω is first expressed in the
/// principal frame of RigidBody::principal_axes().
FreeBodyTheory free_body_theory(const RigidBody& body, const Vec3& omega_body);

}  // namespace poinsot::dynamics
