#include "control_replay.hpp"

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
  opt.dt = s.final_time / 16.0;
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
