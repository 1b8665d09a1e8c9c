#pragma once
/// @file state.hpp
/// The mutable state of a rotating body and the invariants computed from it on demand.
///
/// `R` maps body to space (`x_space = R X_body`); `omega_body` is ω of `Ṙ = R j(ω)` (rad/s). With J the
/// inertia about the rotation point (RigidBody::inertia()): kinetic energy `T = ½ ωᵀJω` (J), `L_body = Jω`,
/// `L_space = R J ω` (kg·m²/s), conserved for a free body. With gravity g (space frame, m/s²) and a pivot,
/// the potential energy is `V = −m gᵀ R d` with d = pivot_to_com_body, and `T + V` is conserved.

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"

namespace poinsot::dynamics {

struct State {
  double time = 0.0;                     ///< s
  Mat3 R_space_body = Mat3::Identity();  ///< rotation body → space
  Vec3 omega_body = Vec3::Zero();        ///< angular velocity, body frame, rad/s

  /// The canonical unit quaternion (w ≥ 0) of R.
  Quat quaternion() const;
  /// The space-frame angular velocity Ω = R ω (rad/s).
  Vec3 omega_space() const { return R_space_body * omega_body; }
};

/// ½ ωᵀ J ω (J).
double kinetic_energy(const RigidBody& body, const State& s);
/// J ω (kg·m²/s), body frame.
Vec3 angular_momentum_body(const RigidBody& body, const State& s);
/// R J ω (kg·m²/s), space frame.
Vec3 angular_momentum_space(const RigidBody& body, const State& s);
/// −m gᵀ R d (J) for a body with a pivot; 0 for a free body.
double potential_energy(const RigidBody& body, const State& s, const Vec3& gravity_space);
/// T + V (J).
double total_energy(const RigidBody& body, const State& s, const Vec3& gravity_space);

/// Throws InvalidInput unless R is a rotation (‖RᵀR − I‖_F ≤ 1e-9 after the caller's projection) and the
/// state is finite. `what` names the source ("initial state").
void validate_state(const State& s, const char* what);

}  // namespace poinsot::dynamics
