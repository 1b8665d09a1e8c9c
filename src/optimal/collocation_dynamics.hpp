#pragma once
/// @file collocation_dynamics.hpp (internal)
/// The right-hand side the collocation transcription uses, with its exact first and second derivatives.
///
/// State x = (q, ω) ∈ ℝ⁷ (q = (w, x, y, z) the body → space quaternion, ω body frame, rad/s); control
/// v = (u, ν) ∈ ℝ⁴ (u body torque, N·m; ν an algebraic variable, 1/s):
///
///     q̇ = ½ q ⊗ (0, ω) + ν q = ½ W(ω) q + ν q,   W(ω) = [[0, −ωᵀ], [ω, −j(ω)]],
///     ω̇ = J⁻¹ (u − ω × Jω).
///
/// ν is the multiplier that keeps ‖q‖ = 1 at every collocation point when that constraint is imposed
/// (d‖q‖²/dt = 2ν‖q‖², so ν = 0 on an exact solution and ν = O(h⁴) on the collocated one). Every function is
/// a polynomial of degree ≤ 2, so the Hessians are constant in the point and exact.
///
/// With reaction wheels (reaction_wheels.hpp; `gyrostat`) J is the bus inertia J_b, u the wheels' motor
/// torques and
///
///     ω̇ = J_b⁻¹ (B u − ω × v(q)),   B = −A,   v_i(q) = qᵀ M_i q = (Rᵀ(q) L)_i,
///
/// L the constant total angular momentum: a cubic in (q, ω), whose Hessian is linear in the point and is
/// still exact.
#include <array>

#include <Eigen/Core>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/pointing_constraint.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::optimal::detail {

using so3::hat;

using Vec7 = Eigen::Matrix<double, 7, 1>;
using Vec4 = Eigen::Matrix<double, 4, 1>;
using Vec11 = Eigen::Matrix<double, 11, 1>;
using Mat7x11 = Eigen::Matrix<double, 7, 11>;
using Mat11 = Eigen::Matrix<double, 11, 11>;

/// W(ω): q ⊗ (0, ω) = W(ω) q.
inline Eigen::Matrix4d quaternion_rate_matrix(const Vec3& w) {
  Eigen::Matrix4d m;
  m << 0, -w[0], -w[1], -w[2],  //
      w[0], 0, w[2], -w[1],     //
      w[1], -w[2], 0, w[0],     //
      w[2], w[1], -w[0], 0;
  return m;
}

/// M(q): q ⊗ (0, ω) = M(q) ω, M = [[−vᵀ], [s I + j(v)]] for q = (s, v).
inline Eigen::Matrix<double, 4, 3> quaternion_omega_matrix(const Vec4& q) {
  Eigen::Matrix<double, 4, 3> m;
  m << -q[1], -q[2], -q[3],  //
      q[0], -q[3], q[2],     //
      q[3], q[0], -q[1],     //
      -q[2], q[1], q[0];
  return m;
}

struct CollocationDynamics {
  Mat3 J;
  Mat3 J_inv;
  bool gyrostat = false;               ///< reaction wheels: the form above
  Mat3 B = Mat3::Identity();           ///< the control's torque on the bus (−A with wheels)
  std::array<Eigen::Matrix4d, 3> M{};  ///< v_i(q) = qᵀ M_i q = (Rᵀ(q) L)_i (wheels)

  /// The body torque and control matrices of `J` alone (no wheels).
  static CollocationDynamics body(const Mat3& inertia) { return {inertia, inertia.inverse()}; }
  /// The gyrostat of bus inertia J_b, spin axes A (columns) and total angular momentum L (space frame).
  static CollocationDynamics wheels(const Mat3& bus_inertia, const Mat3& axes, const Vec3& L) {
    CollocationDynamics d{bus_inertia, bus_inertia.inverse()};
    d.gyrostat = true;
    d.B = -axes;
    for (int i = 0; i < 3; ++i)
      d.M[i] = rotation_bilinear_form(Vec3::Unit(i), L);
    return d;
  }

