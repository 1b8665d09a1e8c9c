#pragma once
/// @file constraints.hpp
/// The joint kinematics, all in one place: the constraints g(x, R) = 0 of model.hpp, their Jacobians, their
/// velocity-product terms, Gᵀλ and the loads their multipliers exert. A joint's rows are of three kinds
/// (model.hpp Joint), and a joint type (joint_types.hpp) is a choice of them.
///
/// Velocities are written per body as the 6-vector (v_space, ω_body): a variation of the 12 coordinates
/// tangent to RᵀR = I is δx, δR = R j(δθ). For a joint with rows c, the Jacobian block of a side is the c × 6
/// matrix G with ġ = G_a (v_a, ω_a) + G_b (v_b, ω_b), and g̈ = G_a (a_a, ω̇_a) + G_b (a_b, ω̇_b) + γ.
///
/// - point rows `d = x_a + R_a A − x_b − R_b B` (3, m): G_a = [I, −R_a j(A)], G_b = [−I, R_b j(B)],
///   γ = R_a j(ω_a)² A − R_b j(ω_b)² B; a universal joint with an axis offset h adds −h n with
///   n = P × U (P = R_a p, U = R_b u, its cross-pin axes; Ω = R ω): −h j(U) j(P) R_a to G_a's ω-block,
///   +h j(P) j(U) R_b to G_b's, and −h ((Ω_a × (Ω_a × P)) × U + 2 (Ω_a × P) × (Ω_b × U) + P × (Ω_b × (Ω_b ×
///   U))) to γ;
/// - line rows (sliding joints, 2, m) `(R_b n)·r − n·B` with r = x_a + R_a A − x_b, N = R_b n, r_b = R_bᵀ r:
///   G_a = [Nᵀ, (A × R_aᵀN)ᵀ], G_b = [−Nᵀ, (n × r_b)ᵀ],
///   γ = N·(R_a j(ω_a)² A) + (ω_b × (ω_b × n))·r_b + 2 (ω_b × n)·R_bᵀṙ, ṙ = v_a + R_a(ω_a × A) − v_b;
///   written linear in each R (n·B for (R_b n)·(R_b B)), like the other rows, so that Φ below is defined;
/// - perpendicularity rows `(R_a p)·(R_b u)` with P = R_a p, U = R_b u, n = P × U, Ω = R ω:
///   G_a = [0, (R_aᵀ n)ᵀ], G_b = [0, −(R_bᵀ n)ᵀ], γ = ((Ω_a × P) × U + P × (Ω_b × U))·(Ω_a − Ω_b).
///
/// A multiplier λ (force = Gᵀλ) acts on body a with the force Σ λ_k (point rows: e_k; line rows: N_k) (space
/// frame, N) at its joint point R_a A, and the torque Σ λ_k n_k of the perpendicularity rows (space frame,
/// N·m; with an axis offset h also −h P × (U × f) of the point rows' force f); body b receives the opposite,
/// the force at the same point of space (x_b + R_b B + h n: point A where the joint holds). In the 12
/// coordinates it also has an R-gradient part Φ = Rᵀ G_Rᵀ λ (body frame, N·m, its skew part is half the
/// torque), which enters Λ.

#include <algorithm>
#include <cmath>
#include <vector>

#include <Eigen/Core>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {

using Vec6 = Eigen::Matrix<double, 6, 1>;  ///< a body velocity (v_space, ω_body) or load
using JointVector = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 6, 1>;  ///< one joint's rows (≤ 6)
/// rows × (v_space, ω_body). Row-major: each row is 6 contiguous numbers, so a fixed-size block has a stride
/// known at compile time (the fast path of the point rows, whose ω-block is used as a 3 × 3 matrix).
using JointJacobian = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor, 6, 6>;

/// The pose of the fixed world: x = 0, R = I, at rest.
const BodyState& world_body_state();
/// The state of a joint's side: bodies[index], or the world's for kWorld.
inline const BodyState& side_state(const std::vector<BodyState>& bodies, int index) {
  return index == kWorld ? world_body_state() : bodies[static_cast<std::size_t>(index)];
}

/// The ω-block −R_a j(A) of the point rows on side a (their v-block is I): fixed size, computed in place.
inline Mat3 point_rows_omega_jacobian_a(const Joint& joint, const Mat3& R_a) {
  return so3::times_hat(R_a, -joint.point_a);
}
/// The ω-block R_b j(B) of the point rows on side b (their v-block is −I).
inline Mat3 point_rows_omega_jacobian_b(const Joint& joint, const Mat3& R_b) {
  return so3::times_hat(R_b, joint.point_b);
}

