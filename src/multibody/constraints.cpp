// Joint constraints: values, Jacobians, velocity-product terms and loads (constraints.hpp).
#include "poinsot/multibody/constraints.hpp"

#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {

const BodyState& world_body_state() {
  static const BodyState world{};
  return world;
}

JointVector joint_value(const Joint& joint, const BodyState& a, const BodyState& b) {
  JointVector g(joint.rows());
  g.head<3>() = a.x_space + a.R_space_body * joint.point_a - b.x_space - b.R_space_body * joint.point_b;
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    g(3 + k) = (a.R_space_body * joint.p_a[ku]).dot(b.R_space_body * joint.u_b[ku]);
  }
  return g;
}

void joint_jacobians(const Joint& joint, const BodyState& a, const BodyState& b, JointJacobian& G_a,
                     JointJacobian& G_b) {
  const int rows = joint.rows();
  G_a.resize(rows, 6);
  G_b.resize(rows, 6);
  G_a.block<3, 3>(0, 0).setIdentity();
  G_a.block<3, 3>(0, 3) = -so3::times_hat(a.R_space_body, joint.point_a);
  G_b.block<3, 3>(0, 0) = -Mat3::Identity();
  G_b.block<3, 3>(0, 3) = so3::times_hat(b.R_space_body, joint.point_b);
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 P = a.R_space_body * joint.p_a[ku];
    const Vec3 U = b.R_space_body * joint.u_b[ku];
    const Vec3 n = P.cross(U);
    G_a.block<1, 3>(3 + k, 0).setZero();
    G_b.block<1, 3>(3 + k, 0).setZero();
    G_a.block<1, 3>(3 + k, 3) = (a.R_space_body.transpose() * n).transpose();
    G_b.block<1, 3>(3 + k, 3) = -(b.R_space_body.transpose() * n).transpose();
  }
}

JointVector joint_bias(const Joint& joint, const BodyState& a, const BodyState& b) {
  JointVector gamma(joint.rows());
  // R j(ω)² A = R (ω × (ω × A)): cross products, not 3 × 3 products (this runs at every RK4 stage).
  const Vec3& wa = a.omega_body;
  const Vec3& wb = b.omega_body;
  gamma.head<3>().noalias() = a.R_space_body * wa.cross(wa.cross(joint.point_a));
  gamma.head<3>().noalias() -= b.R_space_body * wb.cross(wb.cross(joint.point_b));
  if (joint.perpendicular_count == 0) return gamma;
  const Vec3 Oa = a.R_space_body * a.omega_body;
  const Vec3 Ob = b.R_space_body * b.omega_body;
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 P = a.R_space_body * joint.p_a[ku];
    const Vec3 U = b.R_space_body * joint.u_b[ku];
    const Vec3 n_dot = Oa.cross(P).cross(U) + P.cross(Ob.cross(U));
    gamma(3 + k) = n_dot.dot(Oa - Ob);
  }
  return gamma;
}

JointLoads joint_loads(const Joint& joint, const BodyState& a, const BodyState& b,
                       const JointVector& lambda) {
  JointLoads loads;
  const Vec3 f = lambda.head<3>();
  loads.force_a_space = f;
  // R-gradient of λ·(R_a A) is λ Aᵀ, so Φ_a = (R_aᵀλ) Aᵀ; likewise Φ_b = −(R_bᵀλ) Bᵀ.
  loads.phi_a_body = (a.R_space_body.transpose() * f) * joint.point_a.transpose();
  loads.phi_b_body = -(b.R_space_body.transpose() * f) * joint.point_b.transpose();
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 P = a.R_space_body * joint.p_a[ku];
    const Vec3 U = b.R_space_body * joint.u_b[ku];
    const double l = lambda(3 + k);
    loads.torque_a_space += l * P.cross(U);
    // ∂[(R_a p)·(R_b u)]/∂R_a = U pᵀ and ∂/∂R_b = P uᵀ.
    loads.phi_a_body += l * (a.R_space_body.transpose() * U) * joint.p_a[ku].transpose();
    loads.phi_b_body += l * (b.R_space_body.transpose() * P) * joint.u_b[ku].transpose();
  }
  return loads;
}

}  // namespace poinsot::multibody
