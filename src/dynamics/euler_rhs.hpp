#pragma once
// Internal to the dynamics layer: the right-hand side of Euler's equations with the quaternion kinematics,
// shared by the Runge–Kutta integrators (rk4, dopri5, dop853) and the simulation driver.
//
//   J ω̇ = τ_body(t, R, ω) − ω × J ω        (Euler, body frame, rad/s²)
//   q̇ = ½ q ⊗ (0, ω)                        (Ṙ = R j(ω) for R = R(q) body → space)
//
// The state vector is y = (q_w, q_x, q_y, q_z, ω1, ω2, ω3). The quaternion ODE is linear and homogeneous in
// q, so a drift of |q| does not change the rotation R(q/|q|): the integrators normalise on output.
#include <memory>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::dynamics::detail {

using Vec7 = Eigen::Matrix<double, 7, 1>;

/// The rotation of the (not necessarily unit) quaternion stored in y[0..3].
inline Mat3 rotation_of(const Vec7& y) {
  Quat q(y[0], y[1], y[2], y[3]);
  q.normalize();
  return q.toRotationMatrix();
}

class EulerRhs {
 public:
  EulerRhs(const RigidBody& body, std::shared_ptr<const TorqueModel> torque)
      : J_(body.inertia()), J_inv_(body.inertia_inverse()), torque_(std::move(torque)) {
    torque_free_ = !torque_ || torque_->is_zero();
  }

  /// ω̇ (rad/s²) at time t, attitude R and body angular velocity w.
  Vec3 omega_dot(double t, const Mat3& R, const Vec3& w) const {
    Vec3 rhs = -w.cross(J_ * w);
    if (!torque_free_) rhs += torque_->torque_body(t, R, w);
    return J_inv_ * rhs;
  }

  /// ẏ for y = (q, ω).
  Vec7 operator()(double t, const Vec7& y) const {
    const Vec3 w = y.tail<3>();
    Vec7 d;
    d[0] = -0.5 * (y[1] * w[0] + y[2] * w[1] + y[3] * w[2]);
    d[1] = 0.5 * (y[0] * w[0] + y[2] * w[2] - y[3] * w[1]);
    d[2] = 0.5 * (y[0] * w[1] + y[3] * w[0] - y[1] * w[2]);
    d[3] = 0.5 * (y[0] * w[2] + y[1] * w[1] - y[2] * w[0]);
    Vec3 rhs = -w.cross(J_ * w);
    if (!torque_free_) rhs += torque_->torque_body(t, rotation_of(y), w);
    d.tail<3>() = J_inv_ * rhs;
    return d;
  }

  bool torque_free() const { return torque_free_; }
  const TorqueModel* torque() const { return torque_.get(); }

 private:
  Mat3 J_;
  Mat3 J_inv_;
  std::shared_ptr<const TorqueModel> torque_;
  bool torque_free_ = true;
};

/// Keeps the integrator's own representation of the state between steps (a quaternion, a momentum in the
/// principal frame, ...) and tells whether the State handed to the next step is the one it produced, so that
/// no conversion (and no rounding) happens between consecutive steps.
struct ResumeCheck {
  Mat3 R_out = Mat3::Zero();
  Vec3 omega_out = Vec3::Zero();
  bool valid = false;
  bool matches(const State& s) const { return valid && s.R == R_out && s.omega_body == omega_out; }
  void remember(const State& s) {
    R_out = s.R;
    omega_out = s.omega_body;
    valid = true;
  }
};

}  // namespace poinsot::dynamics::detail