/// n = (R_a p) × (R_b u): the common normal of a universal joint's cross-pin axes (space frame; unit where
/// the joint holds).
inline Vec3 cross_pin_normal(const Joint& joint, const BodyState& a, const BodyState& b) {
  return (a.R_space_body * joint.p_a[0]).cross(b.R_space_body * joint.u_b[0]);
}
/// d = x_a + R_a A − x_b − R_b B − h n: the point rows' value (m; h n only for a universal joint whose axes
/// are offset).
inline Vec3 point_rows_value(const Joint& joint, const BodyState& a, const BodyState& b) {
  Vec3 d = a.x_space - b.x_space;
  d.noalias() += a.R_space_body * joint.point_a;
  d.noalias() -= b.R_space_body * joint.point_b;
  if (joint.axis_offset != 0.0) d -= joint.axis_offset * cross_pin_normal(joint, a, b);
  return d;
}
/// (R_a p_k)·(R_b u_k): perpendicularity row k's value (dimensionless).
inline double perpendicular_row_value(const Joint& joint, const BodyState& a, const BodyState& b, int k) {
  const auto ku = static_cast<std::size_t>(k);
  return (a.R_space_body * joint.p_a[ku]).dot(b.R_space_body * joint.u_b[ku]);
}
/// g(x, R) for the joint (m for the translation rows, dimensionless for the perpendicularity rows).
JointVector joint_value(const Joint& joint, const BodyState& a, const BodyState& b);
/// scaled_joint_value for a sliding joint (the general path).
double sliding_scaled_joint_value(const Joint& joint, const BodyState& a, const BodyState& b, double scale,
                                  double length, double* out);
/// The Newton loops' form of joint_value: writes scale·g into out[0 .. rows) and returns
/// joint_residual(joint, g, length), with the point rows on a fixed-size path, inlined (no JointVector).
inline double scaled_joint_value(const Joint& joint, const BodyState& a, const BodyState& b, double scale,
                                 double length, double* out) {
  if (joint.sliding) return sliding_scaled_joint_value(joint, a, b, scale, length, out);
  const Vec3 d = point_rows_value(joint, a, b);
  Eigen::Map<Vec3> point_rows(out);
  point_rows = scale * d;
  double err = d.cwiseAbs().maxCoeff() / length;
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const double gk = perpendicular_row_value(joint, a, b, k);
    out[3 + k] = scale * gk;
    err = std::max(err, std::abs(gk));
  }
  return err;
}
/// G_a and G_b (G_b is meaningless when body b is the world).
void joint_jacobians(const Joint& joint, const BodyState& a, const BodyState& b, JointJacobian& G_a,
                     JointJacobian& G_b);
/// γ = g̈ − G a: the part of the constraint acceleration quadratic in the velocities.
JointVector joint_bias(const Joint& joint, const BodyState& a, const BodyState& b);
/// ġ = G_a (v_a, ω_a) + G_b (v_b, ω_b) (m/s for the translation rows, 1/s for the others).
JointVector joint_velocity(const Joint& joint, const BodyState& a, const BodyState& b);

/// Gᵀλ of one joint: gen_a += G_aᵀ λ and, unless gen_b is null (body b the world), gen_b += G_bᵀ λ, with
/// `lambda` the joint's rows (N for the translation rows, N·m for the others). Point rows take the fixed-size
/// path (±λ on the force, the 3 × 3 ω-block on the torque).
template <class Rows>
void add_joint_generalized_forces(const Joint& joint, const JointJacobian& G_a, const JointJacobian& G_b,
                                  const Eigen::MatrixBase<Rows>& lambda, Vec6& gen_a, Vec6* gen_b) {
  const int t = joint.translation_rows();
  const int extra = joint.perpendicular_count;
  if (t == 3) {
    const Vec3 f = lambda.template head<3>();
    gen_a.head<3>() += f;
    gen_a.tail<3>().noalias() += G_a.block<3, 3>(0, 3).transpose() * f;
    if (gen_b != nullptr) {
      gen_b->head<3>() -= f;
      gen_b->tail<3>().noalias() += G_b.block<3, 3>(0, 3).transpose() * f;
    }
  } else {
    gen_a.noalias() += G_a.topRows(t).transpose() * lambda.head(t);
    if (gen_b != nullptr) gen_b->noalias() += G_b.topRows(t).transpose() * lambda.head(t);
  }
  if (extra == 0) return;
  gen_a.tail<3>().noalias() += G_a.bottomRightCorner(extra, 3).transpose() * lambda.segment(t, extra);
  if (gen_b != nullptr)
    gen_b->tail<3>().noalias() += G_b.bottomRightCorner(extra, 3).transpose() * lambda.segment(t, extra);
}

/// The size of a joint's violation g for a convergence test: the largest |translation row| relative to
/// `length` (m) and the largest |perpendicularity row|, whichever is larger (dimensionless).
double joint_residual(const Joint& joint, const JointVector& g, double length);

/// The loads of a multiplier λ (N for the translation rows, N·m for the perpendicularity rows).
struct JointLoads {
  Vec3 force_a_space = Vec3::Zero();   ///< force on body a at its joint point, N (body b gets −force there)
  Vec3 torque_a_space = Vec3::Zero();  ///< couple on body a, N·m, besides the force (body b gets −torque)
  Mat3 phi_a_body = Mat3::Zero();      ///< R_aᵀ G_Rᵀλ on body a, body frame, N·m
  Mat3 phi_b_body = Mat3::Zero();      ///< same on body b
};
JointLoads joint_loads(const Joint& joint, const BodyState& a, const BodyState& b, const JointVector& lambda);

}  // namespace poinsot::multibody
