#include "poinsot/optimal/indirect_shooting.hpp"

// GCC 12 reports -Wmaybe-uninitialized and -Wrestrict inside Boost.Odeint's stepper copy constructors when
// they are inlined here (false positives in library code: the work arrays are resized before use).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "pmp_system.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "switching_structure.hpp"

namespace poinsot::optimal {

namespace {

using detail::PmpState;
using detail::read_reversals;
using detail::read_switching_structure;
using detail::SwitchGuess;
namespace odeint = boost::numeric::odeint;

class Shooter {
 public:
  Shooter(const ReorientationProblem& p, const ShootingOptions& o, const SwitchGuess& s, bool bang_bang)
      : p_(p),
        o_(o),
        s_(s),
        bang_(bang_bang),
        rev_(!bang_bang && !s.reversals.empty()),
        J_inv_(p.inertia_body.inverse()) {
    R0_ = p.attitude_initial.toRotationMatrix();
    Rf_ = p.attitude_final.toRotationMatrix();
  }

  int size() const { return 6 + (p_.free_final_time() ? 1 : 0) + static_cast<int>(knot_count()); }

  /// The torque on the arc that starts after the switches at times ≤ t_begin (bang-bang), from x.
  Vec3 arc_torque(const Eigen::VectorXd& x, double t_mid) const {
    Vec3 u;
    for (int i = 0; i < 3; ++i) {
      double sign = s_.initial_sign[i];
      for (std::size_t k = 0; k < s_.axes.size(); ++k)
        if (s_.axes[k] == i && switch_time(x, k) < t_mid) sign = -sign;
      u[i] = sign * p_.torque_max[i];
    }
    return u;
  }
  /// The unknown times between arcs: the switches (bang-bang) or the reversals (norm bound).
  std::size_t knot_count() const { return bang_ ? s_.axes.size() : rev_ ? s_.reversals.size() : 0; }
  double switch_time(const Eigen::VectorXd& x, std::size_t k) const { return x[7 + static_cast<int>(k)]; }
  /// The scale of the k-th knot's condition (σ times a torque, like H).
  double knot_scale(std::size_t k) const { return bang_ ? p_.torque_max[s_.axes[k]] : p_.torque_max[0]; }
  double final_time(const Eigen::VectorXd& x) const { return p_.free_final_time() ? x[6] : p_.final_time; }

  /// Integrates from 0 to T; calls observe(t, y, u) at samples_per_arc points of each arc when asked.
  /// Returns false when the switching times are out of order or out of (0, T).
  template <class Observer>
  bool propagate(const Eigen::VectorXd& x, std::vector<double>* sigma_at_switch, Observer&& observe) const {
    const double T = final_time(x);
    if (!(T > 0.0)) return false;
    std::vector<double> knots{0.0};
    std::vector<std::size_t> order;
    if (knot_count() > 0) {
      for (std::size_t k = 0; k < knot_count(); ++k)
        order.push_back(k);
      std::sort(order.begin(), order.end(),
                [&](auto a, auto b) { return switch_time(x, a) < switch_time(x, b); });
      for (auto k : order) {
        if (!(switch_time(x, k) > 0.0 && switch_time(x, k) < T)) return false;
        knots.push_back(switch_time(x, k));
      }
    }
    knots.push_back(T);
    const Vec3 p_theta0 = x.segment<3>(0);
    PmpState y = detail::pack(R0_, p_.omega_initial, 0.5 * R0_ * so3::hat(p_theta0), x.segment<3>(3), 0.0);
    if (sigma_at_switch) sigma_at_switch->assign(knot_count(), 0.0);
    // Reversals: on each arc u = −ū σ/‖σ‖ with σ's sign locked to the side of `side` (σ(0) on the first arc,
    // reversed at each reversal), so that the control is continued smoothly through σ = 0 up to the arc's end
    // and the knot conditions σ(t_k)·side = 0 are smooth in t_k.
    Vec3 side = J_inv_ * x.segment<3>(3);
    for (std::size_t a = 0; a + 1 < knots.size(); ++a) {
      const double t0 = knots[a], t1 = knots[a + 1];
      const Vec3 u_arc = bang_ ? arc_torque(x, 0.5 * (t0 + t1)) : Vec3::Zero();
      auto control = [&](const PmpState& yy) -> Vec3 {
        if (bang_) return u_arc;
        const Vec3 p_omega = Eigen::Map<const Vec3>(yy.data() + 21);
        if (!rev_) return minimising_control(p_, p_omega);
        const Vec3 sigma = J_inv_ * p_omega;
        return sigma.norm() > 0.0
                   ? Vec3(-p_.torque_max[0] * (sigma.dot(side) < 0.0 ? -1.0 : 1.0) * sigma.normalized())
                   : Vec3::Zero();
      };
      auto rhs = [&](const PmpState& yy, PmpState& dy, double) {
        detail::pmp_rhs(p_, J_inv_, yy, dy, control(yy));
      };
      const int n = std::max(2, o_.samples_per_arc);
      for (int i = 0; i < n; ++i) {
        const double ts = t0 + (t1 - t0) * i / (n - 1);
        if (i > 0 && t1 > t0) {
          const double ta = t0 + (t1 - t0) * (i - 1) / (n - 1);
          odeint::integrate_adaptive(odeint::make_controlled<odeint::runge_kutta_fehlberg78<PmpState>>(
                                         o_.integration_tolerance, o_.integration_tolerance),
                                     rhs, y, ta, ts, (ts - ta) / 4);
        }
        observe(ts, y, control(y));
      }
      if (a + 1 < knots.size() - 1) {
        const Vec3 sigma = J_inv_ * Eigen::Map<const Vec3>(y.data() + 21);
        const std::size_t k = order[a];
        if (sigma_at_switch) (*sigma_at_switch)[k] = bang_ ? sigma[s_.axes[k]] : sigma.dot(side.normalized());
        side = -side;
      }
    }
    return true;
  }

