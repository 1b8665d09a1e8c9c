#include "poinsot/ensemble/slew_tracking.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::ensemble {
namespace {

/// q ⊗ (0, ω) / 2.
Quat quaternion_rate(const Quat& q, const Vec3& w) {
  return Quat(-0.5 * (q.x() * w.x() + q.y() * w.y() + q.z() * w.z()),
              0.5 * (q.w() * w.x() + q.y() * w.z() - q.z() * w.y()),
              0.5 * (q.w() * w.y() + q.z() * w.x() - q.x() * w.z()),
              0.5 * (q.w() * w.z() + q.x() * w.y() - q.y() * w.x()));
}

Quat axpy(const Quat& q, double a, const Quat& d) {
  return Quat(q.w() + a * d.w(), q.x() + a * d.x(), q.y() + a * d.y(), q.z() + a * d.z());
}

/// The body's constant matrices.
struct BodyMatrices {
  Mat3 J, J_inv;
};

/// One classical RK4 step of q̇ = ½ q ⊗ (0, ω), J ω̇ = u − ω × J ω with u = torque(stage, q, ω), stage 0 at t,
/// 1 and 2 at t + h/2, 3 at t + h; q normalised at the end.
template <class Torque>
void rk4_step(const BodyMatrices& b, double h, Quat& q, Vec3& w, Torque&& torque) {
  const auto f = [&](int stage, const Quat& qs, const Vec3& ws, Quat& dq, Vec3& dw) {
    const Vec3 u = torque(stage, qs, ws);
    dq = quaternion_rate(qs, ws);
    dw = b.J_inv * (u - ws.cross(b.J * ws));
  };
  Quat k1, k2, k3, k4;
  Vec3 l1, l2, l3, l4;
  f(0, q, w, k1, l1);
  f(1, axpy(q, 0.5 * h, k1), w + 0.5 * h * l1, k2, l2);
  f(2, axpy(q, 0.5 * h, k2), w + 0.5 * h * l2, k3, l3);
  f(3, axpy(q, h, k3), w + h * l3, k4, l4);
  const double s = h / 6.0;
  q = Quat(q.w() + s * (k1.w() + 2.0 * k2.w() + 2.0 * k3.w() + k4.w()),
           q.x() + s * (k1.x() + 2.0 * k2.x() + 2.0 * k3.x() + k4.x()),
           q.y() + s * (k1.y() + 2.0 * k2.y() + 2.0 * k3.y() + k4.y()),
           q.z() + s * (k1.z() + 2.0 * k2.z() + 2.0 * k3.z() + k4.z()));
  // Back onto |q| = 1 by one Newton step of 1/√(|q|²) from 1: |q|² = 1 + ε with ε = O(h⁵) per step (and
  // rounding), so the scale (3 − |q|²)/2 leaves |q| = 1 + O(ε²): unit to rounding, without a root.
  const double scale = 0.5 * (3.0 - q.squaredNorm());
  q.coeffs() *= scale;
  w += s * (l1 + 2.0 * l2 + 2.0 * l3 + l4);
}

BodyMatrices matrices(const Mat3& J) {
  return {J, J.inverse()};
}

void validate(const ReferenceRows& r) {
  const std::size_t n = r.time.size();
  if (r.attitude.size() != n || r.omega.size() != n || r.torque.size() != n)
    throw InvalidInput(
        "slew: reference: columns of unequal lengths; expected one attitude, rate and torque a row");
  if (n < 2) throw InvalidInput(fmt::format("slew: reference: {} rows; expected at least 2", n));
  for (std::size_t i = 0; i < n; ++i) {
    const bool finite = std::isfinite(r.time[i]) && r.attitude[i].coeffs().allFinite() &&
                        r.omega[i].allFinite() && r.torque[i].allFinite();
    if (!finite)
      throw InvalidInput(fmt::format("slew: reference: row {} is not finite; expected numbers", i + 1));
    if (!(r.attitude[i].norm() > 0.5))
      throw InvalidInput(fmt::format("slew: reference: row {}: |q| = {}; expected a unit quaternion", i + 1,
                                     r.attitude[i].norm()));
    if (i > 0 && !(r.time[i] >= r.time[i - 1]))
      throw InvalidInput(fmt::format("slew: reference: row {}: t = {} after {}; expected times in order",
                                     i + 1, r.time[i], r.time[i - 1]));
  }
}

/// The rows' motion at time t (see the header): cubic Hermite on the interval [t_i, t_(i+1)] (t_i <
/// t_(i+1)) that holds t, the first such interval from `hint` on (the times asked are non-decreasing).
class ReferenceInterpolant {
 public:
  ReferenceInterpolant(const ReferenceRows& r, const Mat3& J) : r_(r), b_(matrices(J)), q_(r.attitude) {
    for (std::size_t i = 0; i < q_.size(); ++i) {
      q_[i].normalize();
      if (i > 0 && q_[i].coeffs().dot(q_[i - 1].coeffs()) < 0.0) q_[i].coeffs() *= -1.0;
    }
  }
  void at(double t, Quat& q, Vec3& w) {
    const std::size_t n = r_.time.size();
    if (t <= r_.time.front() || t >= r_.time.back()) {
      const std::size_t i = t <= r_.time.front() ? 0 : n - 1;
      q = q_[i];
      w = r_.omega[i];
      return;
    }
    while (!(r_.time[i_ + 1] > t && r_.time[i_ + 1] > r_.time[i_]) && i_ + 2 < n)
      ++i_;
    const std::size_t a = i_, b = i_ + 1;
    const double h = r_.time[b] - r_.time[a], s = (t - r_.time[a]) / h;
    const double h00 = (1.0 + 2.0 * s) * (1.0 - s) * (1.0 - s), h10 = s * (1.0 - s) * (1.0 - s),
                 h01 = s * s * (3.0 - 2.0 * s), h11 = s * s * (s - 1.0);
    const Quat dqa = quaternion_rate(q_[a], r_.omega[a]), dqb = quaternion_rate(q_[b], r_.omega[b]);
    q.coeffs() =
        h00 * q_[a].coeffs() + h10 * h * dqa.coeffs() + h01 * q_[b].coeffs() + h11 * h * dqb.coeffs();
    q.normalize();
    const auto dw = [&](std::size_t i) {
      return Vec3(b_.J_inv * (r_.torque[i] - r_.omega[i].cross(b_.J * r_.omega[i])));
    };
    w = h00 * r_.omega[a] + h10 * h * dw(a) + h01 * r_.omega[b] + h11 * h * dw(b);
  }

