#pragma once
/// @file constraints.hpp
/// The joint constraints g(x, R) = 0 of model.hpp, their Jacobians and the loads their multipliers exert.
///
/// Velocities are written per body as the 6-vector (v_space, ω_body): a variation of the 12 coordinates
/// tangent to RᵀR = I is δx, δR = R j(δθ). For a joint with rows c, the Jacobian block of a side is the c × 6
/// matrix G with ġ = G_a (v_a, ω_a) + G_b (v_b, ω_b), and g̈ = G_a (a_a, ω̇_a) + G_b (a_b, ω̇_b) + γ.
///
/// - ball rows `x_a + R_a A − x_b − R_b B`: G_a = [I, −R_a j(A)], G_b = [−I, R_b j(B)],
///   γ = R_a j(ω_a)² A − R_b j(ω_b)² B;
/// - perpendicularity rows `(R_a p)·(R_b u)` with P = R_a p, U = R_b u, n = P × U, Ω = R ω:
///   G_a = [0, (R_aᵀ n)ᵀ], G_b = [0, −(R_bᵀ n)ᵀ], γ = ((Ω_a × P) × U + P × (Ω_b × U))·(Ω_a − Ω_b).
///
/// A multiplier λ (force = Gᵀλ) acts on body a with the force λ_{0..2} (space frame, N) at the joint point
/// and the torque Σ λ_k n_k (space frame, N·m); body b receives the opposite. In the 12 coordinates it also
/// has an R-gradient part Φ = Rᵀ G_Rᵀ λ (body frame, N·m, its skew part is half the torque), which enters Λ.

#include <Eigen/Core>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

using Vec6 = Eigen::Matrix<double, 6, 1>;  ///< a body velocity (v_space, ω_body) or load
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;    ///< one joint's rows (≤ 6)
using JointJacobian = Eigen::Matrix<double, Eigen::Dynamic, 6, 0, 6, 6>;  ///< rows × (v_space, ω_body)

/// The pose of the fixed world: x = 0, R = I, at rest.
const BodyState& world_body_state();

/// g(x, R) for the joint (m for the ball rows, dimensionless for the perpendicularity rows).
JointVector joint_value(const Joint& joint, const BodyState& a, const BodyState& b);
/// G_a and G_b (G_b is meaningless when body b is the world).
void joint_jacobians(const Joint& joint, const BodyState& a, const BodyState& b, JointJacobian& G_a,
                     JointJacobian& G_b);
/// γ = g̈ − G a: the part of the constraint acceleration quadratic in the velocities.
JointVector joint_bias(const Joint& joint, const BodyState& a, const BodyState& b);

/// The loads of a multiplier λ (N for the ball rows, N·m for the perpendicularity rows).
struct JointLoads {
  Vec3 force_a_space = Vec3::Zero();   ///< force on body a at the joint point, N (body b gets −force)
  Vec3 torque_a_space = Vec3::Zero();  ///< couple on body a, N·m, besides the force (body b gets −torque)
  Mat3 phi_a_body = Mat3::Zero();      ///< R_aᵀ G_Rᵀλ on body a, body frame, N·m
  Mat3 phi_b_body = Mat3::Zero();      ///< same on body b
};
JointLoads joint_loads(const Joint& joint, const BodyState& a, const BodyState& b, const JointVector& lambda);

}  // namespace poinsot::multibody
