#pragma once
/// @file observables.hpp
/// Invariants and diagnostics of a multibody state: energy, momenta, constraint violation.

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

/// Σ ½ m |v|² + ½ ωᵀ J ω (J), equal to ½ m|ẋ|² + ½ tr(Ṙ K Ṙᵀ) in the 12 coordinates.
double kinetic_energy(const System& system, const State& state);
/// kinetic_energy + potential_energy (loads.hpp), J.
double total_energy(const System& system, const State& state);
/// Σ m v, space frame, kg·m/s.
Vec3 linear_momentum(const System& system, const State& state);
/// Σ (x × m v + R J ω) about the space origin, space frame, kg·m²/s.
Vec3 angular_momentum(const System& system, const State& state);

struct ConstraintViolation {
  double orthogonality = 0.0;  ///< max over bodies of ‖RᵀR − I‖_F (so3::orthogonality_error, dimensionless)
  double joint_gap = 0.0;    ///< max |translation rows|: distance between joined points (or to the line), m
  double joint_angle = 0.0;  ///< max |(R_a p)·(R_b u)| of the perpendicularity rows (dimensionless ≈ rad)
  double joint_velocity = 0.0;  ///< max |ġ| of the translation rows, m/s
};
ConstraintViolation constraint_violation(const System& system, const State& state);

/// Throws InvalidInput unless `state` has one entry per body of `system`.
void check_body_count(const System& system, const State& state);

/// Throws InvalidInput unless `state` has one entry per body, every R is a rotation to 1e-9 and every joint
/// holds to 1e-9 relative to System::length_scale() (positions) — a state the integrator can start from.
void check_consistent(const System& system, const State& state);

}  // namespace poinsot::multibody
