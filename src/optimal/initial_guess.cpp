#include "initial_guess.hpp"

#include <cmath>
#include <numbers>
#include <vector>

#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::optimal {

double first_mesh_turn(int start, int starts) {
  return 2.0 * std::numbers::pi * static_cast<double>(start) / static_cast<double>(starts);
}

namespace detail {
namespace {

/// Advances (R, ω) over dt by 16 explicit midpoint steps of ω̇ = wdot(ω) (rad/s²), R by the exact exponential
/// of the midpoint rate: R ← R exp(h ω_mid). `wdot` may read R (it is called before and after each update).
template <class AngularAcceleration>
void midpoint_substeps(double dt, const AngularAcceleration& wdot, Mat3& R, Vec3& omega) {
  constexpr int kSubsteps = 16;
  const double h = dt / kSubsteps;
  for (int i = 0; i < kSubsteps; ++i) {
    const Vec3 w_mid = omega + 0.5 * h * wdot(omega);
    R = R * so3::exp(h * w_mid);
    omega += h * wdot(w_mid);
  }
}

/// The torque-free motion from the problem's initial state at the collocation points of `nlp` over [0, T]
/// (midpoint_substeps between points).
void torque_free_motion(const CollocationNlp& nlp, double T, std::vector<Mat3>& R, std::vector<Vec3>& omega) {
  const auto& p = nlp.problem();
  const Mat3 J_inv = p.inertia_body.inverse();
  Mat3 Rk = p.attitude_initial.toRotationMatrix();
  // With reaction wheels the free motion of the gyrostat (u = 0): ω̇ = −J_b⁻¹ ω × Rᵀ L.
  const auto wdot = [&](const Vec3& v) {
    if (p.wheels) return Vec3(-nlp.dynamics().J_inv * v.cross(Rk.transpose() * p.wheel_system_momentum()));
    return Vec3(-J_inv * v.cross(p.inertia_body * v));
  };
  Vec3 wk = p.omega_initial;
  double tau_prev = 0.0;
  for (int pt = 0; pt < nlp.points(); ++pt) {
    const double tau = nlp.mesh().point_fraction(pt);
    midpoint_substeps((tau - tau_prev) * T, wdot, Rk, wk);
    tau_prev = tau;
    R.push_back(Rk);
    omega.push_back(wk);
  }
}

}  // namespace

/// The eigenaxis guess: q(t) = q_0 ⊗ exp(s Θ n / 2), ω = Θ n / T (body frame) plus a transverse bump turned
/// by `turn` (rad) about n, u = 0, ν = 0. From a spinning start (ω_0 ≠ 0, fixed final attitude) the same
/// about the torque-free motion R_free(t), ω_free(t): R = R_free exp(s r), r = log(R_free(T)ᵀ R_f),
/// ω = ω_free + s(ω_f − ω_free(T)) + r/T — the guess follows the spin over every turn instead of taking the
/// shortest rotation to R_f.
Guess initial_guess(const CollocationNlp& nlp, double T, double turn) {
  const auto& p = nlp.problem();
  const Mat3 R0 = p.attitude_initial.toRotationMatrix(), Rf = p.attitude_final.toRotationMatrix();
  std::vector<Mat3> spin_R;
  std::vector<Vec3> spin_omega;
  const bool spinning = !p.free_final_attitude && !p.omega_initial.isZero(0.0);
  if (spinning) torque_free_motion(nlp, T, spin_R, spin_omega);
  const Vec3 rotvec = p.free_final_attitude ? Vec3::Zero()
                      : spinning            ? so3::log(spin_R.back().transpose() * Rf)
                                            : so3::log(R0.transpose() * Rf);
  const Vec3 spin_omega_end = spinning ? spin_omega.back() : Vec3::Zero();
  // A transverse rate bump breaks the symmetry of rotations about a principal axis, whose eigenaxis
  // manoeuvre is a stationary point of the NLP but not the optimum (Bilimoria & Wie 1993).
  Vec3 transverse = Vec3(0.36, 0.48, 0.8);
  if (rotvec.norm() > 0.0) transverse -= transverse.dot(rotvec) / rotvec.squaredNorm() * rotvec;
  if (transverse.norm() > 1e-3) transverse.normalize();
  if (rotvec.norm() > 0.0)
    transverse = std::cos(turn) * transverse + std::sin(turn) * rotvec.normalized().cross(transverse);
  std::vector<double> z(nlp.num_variables(), 0.0);
  // With a free final attitude (detumbling to rest) the guess is the motion under the momentum-dumping torque
  // u = −(‖L_0‖/T) Jω/‖Jω‖, which takes ‖L‖ linearly to 0 at T; R and ω are advanced by midpoint_substeps
  // between points (towards a final rate, R turns at the guess's rate held over the interval).
  const bool dumping = p.free_final_attitude && p.omega_final.isZero(0.0);
  const double dump_rate = (p.inertia_body * p.omega_initial).norm() / T;
  const Mat3 J_inv = p.inertia_body.inverse();
  const auto dumping_torque = [&](const Vec3& w) {
    const Vec3 L = p.inertia_body * w;
    return L.norm() > 0.0 ? Vec3(-dump_rate * L.normalized()) : Vec3::Zero();
  };
  Mat3 R_free = R0;
  Vec3 w_free = p.omega_initial;
  double tau_prev = 0.0;
  Quat q_prev = p.attitude_initial;
  for (int pt = 0; pt < nlp.points(); ++pt) {
    const double tau = nlp.mesh().point_fraction(pt);
    Vec3 w = (spinning ? Vec3(spin_omega[pt] + tau * (p.omega_final - spin_omega_end))
                       : Vec3((1.0 - tau) * p.omega_initial + tau * p.omega_final)) +
             rotvec / T + std::sin(std::numbers::pi * tau) * (0.3 * rotvec.norm() / T) * transverse;
    if (dumping) {
      const auto wdot = [&](const Vec3& v) {
        return Vec3(J_inv * (dumping_torque(v) - v.cross(p.inertia_body * v)));
      };
      midpoint_substeps((tau - tau_prev) * T, wdot, R_free, w_free);
    } else if (p.free_final_attitude) {
      Vec3 w_held = w;
      midpoint_substeps((tau - tau_prev) * T, [](const Vec3&) { return Vec3::Zero().eval(); }, R_free,
                        w_held);
    }
    tau_prev = tau;
    if (dumping) {
      w = pt + 1 == nlp.points() ? p.omega_final : w_free;
      // With reaction wheels, the wheel torques whose reaction on the bus is the dumping torque: −A u = τ.
      const Vec3 u = p.wheels ? Vec3(-p.wheels->axes_body.inverse() * dumping_torque(w)) : dumping_torque(w);
      for (int i = 0; i < 3; ++i)
        z[kP * pt + 7 + i] = u[i];
    }
    const Quat q(p.free_final_attitude ? R_free
                 : spinning            ? Mat3(spin_R[pt] * so3::exp(tau * rotvec))
                                       : Mat3(R0 * so3::exp(tau * rotvec)));
    // The sign of q: that of q_0 (continuous along the eigenaxis path, which turns by at most π); along a
    // spin or a tumble over several turns, that of the previous point, so that the guess is continuous (a
    // sign flip between two points is a Simpson defect of 2 that Ipopt has to repair).
    const Quat& q_ref = (spinning || p.free_final_attitude) && pt > 0 ? q_prev : p.attitude_initial;
    const Quat qs =
        q.w() * q_ref.w() + q.vec().dot(q_ref.vec()) < 0 ? Quat(-q.w(), -q.x(), -q.y(), -q.z()) : q;
    q_prev = qs;
    z[kP * pt] = qs.w();
    z[kP * pt + 1] = qs.x();
    z[kP * pt + 2] = qs.y();
    z[kP * pt + 3] = qs.z();
    for (int i = 0; i < 3; ++i)
      z[kP * pt + 4 + i] = w[i];
  }
  if (nlp.free_time()) z[nlp.time_index()] = T;
  return {std::move(z), rotvec.norm() > 0.0};
}

}  // namespace detail
}  // namespace poinsot::optimal