 private:
  const ReferenceRows& r_;
  BodyMatrices b_;
  std::vector<Quat> q_;
  std::size_t i_ = 0;
};

}  // namespace

const char* to_string(SlewTorqueLimit limit) {
  switch (limit) {
    case SlewTorqueLimit::per_axis:
      return "per_axis";
    case SlewTorqueLimit::norm:
      return "norm";
    case SlewTorqueLimit::none:
      break;
  }
  return "none";
}

SlewTracking::SlewTracking(SlewSpec spec, const Mat3& nominal_inertia, const dynamics::State& initial)
    : spec_(std::move(spec)) {
  const SlewSpec& s = spec_;
  if (!s.control) throw InvalidInput("slew: control: missing; expected a t,ux,uy,uz table");
  require_finite("slew: kp", s.kp);
  require_non_negative("slew: kp", s.kp, "N·m/rad");
  require_finite("slew: kd", s.kd);
  require_non_negative("slew: kd", s.kd, "N·m·s/rad");
  if (s.limit != SlewTorqueLimit::none) {
    const int n = s.limit == SlewTorqueLimit::per_axis ? 3 : 1;
    for (int i = 0; i < n; ++i)
      if (!(std::isfinite(s.torque_max[i]) && s.torque_max[i] > 0.0))
        throw InvalidInput(
            fmt::format("slew: torque_max: got {}, expected a finite bound > 0 N·m", s.torque_max[i]));
  }
  require_finite("slew: pointing_requirement", s.pointing_requirement);
  require_non_negative("slew: pointing_requirement", s.pointing_requirement, "rad");
  require_finite("slew: t_end", s.t_end);
  require_positive("slew: t_end", s.t_end, "s");
  require_finite("slew: dt", s.dt);
  require_positive("slew: dt", s.dt, "s");
  require_finite("slew: target omega", s.target_omega);
  q_target_ = so3::quaternion_from_rotation(s.target_attitude);

  // The grid: a node at every row time of the table inside (0, t_end), steps h ≤ dt between nodes.
  std::vector<double> nodes{0.0};
  for (double t : s.control->breakpoints())
    if (t > 0.0 && t < s.t_end) nodes.push_back(t);
  nodes.push_back(s.t_end);
  double steps = 0.0;
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i)
    steps += std::max(1.0, std::ceil((nodes[i + 1] - nodes[i]) / s.dt));
  if (steps > static_cast<double>(kMaxSlewSteps)) {
    throw InvalidInput(
        fmt::format("slew: {:.3g} steps (t_end / dt and the control's {} row times); expected "
                    "at most {:.0e}: a larger dt",
                    steps, nodes.size() - 2, static_cast<double>(kMaxSlewSteps)));
  }
  step_t_.reserve(static_cast<std::size_t>(steps) + 1);
  for (std::size_t i = 0; i + 1 < nodes.size(); ++i) {
    const double a = nodes[i], b = nodes[i + 1];
    const int m = static_cast<int>(std::max(1.0, std::ceil((b - a) / s.dt)));
    for (int j = 0; j < m; ++j)
      step_t_.push_back(a + (b - a) * j / m);
  }
  step_t_.push_back(s.t_end);
  const std::size_t n = step_t_.size() - 1;
  step_h_.resize(n);
  u_ref_.resize(3 * n);
  q_ref_.resize(2 * n + 1);
  w_ref_.resize(2 * n + 1);

  // u_ref at the stages of each step (the table's piece announced, so the step's end sees its own piece),
  // and the reference: the open-loop replay on the nominal body by RK4 on the half steps.
  const dynamics::TabulatedTorque& table = *s.control;
  const BodyMatrices b = matrices(nominal_inertia);
  Quat q = so3::quaternion_from_rotation(initial.R_space_body);
  Vec3 w = initial.omega_body;
  q_ref_[0] = q;
  w_ref_[0] = w;
  const Mat3 I = Mat3::Identity();
  const bool rows = !s.reference.time.empty();
  std::optional<ReferenceInterpolant> interpolant;
  if (rows) {
    validate(s.reference);
    interpolant.emplace(s.reference, nominal_inertia);
    interpolant->at(0.0, q_ref_[0], w_ref_[0]);
  }
  for (std::size_t k = 0; k < n; ++k) {
    const double t = step_t_[k], h = step_t_[k + 1] - t;
    step_h_[k] = h;
    table.enter_interval(t);
    u_ref_[3 * k] = table.torque_body(t, I, Vec3::Zero());
    u_ref_[3 * k + 1] = table.torque_body(t + 0.5 * h, I, Vec3::Zero());
    u_ref_[3 * k + 2] = table.torque_body(step_t_[k + 1], I, Vec3::Zero());
    if (rows) {
      interpolant->at(t + 0.5 * h, q_ref_[2 * k + 1], w_ref_[2 * k + 1]);
      interpolant->at(step_t_[k + 1], q_ref_[2 * k + 2], w_ref_[2 * k + 2]);
      continue;
    }
    for (int half = 0; half < 2; ++half) {
      const double t0 = t + 0.5 * h * half, t1 = half == 0 ? t + 0.5 * h : step_t_[k + 1];
      const double stage_t[4] = {t0, 0.5 * (t0 + t1), 0.5 * (t0 + t1), t1};
      rk4_step(b, t1 - t0, q, w, [&](int stage, const Quat&, const Vec3&) {
        return table.torque_body(stage_t[stage], I, Vec3::Zero());
      });
      q_ref_[2 * k + 1 + half] = q;
      w_ref_[2 * k + 1 + half] = w;
    }
  }
}

