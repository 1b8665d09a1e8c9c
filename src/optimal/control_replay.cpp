#include "control_replay.hpp"
// The replays of a control history through DOP853: an indirect solution's (control_replay.hpp) and a direct
// solution's (poinsot/optimal/direct_replay.hpp).

// GCC 12 reports -Wmaybe-uninitialized and -Wrestrict inside Boost.Odeint's stepper copy constructors when
// they are inlined here (false positives in library code: the work arrays are resized before use).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"

#include <Eigen/SVD>
#include <algorithm>
#include <array>
#include <boost/numeric/odeint.hpp>
#include <exception>
#include <limits>
#include <memory>
#include <vector>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/dynamics/tabulated_torque.hpp"
#include "poinsot/optimal/direct_replay.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::optimal::detail {

namespace {

/// The replayed torque of `s` and the times where it is cut into pieces: for bang-bang controls the constant
/// torque of the arc being integrated (set before the arc, so no stage sees the next one); for smooth
/// controls the table of the samples, each piece announced before it is integrated
/// (TabulatedTorque::enter_interval).
class ReplayedTorque {
 public:
  explicit ReplayedTorque(const IndirectSolution& s) : s_(s) {
    if (s.bang_bang) {
      auto arc = arc_torque_;
      model_ = dynamics::TorqueModel::callback([arc](double, const Mat3&, const Vec3&) { return *arc; },
                                               false, "optimal bang-bang torque");
    } else {
      table_ = std::make_shared<dynamics::TabulatedTorque>(s.time, s.torque_body, "optimal tabulated torque",
                                                           dynamics::TableInterpolation::cubic);
      model_ = table_;
    }
  }
  const std::shared_ptr<const dynamics::TorqueModel>& model() const { return model_; }
  /// The piece boundaries strictly inside (t_begin, t_end), then t_end.
  std::vector<double> cuts(double t_begin, double t_end) const {
    std::vector<double> out;
    if (s_.bang_bang) {
      for (const auto& a : s_.arcs)
        if (a.t_end > t_begin && a.t_end < t_end) out.push_back(a.t_end);
    } else {
      for (const double t : table_->breakpoints())
        if (t > t_begin && t < t_end) out.push_back(t);
    }
    out.push_back(t_end);
    return out;
  }
  /// Selects the piece that starts at t_begin and ends at t_end (its midpoint decides).
  void enter(double t_begin, double t_end) const {
    if (s_.bang_bang) {
      const double mid = 0.5 * (t_begin + t_end);
      *arc_torque_ = Vec3::Zero();
      for (const auto& a : s_.arcs)
        if (a.t_begin <= mid && mid <= a.t_end) *arc_torque_ = a.torque_body;
    } else {
      table_->enter_interval(t_begin);
    }
  }
  /// The torque at t on the piece entered last.
  Vec3 at(double t) const { return model_->torque_body(t, Mat3::Identity(), Vec3::Zero()); }

