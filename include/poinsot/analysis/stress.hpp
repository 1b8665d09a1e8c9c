#pragma once
/// @file stress.hpp
/// The constraint stress of the rotating body (Vallée & Dumitriu 2002, §6, eq. 6.1, with docs/conventions.md
/// C24).
///
/// For a free body (no surface tractions; uniform gravity drops out about the centre of mass), Cauchy's
/// equation `div σ = ρ a` integrated against x gives, for *any* statically admissible stress field,
///
///     ∫σ dv = −∫ρ a⊗x dv = −R̈ K Rᵀ = −R Λ Rᵀ        (space frame, N·m = J; tension positive)
///
/// with x = R X, a = R̈ X. It is symmetric and positive semi-definite, with trace 2T (the virial). Divided
/// by the volume it is the mean stress (Pa). Its principal values give the Tresca (largest shear,
/// (σmax − σmin)/2) and von Mises (√(½[(σ1−σ2)² + (σ2−σ3)² + (σ3−σ1)²])) equivalents used by the paper's
/// conclusion for shape optimisation.
///
/// Steady spin at rate ω (rad/s) about a principal axis k (unit, body frame):
///     ∫σ dv = R ω² (K − ⟨k, K k⟩ k⊗k) Rᵀ
/// e.g. a box of sides a, b, c spinning about z: ω² diag(m a²/12, m b²/12, 0).
///
/// Under an applied torque the external loads add their own moments; the functions here then return
/// −R sym(Λ) Rᵀ, the part carried by the constraint.

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::analysis {

/// ∫σ dv = −R sym(Λ) Rᵀ (N·m, space frame) from the body-frame Λ (J) and the attitude R (body → space).
Mat3 stress_integral_space(const Mat3& lambda_body, const Mat3& R);

/// ∫σ dv (N·m, space frame) of a state, with Λ from the state (eq. 3.2) and the torque (nullptr: free).
Mat3 stress_integral_space(const dynamics::RigidBody& body, const dynamics::State& state,
                           const dynamics::TorqueModel* torque = nullptr);

/// The closed form for a steady spin at `rate` (rad/s) about the unit principal axis `k_body` of K:
/// ω²(K − ⟨k, K k⟩ k⊗k) (N·m, body frame; conjugate by R for the space frame). Throws InvalidInput unless
/// k_body is a non-zero finite vector (it is normalised) and rate is finite.
Mat3 steady_spin_stress_integral_body(const Mat3& poinsot_K, const Vec3& k_body, double rate);

/// Principal values and equivalent stresses of a symmetric stress-like tensor (its unit: N·m for the
/// integral, Pa for the mean stress).
struct StressSummary {
  Mat3 tensor = Mat3::Zero();              ///< the tensor itself (space frame)
  Vec3 principal = Vec3::Zero();           ///< principal values, ascending
  Mat3 principal_axes = Mat3::Identity();  ///< columns: the principal directions (space frame)
  double tresca = 0.0;                     ///< largest shear (σmax − σmin)/2
  double von_mises = 0.0;                  ///< √(½[(σ1−σ2)² + (σ2−σ3)² + (σ3−σ1)²])
  double trace = 0.0;                      ///< σ1 + σ2 + σ3 (2T for the integral)
};

/// Principal values, Tresca and von Mises of the symmetric part of `tensor`.
StressSummary summarize_stress(const Mat3& tensor);

/// The constraint stress of a state: the integral (N·m) and, when `volume_m3` > 0, the mean stress (Pa).
struct ConstraintStress {
  StressSummary integral;  ///< ∫σ dv, N·m
  bool has_mean = false;   ///< a volume was given
  StressSummary mean;      ///< (1/V) ∫σ dv, Pa (only when has_mean)
};

/// ∫σ dv and the mean stress (volume in m³; 0 = unknown, no mean). Throws InvalidInput for a negative or
/// non-finite volume.
ConstraintStress constraint_stress(const Mat3& lambda_body, const Mat3& R, double volume_m3 = 0.0);

}  // namespace poinsot::analysis