  /// The scaled shooting residual; false when x is outside the domain.
  bool residual(const Eigen::VectorXd& x, Eigen::VectorXd& F) const {
    PmpState yT{};
    Vec3 uT = Vec3::Zero();
    std::vector<double> sigma;
    ShootingOptions quick = o_;
    quick.samples_per_arc = 2;
    Shooter fast(p_, quick, s_, bang_);
    if (!fast.propagate(x, &sigma, [&](double, const PmpState& y, const Vec3& u) {
          yT = y;
          uT = u;
        }))
      return false;
    const detail::PmpView v = detail::unpack(yT);
    const double T = final_time(x);
    F.resize(size());
    const Mat3 E = Rf_.transpose() * v.R;
    // Free final attitude: p_θ(T) = 0, i.e. p_θ(0) = 0 (R p_θ is constant).
    F.segment<3>(0) =
        p_.free_final_attitude ? Vec3(x.segment<3>(0)) : Vec3(0.5 * so3::vee(E - E.transpose()));
    F.segment<3>(3) = (v.omega - p_.omega_final) * T;
    int row = 6;
    if (p_.free_final_time()) F[row++] = detail::hamiltonian(p_, J_inv_, v, uT);
    for (std::size_t k = 0; k < sigma.size(); ++k)
      F[row++] = sigma[k] * knot_scale(k);
    return F.allFinite();
  }

