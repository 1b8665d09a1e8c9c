#pragma once
/// @file multipliers.hpp
/// The Lagrange multipliers Λ of the rotation-matrix formulation of Vallée & Dumitriu (2002), computed from
/// the state of the body.
///
/// The paper describes the rotation by the nine entries of R (body → space) under the constraint RᵀR = I,
/// enforced by a symmetric matrix Λ of six multipliers: `R̈ K = R Λ` (eq. 1.1), with K = tr(J)/2·I − J the
/// Poinsot tensor about the rotation point (kg·m²). Differentiating `Ṙ = R j(ω)` gives `R̈ = R(j(ω)² + j(ω̇))`,
/// hence (eq. 3.2, docs/conventions.md conventions)
///
///     Λ = Rᵀ R̈ K = (j(ω)² + j(ω̇)) K        (body frame, joules = kg·m²·s⁻²)
///
/// with ω̇ from Euler's equations `J ω̇ + ω × J ω = τ_body`. K is never inverted (it is singular for plane
/// laminae, docs/conventions.md A3 and C2); J is invertible for every RigidBody.
///
/// Symmetry. For any ω and ω̇, `Λ − Λᵀ = j(J ω̇ + ω × J ω) = j(τ_body)` (docs/conventions.md C, "(1.1)
/// equivalent to Euler's equations"). For a free body Λ is therefore symmetric; under an applied torque the
/// matrix Rᵀ R̈ K splits into the symmetric multiplier matrix sym(Λ) and the torque part j(τ_body)/2. In every
/// case `tr Λ = −ωᵀ J ω = −2T` (T the kinetic energy, J).

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::analysis {

/// ω̇ (rad/s², body frame) from Euler's equations `J ω̇ = τ_body − ω × J ω`, with J = body.inertia() and
/// τ_body from `torque` at the state's time, attitude and ω (nullptr or a zero model: torque-free).
Vec3 angular_acceleration_body(const dynamics::RigidBody& body, const dynamics::State& state,
                               const dynamics::TorqueModel* torque = nullptr);

/// `(j(ω)² + j(ω̇)) K` (J) for given ω (rad/s) and ω̇ (rad/s²), both body frame; K = body.poinsot().
Mat3 lambda_from_omega(const dynamics::RigidBody& body, const Vec3& omega_body, const Vec3& omega_dot_body);

/// Λ = Rᵀ R̈ K = (j(ω)² + j(ω̇)) K (eq. 3.2; J, body frame) with ω̇ from Euler's equations and the torque
/// (nullptr: torque-free). Symmetric for a free body; its skew part is j(τ_body)/2 otherwise.
Mat3 lambda_from_state(const dynamics::RigidBody& body, const dynamics::State& state,
                       const dynamics::TorqueModel* torque = nullptr);

/// The symmetric part (M + Mᵀ)/2 (the multiplier matrix when M = Rᵀ R̈ K under a torque).
Mat3 symmetric_part(const Mat3& m);

/// ‖Λ − Λᵀ − j(τ_body)‖_F (J): how far Λ is from the symmetry the theory demands (0 up to round-off for the
/// state formula; the integrator's multipliers have their own error). τ_body = 0 for a free body.
double symmetry_error(const Mat3& lambda_body, const Vec3& torque_body = Vec3::Zero());

/// Eigenvalues of the symmetric part of Λ (J), ascending (Eigen's self-adjoint solver: accurate to
/// round-off relative to ‖Λ‖).
Vec3 sorted_eigenvalues(const Mat3& lambda_body);

}  // namespace poinsot::analysis
