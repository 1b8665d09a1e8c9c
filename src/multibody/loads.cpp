// Applied loads and potential energy (loads.hpp).
#include "poinsot/multibody/loads.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <Eigen/Geometry>
#include <Eigen/LU>

#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {
namespace {

void add_point_force(BodyLoads& loads, const BodyState& s, const Vec3& f_space, const Vec3& X_body) {
  const Vec3 f_body = s.R_space_body.transpose() * f_space;
  loads.force_space += f_space;
  loads.torque_body += X_body.cross(f_body);
  loads.phi_body += f_body * X_body.transpose();
}

void add_couple(BodyLoads& loads, const Vec3& tau_body) {
  loads.torque_body += tau_body;
  loads.phi_body += 0.5 * so3::hat(tau_body);
}

/// The deflection q − q_rest of a joint spring and the rate q̇ (model.hpp, JointSpring). Hinge: the relative
/// rotation S = R_bᵀR_a is S_rest·Rot(axis_a, δ) with S_rest = R_b_a_zero·Rot(axis_a, q_rest), so δ =
/// atan2(axis_a·vee(P − Pᵀ)/2, (tr P − 1)/2) with P = S_restᵀS, and q̇ = axis_a·(ω_a − Sᵀω_b) (body frames).
/// Prismatic: q = (x_a + R_a A − x_b − R_b B)·s + offset along the axis s = R_b axis_b, q̇ its rate along s.
struct JointDeflection {
  double deflection = 0.0;  ///< q − q_rest, rad or m
  double rate = 0.0;        ///< q̇, rad/s or m/s
};

Vec3 slide_axis_space(const Joint& j, const BodyState& b) {
  return b.R_space_body * j.slide_axis_b();
}

/// One angle of a joint with several (a universal joint's two, a ball joint's three hinges; model.hpp,
/// JointSpring) and the torque on body a per unit of generalized force (body a's frame): e_a, or w = Mᵀc for
/// a universal joint's angle about e_b; E⁻ᵀe_k for a ball joint's hinge k.
struct CoupledAngle {
  JointDeflection q;
  Vec3 torque_axis_a;
};

CoupledAngle universal_angle(const Joint& j, const JointSpring& s, const BodyState& a, const BodyState& b) {
  const Vec3& e_a = j.p_a[0];
  const Mat3 S = b.R_space_body.transpose() * a.R_space_body;
  const Mat3 M = s.R_b_a_zero.transpose() * S;
  const Vec3 c = s.R_b_a_zero.transpose() * j.u_b[0];
  const Vec3 n = c.cross(e_a);
  const Vec3 w = M.transpose() * c;
  const Vec3 omega = a.omega_body - S.transpose() * b.omega_body;
  double angle = 0.0;
  Vec3 axis = e_a;
  if (s.coordinate == JointSpring::Coordinate::a) {
    angle = std::atan2(w.dot(n), w.dot(c));
  } else {
    const Vec3 v = M * e_a;
    angle = std::atan2(v.dot(n), v.dot(e_a));
    axis = w;
  }
  return {{std::remainder(angle - s.rest_position, 2.0 * std::numbers::pi), axis.dot(omega)}, axis};
}

/// The signed angle of the turn about the unit axis n that carries x to y (x and y of equal components along
/// n), rad.
double angle_about(const Vec3& n, const Vec3& x, const Vec3& y) {
  return std::atan2(n.dot(x.cross(y)), x.dot(y) - n.dot(x) * n.dot(y));
}

CoupledAngle ball_hinge_angle(const Joint& j, const JointSpring& s, const BodyState& a, const BodyState& b) {
  const auto& [e1, e2, e3] = s.hinge_axes;
  const Mat3 S = b.R_space_body.transpose() * a.R_space_body;
  const Mat3 M = s.R_b_a_zero.transpose() * S;
  const double lambda = std::atan2(e1.cross(e2).dot(e3), e1.dot(e3));
  const double q2 = lambda - std::copysign(std::acos(std::clamp(e1.dot(M * e3), -1.0, 1.0)), lambda);
  const Mat3 R2 = Eigen::AngleAxisd(q2, e2).toRotationMatrix();
  const double q1 = angle_about(e1, R2 * e3, M * e3);
  const double q3 = angle_about(e3, M.transpose() * e1, R2.transpose() * e1);
  const Mat3 R3_t = Eigen::AngleAxisd(-q3, e3).toRotationMatrix();
  Mat3 E;
  E << R3_t * (R2.transpose() * e1), R3_t * e2, e3;
  // det E = sin(λ − q₂): the distance to the lock in angle. Closer than 1e-6 rad, acos has lost half the
  // digits of q₂ (√ε ≈ 1.5e-8 rad at the lock itself) and the torque E⁻ᵀQ grows as 1/det.
  const double det = E.determinant();
  if (!(std::abs(det) > 1e-6)) {
    throw ComputationFailed(fmt::format(
        "multibody joint '{}': the spring on its {} hinge: the first and third hinge axes are aligned (the "
        "hinges' gimbal lock, q₂ = {} rad), where the three angles are undefined; expected motions away from "
        "it",
        j.name, joint_spring_coordinate_name(s.coordinate), q2));
  }
  const Mat3 E_inv = E.inverse();
  const int k = s.coordinate == JointSpring::Coordinate::first    ? 0
                : s.coordinate == JointSpring::Coordinate::second ? 1
                                                                  : 2;
  const double angles[3] = {q1, q2, q3};
  const Vec3 omega = a.omega_body - S.transpose() * b.omega_body;
  return {{std::remainder(angles[k] - s.rest_position, 2.0 * std::numbers::pi), E_inv.row(k).dot(omega)},
          E_inv.row(k).transpose()};
}

CoupledAngle coupled_angle(const Joint& j, const JointSpring& s, const BodyState& a, const BodyState& b) {
  return j.type == JointType::universal ? universal_angle(j, s, a, b) : ball_hinge_angle(j, s, a, b);
}

bool has_coupled_angles(const Joint& j) {
  return j.type == JointType::universal || j.type == JointType::ball;
}

JointDeflection joint_deflection(const Joint& j, const JointSpring& s, const BodyState& a,
                                 const BodyState& b) {
  if (has_coupled_angles(j)) return coupled_angle(j, s, a, b).q;
  if (j.type == JointType::hinge) {
    const Vec3 n = j.hinge_axis_a();
    const Mat3 S = b.R_space_body.transpose() * a.R_space_body;
    const Mat3 S_rest = s.R_b_a_zero * Eigen::AngleAxisd(s.rest_position, n).toRotationMatrix();
    const Mat3 P = S_rest.transpose() * S;
    const Vec3 sin_n(P(2, 1) - P(1, 2), P(0, 2) - P(2, 0), P(1, 0) - P(0, 1));
    return {std::atan2(0.5 * n.dot(sin_n), 0.5 * (P.trace() - 1.0)),
            n.dot(a.omega_body - S.transpose() * b.omega_body)};
  }
  const Vec3 axis = slide_axis_space(j, b);
  const Vec3 d = a.x_space + a.R_space_body * j.point_a - b.x_space - b.R_space_body * j.point_b;
  const Vec3 d_dot = a.v_space + a.R_space_body * a.omega_body.cross(j.point_a) - b.v_space -
                     b.R_space_body * b.omega_body.cross(j.point_b);
  return {d.dot(axis) + s.offset - s.rest_position, d_dot.dot(axis)};
}

}  // namespace

