// Joint kinematics: values, Jacobians, velocity-product terms, Gᵀλ and loads (constraints.hpp).
#include "poinsot/multibody/constraints.hpp"

#include <algorithm>
#include <cmath>

namespace poinsot::multibody {

const BodyState& world_body_state() {
  static const BodyState world{};
  return world;
}

namespace {

// r = x_a + R_a A − x_b: from body b's centre of mass to point a (space frame, m), the line rows' lever.
Vec3 point_a_from_b(const Joint& joint, const BodyState& a, const BodyState& b) {
  Vec3 r = a.x_space - b.x_space;
  r.noalias() += a.R_space_body * joint.point_a;
  return r;
}

}  // namespace

JointVector joint_value(const Joint& joint, const BodyState& a, const BodyState& b) {
  JointVector g(joint.rows());
  const int t = joint.translation_rows();
  if (joint.sliding) {
    const Vec3 r = point_a_from_b(joint, a, b);
    for (int k = 0; k < 2; ++k) {
      const Vec3& n = joint.n_b[static_cast<std::size_t>(k)];
      g(k) = (b.R_space_body * n).dot(r) - n.dot(joint.point_b);
    }
  } else {
    g.head<3>() = point_rows_value(joint, a, b);
  }
  for (int k = 0; k < joint.perpendicular_count; ++k)
    g(t + k) = perpendicular_row_value(joint, a, b, k);
  return g;
}

double sliding_scaled_joint_value(const Joint& joint, const BodyState& a, const BodyState& b, double scale,
                                  double length, double* out) {
  const JointVector g = joint_value(joint, a, b);
  Eigen::Map<JointVector>(out, g.size()) = scale * g;
  return joint_residual(joint, g, length);
}

void joint_jacobians(const Joint& joint, const BodyState& a, const BodyState& b, JointJacobian& G_a,
                     JointJacobian& G_b) {
  const int rows = joint.rows();
  const int t = joint.translation_rows();
  G_a.resize(rows, 6);
  G_b.resize(rows, 6);
  if (joint.sliding) {
    const Vec3 r_b = b.R_space_body.transpose() * point_a_from_b(joint, a, b);
    for (int k = 0; k < 2; ++k) {
      const Vec3& n = joint.n_b[static_cast<std::size_t>(k)];
      const Vec3 N = b.R_space_body * n;
      G_a.block<1, 3>(k, 0) = N.transpose();
      G_a.block<1, 3>(k, 3) = joint.point_a.cross(a.R_space_body.transpose() * N).transpose();
      G_b.block<1, 3>(k, 0) = -N.transpose();
      G_b.block<1, 3>(k, 3) = n.cross(r_b).transpose();
    }
  } else {
    G_a.block<3, 3>(0, 0).setIdentity();
    G_a.block<3, 3>(0, 3) = point_rows_omega_jacobian_a(joint, a.R_space_body);
    G_b.block<3, 3>(0, 0) = -Mat3::Identity();
    G_b.block<3, 3>(0, 3) = point_rows_omega_jacobian_b(joint, b.R_space_body);
    if (joint.axis_offset != 0.0) {
      // −h ṅ with ṅ = (Ω_a × P) × U + P × (Ω_b × U) = j(U) j(P) Ω_a − j(P) j(U) Ω_b.
      const Mat3 hat_P = so3::hat(a.R_space_body * joint.p_a[0]);
      const Mat3 hat_U = so3::hat(b.R_space_body * joint.u_b[0]);
      G_a.block<3, 3>(0, 3) -= joint.axis_offset * hat_U * hat_P * a.R_space_body;
      G_b.block<3, 3>(0, 3) += joint.axis_offset * hat_P * hat_U * b.R_space_body;
    }
  }
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 P = a.R_space_body * joint.p_a[ku];
    const Vec3 U = b.R_space_body * joint.u_b[ku];
    const Vec3 n = P.cross(U);
    G_a.block<1, 3>(t + k, 0).setZero();
    G_b.block<1, 3>(t + k, 0).setZero();
    G_a.block<1, 3>(t + k, 3) = (a.R_space_body.transpose() * n).transpose();
    G_b.block<1, 3>(t + k, 3) = -(b.R_space_body.transpose() * n).transpose();
  }
}

