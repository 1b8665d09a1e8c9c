#pragma once
/// @file multipliers.hpp
/// The Lagrange multipliers of a multibody system: each body's orthogonality multiplier Λ and each joint's
/// reaction, from the integrator's two stages or exactly at a given state.
///
/// Λ (body frame, symmetric, J) is the multiplier of RᵀR = I in `R̈ K = R Λ + F_R + G_Rᵀλ`, i.e.
/// `Λ = Rᵀ R̈ K − Φ = (j(ω)² + j(ω̇)) K − Φ` where Φ = Rᵀ(F_R + G_Rᵀλ) collects the applied loads and the joint
/// reactions acting on the body (loads.hpp, constraints.hpp). For a free body Φ = 0 and Λ is the single-body
/// multiplier of Vallée & Dumitriu (docs/conventions.md); `−R Λ Rᵀ` is the volume integral of the body's
/// stress.

#include <vector>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

struct Multipliers {
  std::vector<Mat3> Lambda_body;         ///< per body, body frame, J
  std::vector<Vec3> joint_force_space;   ///< per joint: force on body a at the joint point, space frame, N
  std::vector<Vec3> joint_torque_space;  ///< per joint: couple on body a, space frame, N·m
};

/// The exact multipliers of the continuous equations at `state` (index-1 form: the constraint accelerations
/// g̈ = 0 with the velocity-product terms), together with the accelerations: `acceleration_space[i]` (m/s²)
/// and `omega_dot_body[i]` (rad/s²). One sparse solve (kkt_solver.hpp).
struct ExactMultipliers : Multipliers {
  std::vector<Vec3> acceleration_space;
  std::vector<Vec3> omega_dot_body;
};
ExactMultipliers exact_multipliers(const System& system, const State& state);

}  // namespace poinsot::multibody