 private:
  const IndirectSolution& s_;
  std::shared_ptr<Vec3> arc_torque_ = std::make_shared<Vec3>(Vec3::Zero());
  std::shared_ptr<const dynamics::TabulatedTorque> table_;
  std::shared_ptr<const dynamics::TorqueModel> model_;
};

/// ω and the state-transition matrix Φ (6 × 6, column-major) of (δθ, δω), packed for Boost.Odeint.
using VariationalState = std::array<double, 39>;

/// Φ(t_end, t_begin) of the motion from ω(t_begin) = omega under the replayed torque (unscaled (δθ, δω)).
Eigen::Matrix<double, 6, 6> segment_transition(const ReorientationProblem& p, const ReplayedTorque& torque,
                                               Vec3 omega, double t_begin, double t_end) {
  namespace odeint = boost::numeric::odeint;
  const Mat3& J = p.inertia_body;
  const Mat3 J_inv = J.inverse();
  VariationalState y{};
  Eigen::Map<Vec3>(y.data()) = omega;
  Eigen::Map<Eigen::Matrix<double, 6, 6>>(y.data() + 3).setIdentity();
  auto rhs = [&](const VariationalState& x, VariationalState& dx, double t) {
    const Vec3 w = Eigen::Map<const Vec3>(x.data());
    const Eigen::Map<const Eigen::Matrix<double, 6, 6>> phi(x.data() + 3);
    Eigen::Matrix<double, 6, 6> A = Eigen::Matrix<double, 6, 6>::Zero();
    A.topLeftCorner<3, 3>() = -so3::hat(w);
    A.topRightCorner<3, 3>() = Mat3::Identity();
    A.bottomRightCorner<3, 3>() = J_inv * (so3::hat(J * w) - so3::hat(w) * J);
    Eigen::Map<Vec3>(dx.data()) = J_inv * (torque.at(t) - w.cross(J * w));
    Eigen::Map<Eigen::Matrix<double, 6, 6>>(dx.data() + 3) = A * phi;
  };
  double t = t_begin;
  for (const double cut : torque.cuts(t_begin, t_end)) {
    torque.enter(t, cut);
    odeint::integrate_adaptive(
        odeint::make_controlled<odeint::runge_kutta_fehlberg78<VariationalState>>(1e-10, 1e-10), rhs, y, t,
        cut, (cut - t) / 4);
    t = cut;
  }
  return Eigen::Map<const Eigen::Matrix<double, 6, 6>>(y.data() + 3);
}

}  // namespace

dynamics::State replay_control(const ReorientationProblem& p, const IndirectSolution& s,
                               dynamics::State start, double t_end) {
  const auto body = dynamics::RigidBody::from_inertia(p.inertia_body);
  const ReplayedTorque torque(s);
  dynamics::IntegratorOptions opt;
  opt.dt = opt.max_step = s.final_time / 16.0;
  opt.rtol = opt.atol = replay_tolerance;
  dynamics::Dop853Integrator integrator(body, torque.model(), opt);
  dynamics::State state = start;
  double dt = opt.dt;
  try {
    for (const double cut : torque.cuts(start.time, t_end)) {
      torque.enter(state.time, cut);
      while (cut - state.time > 1e-14 * s.final_time) {
        const auto r = integrator.step(state, std::min(dt, cut - state.time));
        dt = std::max(r.dt_next, 1e-12);
      }
      state.time = cut;
    }
  } catch (const ComputationFailed&) {  // DOP853 gave up (a non-finite start or motion): no state to compare
    const double nan = std::numeric_limits<double>::quiet_NaN();
    state.R_space_body.setConstant(nan);
    state.omega_body.setConstant(nan);
  }
  return state;
}

double replay_amplification(const ReorientationProblem& p, const IndirectSolution& s) {
  const ReplayedTorque torque(s);
  std::vector<double> t{0.0};
  t.insert(t.end(), s.node_time.begin(), s.node_time.end());
  t.push_back(s.final_time);
  Eigen::Matrix<double, 6, 6> phi = Eigen::Matrix<double, 6, 6>::Identity();
  try {
    for (std::size_t m = 0; m + 1 < t.size(); ++m) {
      const Vec3 omega = m == 0 ? p.omega_initial : s.node_omega_body[m - 1];
      phi = segment_transition(p, torque, omega, t[m], t[m + 1]) * phi;
    }
  } catch (const std::exception&) {  // Odeint's step control gave up (a motion that left every scale)
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (!phi.allFinite()) return std::numeric_limits<double>::quiet_NaN();
  // Scaled coordinates (δθ, T δω): Φ_s = S Φ S⁻¹, S = diag(I, T I).
  const double T = s.final_time;
  phi.topRightCorner<3, 3>() /= T;
  phi.bottomLeftCorner<3, 3>() *= T;
  return Eigen::JacobiSVD<Eigen::Matrix<double, 6, 6>>(phi).singularValues()[0];
}

}  // namespace poinsot::optimal::detail

