#pragma once
// Internal to the dynamics layer: the right-hand side of Euler's equations with the quaternion kinematics,
// shared by the Runge–Kutta integrators (rk4, dopri5, dop853) and the simulation driver.
//
//   J ω̇ = τ_body(t, R, ω) − ω × J ω        (Euler, body frame, rad/s²)
//   q̇ = ½ q ⊗ (0, ω)                        (Ṙ = R j(ω) for R = R(q) body → space)
//
// The state vector is y = (q_w, q_x, q_y, q_z, ω1, ω2, ω3). The quaternion ODE is linear and homogeneous in
// q, so a drift of |q| does not change the rotation R(q/|q|): the integrators normalise on output.
#include <cmath>
#include <memory>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"
#include "poinsot/so3/quaternion.hpp"

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
    diagonal_ = body.is_diagonal();
    const Vec3 I = J_.diagonal();
    // Euler's equations in a principal body frame: ω̇1 = (I2 − I3)/I1 ω2 ω3 + τ1/I1, cyclically.
    gyro_ = Vec3((I[1] - I[2]) / I[0], (I[2] - I[0]) / I[1], (I[0] - I[1]) / I[2]);
    inv_diag_ = I.cwiseInverse();
  }

  /// ω̇ (rad/s²) of the free body, −J⁻¹(ω × Jω).
  Vec3 free_omega_dot(const Vec3& w) const {
    if (diagonal_) return Vec3(gyro_[0] * w[1] * w[2], gyro_[1] * w[2] * w[0], gyro_[2] * w[0] * w[1]);
    return -(J_inv_ * w.cross(J_ * w));
  }
  /// ω̇ (rad/s²) at time t, attitude R and body angular velocity w.
  Vec3 omega_dot(double t, const Mat3& R, const Vec3& w) const {
    if (torque_free_) return free_omega_dot(w);
    const Vec3 tau = torque_->torque_body(t, R, w);
    return free_omega_dot(w) + (diagonal_ ? Vec3(tau.cwiseProduct(inv_diag_)) : Vec3(J_inv_ * tau));
  }

  /// ẏ for y = (q, ω).
  __attribute__((always_inline)) Vec7 operator()(double t, const Vec7& y) const {
    const Vec3 w = y.tail<3>();
    Vec7 d;
    d[0] = -0.5 * (y[1] * w[0] + y[2] * w[1] + y[3] * w[2]);
    d[1] = 0.5 * (y[0] * w[0] + y[2] * w[2] - y[3] * w[1]);
    d[2] = 0.5 * (y[0] * w[1] + y[3] * w[0] - y[1] * w[2]);
    d[3] = 0.5 * (y[0] * w[2] + y[1] * w[1] - y[2] * w[0]);
    d.tail<3>() = torque_free_ ? free_omega_dot(w) : omega_dot(t, rotation_of(y), w);
    return d;
  }

  bool torque_free() const { return torque_free_; }
  const TorqueModel* torque() const { return torque_.get(); }

 private:
  Mat3 J_;
  Mat3 J_inv_;
  std::shared_ptr<const TorqueModel> torque_;
  bool torque_free_ = true;
  bool diagonal_ = false;
  Vec3 gyro_ = Vec3::Zero();
  Vec3 inv_diag_ = Vec3::Zero();
};

/// One Björck–Bowie step towards the nearest rotation, R ← R − ½ R (RᵀR − I): for ‖RᵀR − I‖ = δ it leaves
/// O(δ²). The splitting and variational methods apply it every kReorthogonalizeEvery steps so that rounding
/// errors, which otherwise accumulate like a random walk (‖RᵀR − I‖ ~ 3e-13 after 10⁶ steps), stay at the
/// level of one step's round-off; it moves R by O(δ) = O(1e-15), below anything the methods resolve.
inline void reorthogonalize(Mat3& R) {
  const Mat3 E = R.transpose() * R - Mat3::Identity();
  R -= 0.5 * (R * E);
}
inline constexpr int kReorthogonalizeEvery = 16;

/// y = (q, ω) of a State: the canonical unit quaternion of R (Shepperd) and the body angular velocity
/// (rad/s).
inline Vec7 vec7_of(const State& s) {
  const Quat q = so3::quaternion_from_rotation(s.R_space_body);
  Vec7 y;
  y << q.w(), q.x(), q.y(), q.z(), s.omega_body;
  return y;
}

/// Keeps the integrator's own representation of the state between steps (a quaternion, a momentum in the
/// principal frame, ...) and tells whether the State handed to the next step is the one it produced, so that
/// no conversion (and no rounding) happens between consecutive steps.
struct ResumeCheck {
  Mat3 R_out = Mat3::Zero();
  Vec3 omega_out = Vec3::Zero();
  bool valid = false;
  bool matches(const State& s) const { return valid && s.R_space_body == R_out && s.omega_body == omega_out; }
  void remember(const State& s) {
    R_out = s.R_space_body;
    omega_out = s.omega_body;
    valid = true;
  }
};

/// Ends an accepted step of a Runge–Kutta method on y = (q, ω): renormalises q when |q| has drifted from 1 by
/// more than 1e-8 (R(q) does not depend on |q|, but the tolerance scaling does), writes t, R(q) and ω into
/// `state` and remembers it. Returns false when q was rescaled, i.e. a first-same-as-last derivative no
/// longer matches y.
inline bool accept_step(Vec7& y, double t, State& state, ResumeCheck& resume) {
  const double qn = y.head<4>().norm();
  const bool unchanged = std::abs(qn - 1.0) <= 1e-8;
  if (!unchanged) y.head<4>() /= qn;
  state.time = t;
  state.R_space_body = rotation_of(y);
  state.omega_body = y.tail<3>();
  resume.remember(state);
  return unchanged;
}

}  // namespace poinsot::dynamics::detail