  /// v(q) = Rᵀ(q) L (wheels).
  Vec3 body_momentum(const Vec4& q) const { return {q.dot(M[0] * q), q.dot(M[1] * q), q.dot(M[2] * q)}; }
  /// ∂v/∂q (3×4, wheels).
  Eigen::Matrix<double, 3, 4> body_momentum_jacobian(const Vec4& q) const {
    Eigen::Matrix<double, 3, 4> V;
    for (int i = 0; i < 3; ++i)
      V.row(i) = 2.0 * (M[i] * q).transpose();
    return V;
  }

  /// f(z) for z = (q, ω, u, ν).
  Vec7 rhs(const Vec11& z) const {
    const Vec4 q = z.segment<4>(0);
    const Vec3 w = z.segment<3>(4), u = z.segment<3>(7);
    Vec7 f;
    f.segment<4>(0) = 0.5 * quaternion_rate_matrix(w) * q + z[10] * q;
    if (gyrostat)
      f.segment<3>(4) = J_inv * (B * u - w.cross(body_momentum(q)));
    else
      f.segment<3>(4) = J_inv * (u - w.cross(J * w));
    return f;
  }

  /// ∂f/∂z (7×11).
  Mat7x11 jacobian(const Vec11& z) const {
    const Vec4 q = z.segment<4>(0);
    const Vec3 w = z.segment<3>(4);
    Mat7x11 a = Mat7x11::Zero();
    a.block<4, 4>(0, 0) = 0.5 * quaternion_rate_matrix(w) + z[10] * Eigen::Matrix4d::Identity();
    a.block<4, 3>(0, 4) = 0.5 * quaternion_omega_matrix(q);
    a.block<4, 1>(0, 10) = q;
    if (gyrostat) {
      a.block<3, 4>(4, 0) = -J_inv * hat(w) * body_momentum_jacobian(q);
      a.block<3, 3>(4, 4) = J_inv * hat(body_momentum(q));
      a.block<3, 3>(4, 7) = J_inv * B;
      return a;
    }
    a.block<3, 3>(4, 4) = -J_inv * (hat(w) * J - hat(J * w));
    a.block<3, 3>(4, 7) = J_inv;
    return a;
  }

  /// ∇²(cᵀ f) (11×11, symmetric) at z: independent of z without wheels; with them linear in (q, ω).
  Mat11 weighted_hessian(const Vec7& c, const Vec11& z) const {
    Mat11 h = Mat11::Zero();
    const Vec4 cq = c.segment<4>(0);
    for (int j = 0; j < 3; ++j) {
      const Vec3 e = Vec3::Unit(j);
      const Vec4 col = 0.5 * quaternion_rate_matrix(e).transpose() * cq;  // ∂²(cqᵀ ½W(ω)q)/∂q∂ω_j
      h.block<4, 1>(0, 4 + j) = col;
      h.block<1, 4>(4 + j, 0) = col.transpose();
    }
    h.block<4, 1>(0, 10) = cq;
    h.block<1, 4>(10, 0) = cq.transpose();
    const Vec3 a = J_inv * c.segment<3>(4);  // J symmetric
    if (gyrostat) {
      // s = −aᵀ(ω × v(q)) = −Σ_i (a × ω)_i qᵀ M_i q; ∂s/∂ω = a × v(q).
      const Vec4 q = z.segment<4>(0);
      const Vec3 axw = a.cross(Vec3(z.segment<3>(4)));
      h.block<4, 4>(0, 0) = -2.0 * (axw[0] * M[0] + axw[1] * M[1] + axw[2] * M[2]);
      const Eigen::Matrix<double, 3, 4> cross = hat(a) * body_momentum_jacobian(q);
      h.block<3, 4>(4, 0) += cross;
      h.block<4, 3>(0, 4) += cross.transpose();
      return h;
    }
    h.block<3, 3>(4, 4) = hat(a) * J - J * hat(a);
    return h;
  }
};

}  // namespace poinsot::optimal::detail
