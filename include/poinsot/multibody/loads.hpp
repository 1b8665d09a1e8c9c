#pragma once
/// @file loads.hpp
/// The applied loads of a multibody system (gravity, constant forces and torques, spring-dampers between
/// points and on joint coordinates) in the rotation-matrix coordinates, and their potential energy.
///
/// A force f (space frame, N) at the body point X (body frame, m, from the centre of mass) does the virtual
/// work f·(δx + δR X): its generalized force on x is f and on R is F_R = f Xᵀ. Written in the body frame, Φ =
/// RᵀF_R = (Rᵀf) Xᵀ, and the body torque is τ = 2 vee(skew Φ) = X × Rᵀf. A pure couple τ (body frame, N·m)
/// has Φ = ½ j(τ) (its symmetric part is arbitrary and taken as zero). Φ's symmetric part enters the
/// multiplier Λ = Rᵀ R̈ K − Φ (docs/multibody_theory.md §1).

#include <vector>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

struct BodyLoads {
  Vec3 force_space = Vec3::Zero();  ///< resultant force, space frame, N
  Vec3 torque_body = Vec3::Zero();  ///< torque about the centre of mass, body frame, N·m
  Mat3 phi_body = Mat3::Zero();     ///< Φ = Rᵀ F_R, body frame, N·m
};

/// Loads at the positions and velocities of `bodies` (velocities are used by the dampers only). `out` is
/// resized to the body count; nothing else is allocated.
void applied_loads(const System& system, const std::vector<BodyState>& bodies, std::vector<BodyLoads>& out);

/// Potential energy (J) of gravity (−Σ m g·x), of the springs (Σ ½ k (ℓ − ℓ₀)²), of the joint springs
/// (Σ ½ k (q − q_rest)², model.hpp) and of the constant forces
/// (−Σ f·(x + R X)). Constant torques have no potential and are left out.
double potential_energy(const System& system, const std::vector<BodyState>& bodies);

}  // namespace poinsot::multibody