 private:
  const ReorientationProblem& p_;
  ShootingOptions o_;
  const SwitchGuess& s_;
  bool bang_, rev_;
  Mat3 J_inv_, R0_, Rf_;
};

/// Newton's method with a backtracking line search on the shooting residual, from x (F = its residual);
/// stops at norm ≤ o.tolerance, after o.max_iterations, or when no step decreases the residual. Returns the
/// iterations taken; x, F and norm are the last accepted iterate; `stalled` tells whether it stopped because
/// no step decreased the residual.
int newton(const Shooter& shooter, const ShootingOptions& o, Eigen::VectorXd& x, Eigen::VectorXd& F,
           double& norm, bool& stalled) {
  int it = 0;
  stalled = false;
  for (; it < o.max_iterations && norm > o.tolerance; ++it) {
    const int n = shooter.size();
    Eigen::MatrixXd Jac(n, n);
    for (int j = 0; j < n; ++j) {
      const double scale = j < 3   ? x.segment<3>(0).cwiseAbs().maxCoeff()
                           : j < 6 ? x.segment<3>(3).cwiseAbs().maxCoeff()
                                   : std::abs(x[j]);
      const double h = 1e-7 * std::max({std::abs(x[j]), 1e-2 * scale, 1e-12});
      Eigen::VectorXd xp = x, Fp;
      xp[j] += h;
      if (!shooter.residual(xp, Fp)) {
        xp[j] = x[j] - h;
        if (!shooter.residual(xp, Fp)) break;
        Jac.col(j) = (F - Fp) / h;
      } else {
        Jac.col(j) = (Fp - F) / h;
      }
    }
    const Eigen::VectorXd step = Jac.colPivHouseholderQr().solve(-F);
    double alpha = 1.0;
    bool accepted = false;
    for (int ls = 0; ls < 30; ++ls, alpha *= 0.5) {
      Eigen::VectorXd xn = x + alpha * step, Fn;
      if (shooter.residual(xn, Fn) && Fn.cwiseAbs().maxCoeff() < (1.0 - 1e-4 * alpha) * norm) {
        x = xn;
        F = Fn;
        norm = Fn.cwiseAbs().maxCoeff();
        accepted = true;
        break;
      }
    }
    if (!accepted) {
      stalled = true;
      break;
    }
  }
  return it;
}

}  // namespace

Vec3 minimising_control(const ReorientationProblem& p, const Vec3& costate_omega) {
  const Vec3 sigma = p.inertia_body.inverse() * costate_omega;
  Vec3 u;
  switch (p.objective) {
    case Objective::minimum_time:
      if (p.bound == TorqueBound::per_axis) {
        for (int i = 0; i < 3; ++i)
          u[i] = sigma[i] < 0 ? p.torque_max[i] : -p.torque_max[i];
        return u;
      }
      return sigma.norm() > 0 ? Vec3(-p.torque_max[0] * sigma.normalized()) : Vec3::Zero();
    case Objective::minimum_energy:
      u = -0.5 * sigma;
      break;
    case Objective::minimum_time_regularised:
      u = -sigma / (2.0 * p.energy_weight);
      break;
  }
  if (p.bound == TorqueBound::per_axis) return u.cwiseMax(-p.torque_max).cwiseMin(p.torque_max);
  return u.norm() > p.torque_max[0] ? Vec3(p.torque_max[0] * u.normalized()) : u;
}

IndirectSolution solve_indirect(const ReorientationProblem& p, const DirectSolution& d,
                                const ShootingOptions& o) {
  validate(p);
  if (d.costate_time.size() < 2 || d.time.empty())
    throw InvalidInput(
        "indirect: the direct solution has no costate estimates; expected a solve_direct result");
  IndirectSolution out;
  out.bang_bang = p.objective == Objective::minimum_time && p.bound == TorqueBound::per_axis;

  double rate_peak = 0.0;
  for (const auto& w : d.omega_body)
    rate_peak = std::max(rate_peak, w.cwiseAbs().maxCoeff());
  if (p.has_rate_bound() && rate_peak > p.rate_max * (1.0 - 1e-4)) {
    out.status = "not applied: the rate bound is active (peak |ω_i| = " + format_number(rate_peak, 8) +
                 " rad/s); state-constrained arcs are not handled by the shooting method";
    return out;
  }
  SwitchGuess sw = out.bang_bang ? read_switching_structure(p, d) : SwitchGuess{};
  if (p.objective == Objective::minimum_time && p.bound == TorqueBound::norm)
    sw.reversals = read_reversals(p, d);
  if (!sw.singular.empty()) {
    out.status = "not applied: " + sw.singular + "; singular arcs are not handled by the shooting method";
    return out;
  }
  Shooter shooter(p, o, sw, out.bang_bang);

  // Initial costates: R p_θ is constant, so p_θ(0) = R_0ᵀ · mean_k(R_k p_θ,k); p_ω(0) extrapolated linearly.
  Vec3 pi_space = Vec3::Zero();
  for (std::size_t k = 0; k < d.costate_time.size(); ++k) {
    // attitude at the costate time: nearest sample (interval centres coincide with midpoints)
    const auto it = std::lower_bound(d.time.begin(), d.time.end(), d.costate_time[k]);
    const std::size_t j = std::min<std::size_t>(it - d.time.begin(), d.time.size() - 1);
    pi_space += d.attitude[j].toRotationMatrix() * d.costate_attitude_body[k];
  }
  pi_space /= static_cast<double>(d.costate_time.size());
  Eigen::VectorXd x(shooter.size());
  x.segment<3>(0) = p.attitude_initial.toRotationMatrix().transpose() * pi_space;
  const double c0 = d.costate_time[0], c1 = d.costate_time[1];
  x.segment<3>(3) = d.costate_omega[0] - c0 / (c1 - c0) * (d.costate_omega[1] - d.costate_omega[0]);
  if (p.free_final_time()) x[6] = d.final_time;
  for (std::size_t k = 0; k < sw.times.size(); ++k)
    x[7 + static_cast<int>(k)] = sw.times[k];
  for (std::size_t k = 0; k < sw.reversals.size(); ++k)
    x[7 + static_cast<int>(k)] = sw.reversals[k];

  Eigen::VectorXd F;
  if (!shooter.residual(x, F)) {
    out.status = "not converged: the direct solution's costates give no admissible initial shot";
    return out;
  }
  double norm = F.cwiseAbs().maxCoeff();
  bool stalled = false;
  int it = newton(shooter, o, x, F, norm, stalled);
  // The residual's floor is the integration's error: when Newton stalls just above the tolerance, polish
  // once with a tenfold tighter integration (e.g. the reversal of a sphere's slew: 3.5e-12 at 1e-13).
  ShootingOptions used = o;
  if (norm > o.tolerance && norm < 100.0 * o.tolerance) {
    ShootingOptions tight = o;
    tight.integration_tolerance = o.integration_tolerance / 10.0;
    const Shooter polish(p, tight, sw, out.bang_bang);
    if (Eigen::VectorXd Fp; polish.residual(x, Fp)) {
      F = Fp;
      norm = Fp.cwiseAbs().maxCoeff();
      it += newton(polish, tight, x, F, norm, stalled);
      used = tight;
    }
  }
  // Still stalled within 10× the tolerance with the tighter integration: the residual's round-off floor.
  const bool floor = norm > o.tolerance && stalled && used.integration_tolerance < o.integration_tolerance &&
                     norm <= 10.0 * o.tolerance;
  const Shooter result_shooter(p, used, sw, out.bang_bang);
  out.iterations = it;
  out.residual = norm;
  out.converged = norm <= o.tolerance || floor;
  out.status = floor           ? "converged (residual " + format_number(norm, 3) + " at its round-off floor)"
               : out.converged ? "converged"
                               : "not converged: shooting residual " + format_number(norm, 3) + " after " +
                                     std::to_string(it) + " Newton iterations";
  out.final_time = result_shooter.final_time(x);
  out.costate_attitude_initial = x.segment<3>(0);
  out.costate_omega_initial = x.segment<3>(3);
  for (std::size_t k = 0; k < result_shooter.knot_count(); ++k) {
    out.switch_times.push_back(result_shooter.switch_time(x, k));
    out.switch_axes.push_back(out.bang_bang ? sw.axes[k] : -1);
  }
  {  // ascending switching times
    std::vector<std::size_t> idx(out.switch_times.size());
    for (std::size_t k = 0; k < idx.size(); ++k)
      idx[k] = k;
    std::sort(idx.begin(), idx.end(),
              [&](auto a, auto b) { return out.switch_times[a] < out.switch_times[b]; });
    std::vector<double> t;
    std::vector<int> a;
    for (auto k : idx) {
      t.push_back(out.switch_times[k]);
      a.push_back(out.switch_axes[k]);
    }
    out.switch_times = t;
    out.switch_axes = a;
  }
  const Mat3 J_inv = p.inertia_body.inverse();
  result_shooter.propagate(x, nullptr, [&](double t, const PmpState& y, const Vec3& u) {
    const detail::PmpView v = detail::unpack(y);
    out.time.push_back(t);
    out.attitude.push_back(v.R);
    out.omega_body.push_back(v.omega);
    out.torque_body.push_back(u);
    out.costate_attitude.push_back(v.P);
    out.costate_attitude_body.push_back(detail::attitude_costate_body(v.R, v.P));
    out.costate_omega.push_back(v.p_omega);
    out.switching_function.push_back(J_inv * v.p_omega);
    out.hamiltonian.push_back(detail::hamiltonian(p, J_inv, v, u));
    out.cost = v.cost;
  });
  if (out.bang_bang) {
    std::vector<double> knots{0.0};
    knots.insert(knots.end(), out.switch_times.begin(), out.switch_times.end());
    knots.push_back(out.final_time);
    for (std::size_t a = 0; a + 1 < knots.size(); ++a)
      out.arcs.push_back(
          {knots[a], knots[a + 1], result_shooter.arc_torque(x, 0.5 * (knots[a] + knots[a + 1]))});
  }
  return out;
}

}  // namespace poinsot::optimal
