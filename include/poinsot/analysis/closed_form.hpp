#pragma once
/// @file closed_form.hpp
/// Λ of a torque-free body as an explicit function of ω alone (Vallée & Dumitriu 2002, §3, Property 2), with
/// the corrections of docs/conventions.md (C4–C8).
///
/// Notation of the paper (eq. 3.4), J = J0 the inertia about the centre of mass in the body frame (kg·m²):
///   ξ0 = ω⊗ω,  ξij = J^i ξ0 J^j,  η0 = ⟨ω, ω⟩,  ηij = η0 J^(i+j),
///   τ0 = 1/det J,  τ1 = tr J / 2,  τ2 = ((tr J)² − tr(J²))/2.
/// Then
///   (3.5)  j(ω̇) = τ0 (ξ12 − ξ21)                                  (Lemma 1; C4: τ0, not τ0⁻¹)
///   (3.7)  Λ = τ1(ξ0 − η0 I) + η01 − (ξ01 + ξ10) + τ0 J [ξ11 − τ1(ξ01 + ξ10) + τ2 ξ0] J   (C5: ξ0, not ε0)
///   (3.8)  Λ = τ1(ξ0 − η0 I) + τ0τ1(ξ12 − ξ21) − ξ01 + η01 − τ0(ξ13 − ξ22)          (C6: τ0τ1, not τ0)
///   sym.   Λ = τ1(ξ0 − η0 I) + η01 + τ0 ξ22 − τ0τ1(ξ12 + ξ21) − (ξ01 + ξ10) + τ0τ2 ξ11   (C8: + ξ10)
/// and the Cayley–Hamilton identity `τ0⁻¹ I − τ2 J + 2τ1 J² − J³ = 0` (C7) that turns (3.8) into the
/// symmetric form. All are in joules, body frame, and valid only without torque.

#include "poinsot/core/types.hpp"

namespace poinsot::analysis {

/// The invariants τ0 (kg⁻³·m⁻⁶), τ1 (kg·m²), τ2 (kg²·m⁴) of J (eq. 3.4).
struct InertiaInvariants {
  double tau0 = 0.0;  ///< 1 / det J
  double tau1 = 0.0;  ///< tr J / 2
  double tau2 = 0.0;  ///< ((tr J)² − tr(J²)) / 2, the second invariant of J
};

/// τ0, τ1, τ2 of a symmetric positive-definite J. Throws InvalidInput for a non-finite or singular J.
InertiaInvariants inertia_invariants(const Mat3& J);

/// The left side of the Cayley–Hamilton identity (C7), `τ0⁻¹ I − τ2 J + 2τ1 J² − J³` (zero up to
/// round-off; returned for checking).
Mat3 cayley_hamilton_residual(const Mat3& J);

/// j(ω̇) from Lemma 1, eq. (3.5): τ0 (ξ12 − ξ21) (rad/s², a skew matrix) for the torque-free body.
Mat3 omega_dot_hat_lemma1(const Mat3& J, const Vec3& omega_body);

/// Which printed (and corrected) form of the closed form to evaluate.
enum class ClosedForm {
  property2,  ///< eq. (3.7)
  eq38,       ///< eq. (3.8) with C6
  symmetric,  ///< the "symmetrical form" after (3.8), with C8
};

/// Λ (J, body frame) of the torque-free body with inertia J (kg·m², body frame) spinning at ω (rad/s, body
/// frame), from ω alone. Equals (j(ω)² + j(ω̇))K with ω̇ from Euler's equations.
Mat3 lambda_closed_form(const Mat3& J, const Vec3& omega_body, ClosedForm form = ClosedForm::property2);

}  // namespace poinsot::analysis