JointVector joint_bias(const Joint& joint, const BodyState& a, const BodyState& b) {
  JointVector gamma(joint.rows());
  const int t = joint.translation_rows();
  // R j(ω)² A = R (ω × (ω × A)): cross products, not 3 × 3 products (this runs at every RK4 stage).
  const Vec3& wa = a.omega_body;
  const Vec3& wb = b.omega_body;
  if (joint.sliding) {
    const Vec3 centripetal_a = a.R_space_body * wa.cross(wa.cross(joint.point_a));
    const Vec3 r_b = b.R_space_body.transpose() * point_a_from_b(joint, a, b);
    const Vec3 r_dot_b =
        b.R_space_body.transpose() * (a.v_space + a.R_space_body * wa.cross(joint.point_a) - b.v_space);
    for (int k = 0; k < 2; ++k) {
      const Vec3& n = joint.n_b[static_cast<std::size_t>(k)];
      const Vec3 wn = wb.cross(n);
      gamma(k) = (b.R_space_body * n).dot(centripetal_a) + wb.cross(wn).dot(r_b) + 2.0 * wn.dot(r_dot_b);
    }
  } else {
    gamma.head<3>().noalias() = a.R_space_body * wa.cross(wa.cross(joint.point_a));
    gamma.head<3>().noalias() -= b.R_space_body * wb.cross(wb.cross(joint.point_b));
    if (joint.axis_offset != 0.0) {
      // −h n̈ at zero angular accelerations.
      const Vec3 Oa = a.R_space_body * wa;
      const Vec3 Ob = b.R_space_body * wb;
      const Vec3 P = a.R_space_body * joint.p_a[0];
      const Vec3 U = b.R_space_body * joint.u_b[0];
      const Vec3 n_ddot = Oa.cross(Oa.cross(P)).cross(U) + 2.0 * Oa.cross(P).cross(Ob.cross(U)) +
                          P.cross(Ob.cross(Ob.cross(U)));
      gamma.head<3>() -= joint.axis_offset * n_ddot;
    }
  }
  if (joint.perpendicular_count == 0) return gamma;
  const Vec3 Oa = a.R_space_body * a.omega_body;
  const Vec3 Ob = b.R_space_body * b.omega_body;
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 P = a.R_space_body * joint.p_a[ku];
    const Vec3 U = b.R_space_body * joint.u_b[ku];
    const Vec3 n_dot = Oa.cross(P).cross(U) + P.cross(Ob.cross(U));
    gamma(t + k) = n_dot.dot(Oa - Ob);
  }
  return gamma;
}

JointVector joint_velocity(const Joint& joint, const BodyState& a, const BodyState& b) {
  JointJacobian G_a, G_b;
  joint_jacobians(joint, a, b, G_a, G_b);
  Vec6 va, vb;
  va << a.v_space, a.omega_body;
  vb << b.v_space, b.omega_body;
  return G_a * va + G_b * vb;
}

double joint_residual(const Joint& joint, const JointVector& g, double length) {
  const int t = joint.translation_rows();
  double err = g.head(t).cwiseAbs().maxCoeff() / length;
  if (joint.perpendicular_count > 0)
    err = std::max(err, g.tail(joint.perpendicular_count).cwiseAbs().maxCoeff());
  return err;
}

JointLoads joint_loads(const Joint& joint, const BodyState& a, const BodyState& b,
                       const JointVector& lambda) {
  JointLoads loads;
  const int t = joint.translation_rows();
  if (joint.sliding) {
    // λ_k (R_b n_k)·(x_a + R_a A − x_b): force λ_k N_k on a at its point; R-gradients N_k Aᵀ on a and
    // r n_kᵀ on b.
    const Vec3 r_b = b.R_space_body.transpose() * point_a_from_b(joint, a, b);
    Vec3 f_b = Vec3::Zero();  // the force in b's frame
    for (int k = 0; k < 2; ++k) {
      const Vec3& n = joint.n_b[static_cast<std::size_t>(k)];
      f_b += lambda(k) * n;
      loads.phi_b_body += lambda(k) * r_b * n.transpose();
    }
    loads.force_a_space = b.R_space_body * f_b;
  } else {
    // R-gradient of λ·(R_a A) is λ Aᵀ, so Φ_b = −(R_bᵀλ) Bᵀ below; likewise Φ_a.
    loads.force_a_space = lambda.head<3>();
    loads.phi_b_body = -(b.R_space_body.transpose() * loads.force_a_space) * joint.point_b.transpose();
  }
  loads.phi_a_body = (a.R_space_body.transpose() * loads.force_a_space) * joint.point_a.transpose();
  if (joint.axis_offset != 0.0) {
    // λ·(−h (R_a p) × (R_b u)): R-gradients −h (U × f) pᵀ on a and −h (f × P) uᵀ on b; torque −h P × (U × f).
    const Vec3& f = loads.force_a_space;
    const double h = joint.axis_offset;
    const Vec3 P = a.R_space_body * joint.p_a[0];
    const Vec3 U = b.R_space_body * joint.u_b[0];
    loads.torque_a_space -= h * P.cross(U.cross(f));
    loads.phi_a_body -= h * (a.R_space_body.transpose() * U.cross(f)) * joint.p_a[0].transpose();
    loads.phi_b_body -= h * (b.R_space_body.transpose() * f.cross(P)) * joint.u_b[0].transpose();
  }
  for (int k = 0; k < joint.perpendicular_count; ++k) {
    const auto ku = static_cast<std::size_t>(k);
    const Vec3 P = a.R_space_body * joint.p_a[ku];
    const Vec3 U = b.R_space_body * joint.u_b[ku];
    const double l = lambda(t + k);
    loads.torque_a_space += l * P.cross(U);
    // ∂[(R_a p)·(R_b u)]/∂R_a = U pᵀ and ∂/∂R_b = P uᵀ.
    loads.phi_a_body += l * (a.R_space_body.transpose() * U) * joint.p_a[ku].transpose();
    loads.phi_b_body += l * (b.R_space_body.transpose() * P) * joint.u_b[ku].transpose();
  }
  return loads;
}

}  // namespace poinsot::multibody