namespace poinsot::optimal {

double DirectReplay::scaled_error() const {
  if (std::isnan(attitude_error) || std::isnan(rate_error)) return std::numeric_limits<double>::quiet_NaN();
  return std::max(attitude_error, final_time * rate_error);
}

namespace {

/// One interval of the transcription: the sample indices of its left node, midpoint and right node.
struct ReplayInterval {
  std::size_t left = 0;
  double t_begin = 0.0, t_end = 0.0;
};

/// The intervals of `d`: node, midpoint, node, ..., a repeated time (a phase boundary's duplicated node)
/// starting the next phase.
std::vector<ReplayInterval> intervals_of(const DirectSolution& d) {
  const std::size_t n = d.time.size();
  if (n < 3 || d.torque_body.size() != n || d.attitude.empty())
    throw InvalidInput("direct replay: " + std::to_string(n) +
                       " samples; expected a direct solution (nodes and midpoints)");
  std::vector<ReplayInterval> out;
  std::size_t i = 0;
  while (i + 2 < n) {
    if (d.time[i + 1] == d.time[i]) {  // the duplicated node between two phases
      ++i;
      continue;
    }
    if (!(d.time[i] < d.time[i + 1] && d.time[i + 1] < d.time[i + 2]))
      throw InvalidInput("direct replay: the sample times are not increasing at t = " +
                         std::to_string(d.time[i]) + " s; expected nodes and midpoints in order");
    out.push_back({i, d.time[i], d.time[i + 2]});
    i += 2;
  }
  if (i + 1 != n) throw InvalidInput("direct replay: the samples do not end on a node");
  return out;
}

}  // namespace

namespace {

/// The quadratic control through (u_left, u_mid, u_right) at s = 0, ½, 1 of an interval, and with reaction
/// wheels the wheel momenta it integrates to: h(s) = h_left + Δ Σ_j P_j(s) u_j with the antiderivatives P_j
/// of the three Lagrange basis polynomials (P_j(1) = 1/6, 4/6, 1/6: Simpson's rule), exact.
struct ReplayedControl {
  const DirectSolution& d;
  ReplayInterval k;
  Vec3 h_left = Vec3::Zero();