SlewOutcome SlewTracking::run(const Mat3& inertia, const dynamics::State& initial) const {
  const SlewSpec& s = spec_;
  const BodyMatrices b = matrices(inertia);
  Quat q = so3::quaternion_from_rotation(initial.R_space_body);
  Vec3 w = initial.omega_body;
  const Vec3 L_space0 = initial.R_space_body * (inertia * w);
  SlewOutcome out;
  double peak_u2 = 0.0, peak_fb2 = 0.0, peak_h2 = 0.0;
  // The law at reference point r (t_k or t_k + h/2) with the planned torque u_ref; the peaks are taken on
  // the motion itself (the first stage of each step, and the end), not on RK4's predictor stages.
  const auto law = [&](std::size_t r, const Vec3& u_ref, const Quat& qs, const Vec3& ws) {
    const Quat& qr = q_ref_[r];
    // (w, v) = q_ref* ⊗ q, at the stage's q as it is (|q| = 1 on the motion; the field is smooth off it).
    const double ew = qr.w() * qs.w() + qr.x() * qs.x() + qr.y() * qs.y() + qr.z() * qs.z();
    const Vec3 ev(qr.w() * qs.x() - qr.x() * qs.w() - qr.y() * qs.z() + qr.z() * qs.y(),
                  qr.w() * qs.y() - qr.y() * qs.w() - qr.z() * qs.x() + qr.x() * qs.z(),
                  qr.w() * qs.z() - qr.z() * qs.w() - qr.x() * qs.y() + qr.y() * qs.x());
    const double kp2 = ew < 0.0 ? -2.0 * s.kp : 2.0 * s.kp;
    Vec3 u = u_ref - kp2 * ev - s.kd * (ws - w_ref_[r]);
    if (s.limit == SlewTorqueLimit::per_axis) {
      u = u.cwiseMax(-s.torque_max).cwiseMin(s.torque_max);
    } else if (s.limit == SlewTorqueLimit::norm) {
      const double un2 = u.squaredNorm();
      if (un2 > s.torque_max[0] * s.torque_max[0]) u *= s.torque_max[0] / std::sqrt(un2);
    }
    return u;
  };
  const auto track = [&](const Vec3& u, const Vec3& u_ref) {
    peak_u2 = std::max(peak_u2, u.squaredNorm());
    peak_fb2 = std::max(peak_fb2, (u - u_ref).squaredNorm());
  };
  const std::size_t n = step_h_.size();
  for (std::size_t k = 0; k < n; ++k) {
    rk4_step(b, step_h_[k], q, w, [&](int stage, const Quat& qs, const Vec3& ws) {
      const std::size_t half = static_cast<std::size_t>((stage + 1) / 2);  // t, t + h/2, t + h
      const Vec3& u_ref = u_ref_[3 * k + half];
      const Vec3 u = law(2 * k + half, u_ref, qs, ws);
      if (stage == 0) track(u, u_ref);
      return u;
    });
    const Vec3 h_wheel = q.conjugate() * L_space0 - b.J * w;
    peak_h2 = std::max(peak_h2, h_wheel.squaredNorm());
  }
  if (n > 0) track(law(2 * n, u_ref_[3 * n - 1], q, w), u_ref_[3 * n - 1]);
  out.final_state.time = s.t_end;
  out.final_state.R_space_body = q.toRotationMatrix();
  out.final_state.omega_body = w;
  out.pointing_error = so3::angle_between(q, q_target_);
  out.rate_error = (w - s.target_omega).norm();
  out.peak_torque = std::sqrt(peak_u2);
  out.peak_feedback_torque = std::sqrt(peak_fb2);
  out.peak_wheel_momentum = std::sqrt(peak_h2);
  out.meets_requirement = out.pointing_error <= s.pointing_requirement;
  return out;
}

}  // namespace poinsot::ensemble