void applied_loads(const System& system, const std::vector<BodyState>& bodies, std::vector<BodyLoads>& out) {
  const auto n = static_cast<std::size_t>(system.body_count());
  out.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    out[i] = BodyLoads{};
    out[i].force_space = system.bodies()[i].mass * system.gravity();
  }
  for (const ConstantForce& f : system.forces()) {
    const auto i = static_cast<std::size_t>(f.body);
    add_point_force(out[i], bodies[i], f.force_space, f.point_body);
  }
  for (const ConstantTorque& t : system.torques()) {
    const auto i = static_cast<std::size_t>(t.body);
    add_couple(out[i], t.in_body_frame ? t.torque : Vec3(bodies[i].R_space_body.transpose() * t.torque));
  }
  for (const Spring& s : system.springs()) {
    const BodyState& a = side_state(bodies, s.body_a);
    const BodyState& b = side_state(bodies, s.body_b);
    const Vec3 ra = a.R_space_body * s.point_a;
    const Vec3 rb = b.R_space_body * s.point_b;
    const Vec3 d = a.x_space + ra - b.x_space - rb;
    const double length = d.norm();
    const Vec3 d_dot = a.v_space + a.R_space_body * a.omega_body.cross(s.point_a) - b.v_space -
                       b.R_space_body * b.omega_body.cross(s.point_b);
    Vec3 f_a = Vec3::Zero();
    if (length > 0.0) {
      const Vec3 e = d / length;
      f_a = -(s.stiffness * (length - s.rest_length) + s.damping * e.dot(d_dot)) * e;
    } else if (s.rest_length == 0.0) {
      f_a = -s.damping * d_dot;  // ℓ = ℓ₀ = 0: no elastic force, damping along the relative velocity
    }
    add_point_force(out[static_cast<std::size_t>(s.body_a)], a, f_a, s.point_a);
    if (s.body_b != kWorld) add_point_force(out[static_cast<std::size_t>(s.body_b)], b, -f_a, s.point_b);
  }
  for (const JointSpring& s : system.joint_springs()) {
    const Joint& j = system.joints()[static_cast<std::size_t>(s.joint)];
    const BodyState& a = side_state(bodies, j.body_a);
    const BodyState& b = side_state(bodies, j.body_b);
    const bool coupled = has_coupled_angles(j);
    const CoupledAngle u = coupled ? coupled_angle(j, s, a, b) : CoupledAngle{};
    const JointDeflection q = coupled ? u.q : joint_deflection(j, s, a, b);
    const double Q = -s.stiffness * q.deflection - s.damping * q.rate;
    BodyLoads& on_a = out[static_cast<std::size_t>(j.body_a)];
    if (j.type != JointType::prismatic) {
      const Vec3 tau_a = Q * (coupled ? u.torque_axis_a : j.hinge_axis_a());
      add_couple(on_a, tau_a);
      if (j.body_b != kWorld) {
        const Vec3 tau_b = -(b.R_space_body.transpose() * (a.R_space_body * tau_a));
        add_couple(out[static_cast<std::size_t>(j.body_b)], tau_b);
      }
    } else {
      const Vec3 f_a = Q * slide_axis_space(j, b);
      add_point_force(on_a, a, f_a, j.point_a);
      if (j.body_b != kWorld) add_point_force(out[static_cast<std::size_t>(j.body_b)], b, -f_a, j.point_b);
    }
  }
}

double potential_energy(const System& system, const std::vector<BodyState>& bodies) {
  double V = 0.0;
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    V -= system.bodies()[i].mass * system.gravity().dot(bodies[i].x_space);
  }
  for (const ConstantForce& f : system.forces()) {
    const BodyState& s = bodies[static_cast<std::size_t>(f.body)];
    V -= f.force_space.dot(s.x_space + s.R_space_body * f.point_body);
  }
  for (const Spring& s : system.springs()) {
    const BodyState& a = side_state(bodies, s.body_a);
    const BodyState& b = side_state(bodies, s.body_b);
    const double length =
        (a.x_space + a.R_space_body * s.point_a - b.x_space - b.R_space_body * s.point_b).norm();
    V += 0.5 * s.stiffness * (length - s.rest_length) * (length - s.rest_length);
  }
  for (const JointSpring& s : system.joint_springs()) {
    const Joint& j = system.joints()[static_cast<std::size_t>(s.joint)];
    const double q =
        joint_deflection(j, s, side_state(bodies, j.body_a), side_state(bodies, j.body_b)).deflection;
    V += 0.5 * s.stiffness * q * q;
  }
  return V;
}

}  // namespace poinsot::multibody