  double fraction(double t) const { return (t - k.t_begin) / (k.t_end - k.t_begin); }
  Vec3 control(double t) const {
    const double s = fraction(t);
    return 2 * (s - 0.5) * (s - 1) * d.torque_body[k.left] - 4 * s * (s - 1) * d.torque_body[k.left + 1] +
           2 * s * (s - 0.5) * d.torque_body[k.left + 2];
  }
  Vec3 wheel_momentum(double t) const {
    const double s = fraction(t), s2 = s * s, s3 = s2 * s;
    return h_left + (k.t_end - k.t_begin) * ((2.0 / 3.0 * s3 - 1.5 * s2 + s) * d.torque_body[k.left] +
                                             (-4.0 / 3.0 * s3 + 2.0 * s2) * d.torque_body[k.left + 1] +
                                             (2.0 / 3.0 * s3 - 0.5 * s2) * d.torque_body[k.left + 2]);
  }
};

}  // namespace

DirectReplay replay_direct(const ReorientationProblem& p, const DirectSolution& d) {
  const std::vector<ReplayInterval> intervals = intervals_of(d);
  auto current = std::make_shared<ReplayedControl>(ReplayedControl{d, intervals.front()});
  if (p.wheels) current->h_left = p.wheels->momentum_initial;
  // Without wheels the control is the body torque. With them the bus (inertia J_b) feels −A u and carries
  // the wheels' momentum: J_b ω̇ + ω × (J_b ω + A h) = −A u, that is, a rigid body J_b under the torque
  // −A u − ω × A h with h integrated exactly from h_0 (reaction_wheels.hpp), not taken from the conserved L.
  const auto torque =
      p.wheels ? dynamics::TorqueModel::callback(
                     [current, A = p.wheels->axes_body](double t, const Mat3&, const Vec3& w) -> Vec3 {
                       return -A * current->control(t) - w.cross(A * current->wheel_momentum(t));
                     },
                     true, "direct collocation wheel torques")
               : dynamics::TorqueModel::callback(
                     [current](double t, const Mat3&, const Vec3&) -> Vec3 { return current->control(t); },
                     false, "direct collocation torque");
  const auto body = dynamics::RigidBody::from_inertia(p.bus_inertia());
  dynamics::IntegratorOptions opt;
  opt.dt = opt.max_step = d.final_time / 16.0;
  opt.rtol = opt.atol = 1e-13;
  dynamics::Dop853Integrator integrator(body, torque, opt);
  dynamics::State state;
  state.time = 0.0;
  state.R_space_body = p.attitude_initial.toRotationMatrix();
  state.omega_body = p.omega_initial;
  DirectReplay r;
  r.final_time = d.final_time;
  const std::size_t cones = p.pointing.size();
  r.pointing.reset(p.pointing);
  Quat q_prev(state.R_space_body);
  r.pointing.lower(p.pointing, 0.0, q_prev);
  // Between the end of the previous step and `s`: the Hermite interpolant at 8 points
  // (pointing_constraint.hpp).
  Vec3 w_prev = state.omega_body;
  double t_prev = 0.0;
  const auto check_pointing = [&](const dynamics::State& s) {
    if (cones == 0) return;
    const Quat q(s.R_space_body);
    r.pointing.lower_along(p.pointing, t_prev, q_prev, w_prev, s.time, q, s.omega_body, 8);
    q_prev = q;
    w_prev = s.omega_body;
    t_prev = s.time;
  };
  // With wheels: |h_k| / h̄_k and the drift of L = R (J_b ω + A h) at the end of every step.
  const Mat3 Jb = p.bus_inertia();
  const Vec3 L0 = p.wheel_system_momentum();
  const auto check_wheels = [&](const dynamics::State& s) {
    if (!p.wheels) return;
    const Vec3 h = current->wheel_momentum(s.time);
    for (int i = 0; i < 3; ++i) {
      r.peak_wheel_momentum[i] = std::max(r.peak_wheel_momentum[i], std::abs(h[i]));
      if (std::isfinite(p.wheels->momentum_max[i]))
        r.wheel_momentum_excess =
            std::max(r.wheel_momentum_excess, std::abs(h[i]) / p.wheels->momentum_max[i] - 1.0);
    }
    const Vec3 L = s.R_space_body * (Jb * s.omega_body + p.wheels->axes_body * h);
    r.momentum_drift = std::max(r.momentum_drift, (L - L0).norm());
  };
  if (p.wheels) {
    r.peak_wheel_momentum = p.wheels->momentum_initial.cwiseAbs();
    r.wheel_momentum_excess = -std::numeric_limits<double>::infinity();
  }
  double dt = opt.dt;
  try {
    for (const ReplayInterval& k : intervals) {
      if (p.wheels && k.left != current->k.left) current->h_left = current->wheel_momentum(current->k.t_end);
      current->k = k;
      state.time = k.t_begin;
      const double max_step = cones > 0 || p.wheels ? (k.t_end - k.t_begin) / 16.0 : k.t_end - k.t_begin;
      while (k.t_end - state.time > 1e-14 * d.final_time) {
        const auto step = integrator.step(state, std::min({dt, max_step, k.t_end - state.time}));
        dt = std::max(step.dt_next, 1e-12);
        check_pointing(state);
        check_wheels(state);
      }
      state.time = k.t_end;
    }
    if (p.wheels) r.final_wheel_momentum = current->wheel_momentum(current->k.t_end);
  } catch (const ComputationFailed&) {  // DOP853 gave up: nothing to compare
    r.attitude_error = r.rate_error = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  const Mat3 target =
      p.free_final_attitude ? d.attitude.back().toRotationMatrix() : p.attitude_final.toRotationMatrix();
  r.attitude_error = state.R_space_body.allFinite() ? so3::angle_between(state.R_space_body, target)
                                                    : std::numeric_limits<double>::quiet_NaN();
  r.rate_error = (state.omega_body - p.omega_final).norm();
  return r;
}

}  // namespace poinsot::optimal
