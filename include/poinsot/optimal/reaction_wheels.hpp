#pragma once
/// @file reaction_wheels.hpp
/// Three reaction wheels as the actuators of a slew: the spacecraft as a gyrostat.
///
/// Model. A rigid bus carries three axisymmetric wheels, each balanced on a body-fixed unit spin axis a_k
/// (the columns of A, body frame), with axial inertia I_k (kg·m²). J (ReorientationProblem::inertia_body) is
/// the inertia of the whole spacecraft with its wheels locked, about the centre of mass, body frame. h_k
/// (N·m·s) is wheel k's absolute axial angular momentum, h_k = I_k (a_kᵀ ω + Ω_k) with Ω_k its spin rate
/// relative to the bus, and u_k (N·m) the motor torque on wheel k (the bus feels −a_k u_k). With no external
/// torque:
///
///     ḣ = u,    J_b ω̇ + ω × (J_b ω + A h) = −A u,    J_b = J − A diag(I_k) Aᵀ,
///
/// and the total angular momentum L = R (J_b ω + A h) (space frame) is constant. With three independent axes
/// the wheel momenta follow from the attitude and the rate, h = A⁻¹ (Rᵀ L − J_b ω), and the bus obeys
///
///     J_b ω̇ = −A u − ω × Rᵀ L,
///
/// a rigid body of inertia J_b whose control torque is −A u and whose gyroscopic term is set by the constant
/// L. The direct method transcribes that reduced form (the wheel torques are its controls; Rᵀ(q) L is a
/// quadratic form in the quaternion, so the derivatives stay exact, and the momentum bounds |h_k| ≤ h̄_k are
/// path inequalities); the replay of its control integrates the full (R, ω, h) system instead.
#include <limits>

#include "poinsot/core/types.hpp"

namespace poinsot::optimal {

struct ReactionWheels {
  Mat3 axes_body = Mat3::Identity();  ///< columns a_k: unit spin axes, body frame, linearly independent
  Vec3 spin_inertia = Vec3::Ones();   ///< I_k, each wheel's axial moment of inertia (kg·m²)
  /// h̄_k: |h_k(t)| ≤ h̄_k at every instant (N·m·s); infinity: no bound.
  Vec3 momentum_max = Vec3::Constant(std::numeric_limits<double>::infinity());
  Vec3 momentum_initial = Vec3::Zero();  ///< h_k(0) (N·m·s)

  /// At least one wheel's momentum is bounded (a finite h̄_k).
  bool has_momentum_bound() const {
    return momentum_max.minCoeff() < std::numeric_limits<double>::infinity();
  }
};

/// J_b = J − Σ_k I_k a_k a_kᵀ (kg·m², body frame): the inertia the bus's rate ω carries (J with the wheels'
/// axial inertia removed).
Mat3 bus_inertia(const Mat3& inertia_locked, const ReactionWheels& wheels);

/// L = R (J_b ω + A h) (N·m·s, space frame) at the attitude q, rate ω (body frame) and wheel momenta h.
Vec3 total_momentum_space(const Mat3& inertia_locked, const ReactionWheels& wheels, const Quat& attitude,
                          const Vec3& omega_body, const Vec3& wheel_momentum);

/// h = A⁻¹ (Rᵀ L − J_b ω) (N·m·s): the wheel momenta at attitude q and rate ω that keep the total angular
/// momentum L (space frame).
Vec3 wheel_momentum(const Mat3& inertia_locked, const ReactionWheels& wheels, const Vec3& momentum_space,
                    const Quat& attitude, const Vec3& omega_body);

/// Ω_k = h_k / I_k − a_kᵀ ω (rad/s): each wheel's spin rate relative to the bus.
Vec3 wheel_speed(const ReactionWheels& wheels, const Vec3& wheel_momentum, const Vec3& omega_body);

/// Throws InvalidInput, one line naming the key under "optimal_control.reaction_wheels", unless: every axis
/// is finite and unit to 1e-9 (a zero axis is refused as such); the three are independent (|det A| ≥ 1e-6);
/// every spin inertia is finite and positive; J_b is positive definite (the wheels' axial inertia is part
/// of J, so it cannot exceed it); every momentum bound is positive (infinity: none); the initial momenta are
/// finite and within their bounds.
void validate(const ReactionWheels& wheels, const Mat3& inertia_locked);

}  // namespace poinsot::optimal
