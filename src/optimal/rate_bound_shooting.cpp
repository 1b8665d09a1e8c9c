#include "rate_bound_shooting.hpp"

// GCC 12 reports -Wmaybe-uninitialized, -Wuninitialized and -Wrestrict inside Boost.Odeint's stepper copy
// constructors when they are inlined here (false positives in library code: the work arrays are resized
// before use).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <Eigen/Dense>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <limits>

#include "pmp_system.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/core/linear_solvers.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::optimal::detail {

namespace {

namespace odeint = boost::numeric::odeint;
using Kind = RateBoundEvent::Kind;

/// The control of one arc: the bang signs of the free axes and the set of held axes with their sides.
struct ArcMode {
  Vec3 sign = Vec3::Ones();
  std::array<bool, 3> held{false, false, false};
  Vec3 side = Vec3::Zero();
};

/// u and μ on an arc for the state y (indirect sections of rate_bound_shooting.hpp): u_k = sign_k u_max,k off
/// the held set A; on A, (J⁻¹u)_A = (J⁻¹(ω × Jω))_A; μ from (J⁻¹)_AA (μ s)_A = (J⁻¹ g)_A.
void arc_control(const ReorientationProblem& p, const Mat3& J_inv, const ArcMode& mode, const PmpState& y,
                 Vec3& u, Vec3& mu) {
  const PmpView v = unpack(y);
  const Mat3& J = p.inertia_body;
  u = mode.sign.cwiseProduct(p.torque_max);
  mu.setZero();
  std::vector<int> A;
  for (int k = 0; k < 3; ++k)
    if (mode.held[static_cast<std::size_t>(k)]) A.push_back(k);
  if (A.empty()) return;
  const auto n = static_cast<Eigen::Index>(A.size());
  const Vec3 gyro = J_inv * v.omega.cross(J * v.omega);
  const Vec3 sigma = J_inv * v.p_omega;
  const Vec3 g =
      -attitude_costate_body(v.R, v.P) + (so3::hat(v.omega) * J - so3::hat(J * v.omega)).transpose() * sigma;
  const Vec3 Jg = J_inv * g;
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd b(n), c(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    const int k = A[static_cast<std::size_t>(a)];
    for (Eigen::Index e = 0; e < n; ++e)
      M(a, e) = J_inv(k, A[static_cast<std::size_t>(e)]);
    double free_part = 0.0;
    for (int j = 0; j < 3; ++j)
      if (!mode.held[static_cast<std::size_t>(j)]) free_part += J_inv(k, j) * u[j];
    b[a] = gyro[k] - free_part;
    c[a] = Jg[k];
  }
  const DenseLu lu(M);
  const Eigen::VectorXd uA = lu.solve(b), ms = lu.solve(c);
  for (Eigen::Index a = 0; a < n; ++a) {
    const int k = A[static_cast<std::size_t>(a)];
    u[k] = uA[a];
    mu[k] = mode.side[k] * ms[a];
  }
}

class RateBoundShooter {
 public:
  RateBoundShooter(const ReorientationProblem& p, const RateBoundStructure& s, double tolerance)
      : p_(p),
        s_(s),
        tol_(tolerance),
        J_inv_(p.inertia_body.inverse()),
        R0_(p.attitude_initial.toRotationMatrix()),
        Rf_(p.attitude_final.toRotationMatrix()) {}

  int size() const { return 7 + static_cast<int>(s_.events.size()); }
  double final_time(const Eigen::VectorXd& x) const { return x[6]; }

  /// Integrates 0 → T; observe(t, y, u, μ) at `samples` points of each arc (ends included). At each entry
  /// the rows of its arc are written into F (when given). False outside the domain (T ≤ 0, events outside
  /// (0, T), an exit before its entry, two events of one axis out of their order).
  template <class Observer>
  bool integrate(const Eigen::VectorXd& x, int samples, PmpState& end, Vec3& u_end, Eigen::VectorXd* F,
                 Observer&& observe) const {
    const double T = x[6];
    if (!(T > 0.0)) return false;
    const std::size_t n = s_.events.size();
    std::vector<std::pair<double, std::size_t>> order;
    for (std::size_t k = 0; k < n; ++k) {
      const double t = x[7 + static_cast<int>(k)];
      if (!(t > 0.0 && t < T)) return false;
      order.emplace_back(t, k);
    }
    std::sort(order.begin(), order.end());
    // The events of one axis keep their structural order (an exit after its entry, switches in sequence).
    for (int axis = 0; axis < 3; ++axis) {
      std::size_t last = 0;
      bool first = true;
      for (const auto& [t, k] : order)
        if (s_.events[k].axis == axis) {
          if (!first && k < last) return false;
          last = k;
          first = false;
        }
    }
    ArcMode mode;
    mode.sign = s_.initial_sign;
    PmpState y = pack(R0_, p_.omega_initial, 0.5 * R0_ * so3::hat(x.segment<3>(0)), x.segment<3>(3), 0.0);
    double t0 = 0.0;
    Vec3 u, mu;
    for (std::size_t a = 0; a <= n; ++a) {
      const double t1 = a < n ? order[a].first : T;
      auto rhs = [&](const PmpState& yy, PmpState& dy, double) {
        Vec3 uu, mm;
        arc_control(p_, J_inv_, mode, yy, uu, mm);
        pmp_rhs(p_, J_inv_, yy, dy, uu);
        for (int k = 0; k < 3; ++k)
          dy[21 + k] -= mm[k] * mode.side[k];
      };
      // Events at one time (three axes entering together) leave arcs of zero length: integrated, not
      // sampled, so that no time appears more than twice among the samples (the replayed torque table).
      const int m = t1 - t0 > 1e-12 * T ? std::max(2, samples) : 1;
      for (int i = 0; i < m; ++i) {
        const double ts = t0 + (t1 - t0) * i / (m - 1);
        if (i > 0 && t1 > t0) {
          const double ta = t0 + (t1 - t0) * (i - 1) / (m - 1);
          odeint::integrate_adaptive(
              odeint::make_controlled<odeint::runge_kutta_fehlberg78<PmpState>>(tol_, tol_), rhs, y, ta, ts,
              (ts - ta) / 4);
        }
        arc_control(p_, J_inv_, mode, y, u, mu);
        if (m > 1) observe(ts, y, u, mu);
      }
      if (m == 1 && t1 > t0)
        odeint::integrate_adaptive(
            odeint::make_controlled<odeint::runge_kutta_fehlberg78<PmpState>>(tol_, tol_), rhs, y, t0, t1,
            t1 - t0);
      if (a == n) break;
      // The event at t1: its rows, then the next arc's mode.
      const std::size_t k = order[a].second;
      const RateBoundEvent& e = s_.events[k];
      const PmpView v = unpack(y);
      const Vec3 sigma = J_inv_ * v.p_omega;
      const double ubar = p_.torque_max[e.axis];
      switch (e.kind) {
        case Kind::sign_change:
          if (F) (*F)[7 + static_cast<int>(k)] = sigma[e.axis] * ubar;
          mode.sign[e.axis] = -mode.sign[e.axis];
          break;
        case Kind::entry:
          if (F) {
            (*F)[7 + static_cast<int>(k)] = (v.omega[e.axis] - e.side * p_.rate_max) * T;
            (*F)[7 + e.pair] = sigma[e.axis] * ubar;
          }
          mode.held[static_cast<std::size_t>(e.axis)] = true;
          mode.side[e.axis] = e.side;
          break;
        case Kind::exit:
          mode.held[static_cast<std::size_t>(e.axis)] = false;
          mode.side[e.axis] = 0.0;
          mode.sign[e.axis] = e.sign_after;
          break;
      }
      t0 = t1;
    }
    end = y;
    u_end = u;
    return true;
  }

  bool residual(const Eigen::VectorXd& x, Eigen::VectorXd& F) const {
    F.setZero(size());
    PmpState y;
    Vec3 u;
    if (!integrate(x, 2, y, u, &F, [](double, const PmpState&, const Vec3&, const Vec3&) {})) return false;
    const PmpView v = unpack(y);
    const double T = x[6];
    const Mat3 E = Rf_.transpose() * v.R;
    F.segment<3>(0) =
        p_.free_final_attitude ? Vec3(x.segment<3>(0)) : Vec3(0.5 * so3::vee(E - E.transpose()));
    F.segment<3>(3) = (v.omega - p_.omega_final) * T;
    F[6] = hamiltonian(p_, J_inv_, v, u);
    return F.allFinite();
  }

 private:
  const ReorientationProblem& p_;
  const RateBoundStructure& s_;
  double tol_;
  Mat3 J_inv_, R0_, Rf_;
};

/// Central-difference Jacobian (steps 1e-6 of the unknown or of its group's size: p_θ and p_ω/T, p_ω and
/// p_θ T, times T) and Newton with a backtracking line search on the max norm; least squares where the
/// Jacobian is singular. Returns the iterations; `stalled` when no step decreased the residual. Calls
/// o.on_newton_iteration, when set, after each iteration with the residual.
int rate_newton(const RateBoundShooter& sh, const ShootingOptions& o, Eigen::VectorXd& x, Eigen::VectorXd& F,
                double& norm, bool& stalled) {
  const double tolerance = o.tolerance;
  const int max_iterations = o.max_iterations;
  stalled = false;
  int it = 0;
  const int n = sh.size();
  for (; it < max_iterations && norm > tolerance; ++it) {
    const double T = x[6];
    const double pt = x.segment<3>(0).cwiseAbs().maxCoeff(), pw = x.segment<3>(3).cwiseAbs().maxCoeff();
    Eigen::MatrixXd jac(n, n);
    bool ok = true;
    for (int j = 0; j < n && ok; ++j) {
      const double scale = j < 3 ? std::max(pt, pw / T) : j < 6 ? std::max(pw, pt * T) : T;
      const double h = 1e-6 * std::max({std::abs(x[j]) * (j < 6 ? 1.0 : 0.0), scale, 1e-12});
      Eigen::VectorXd xp = x, xm = x, Fp, Fm;
      xp[j] += h;
      xm[j] -= h;
      const bool plus = sh.residual(xp, Fp), minus = sh.residual(xm, Fm);
      if (plus && minus)
        jac.col(j) = (Fp - Fm) / (2.0 * h);
      else if (plus)
        jac.col(j) = (Fp - F) / h;
      else if (minus)
        jac.col(j) = (F - Fm) / h;
      else
        ok = false;
    }
    if (!ok) break;
    const Eigen::VectorXd step = solve_col_piv_qr(jac, Eigen::VectorXd(-F));
    bool accepted = false;
    double alpha = 1.0;
    for (int ls = 0; ls < 30 && step.allFinite(); ++ls, alpha *= 0.5) {
      Eigen::VectorXd xn = x + alpha * step, Fn;
      if (sh.residual(xn, Fn) && Fn.cwiseAbs().maxCoeff() < (1.0 - 1e-4 * alpha) * norm) {
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
    if (o.on_newton_iteration) o.on_newton_iteration(norm);
  }
  return it;
}

/// Linear interpolation of the direct estimates of p_ω at t (extrapolated beyond the interval centres).
Vec3 direct_costate_omega(const DirectSolution& d, double t) {
  const auto& c = d.costate_time;
  const auto it = std::upper_bound(c.begin(), c.end(), t);
  const std::size_t j = std::clamp<std::size_t>(static_cast<std::size_t>(it - c.begin()), 1, c.size() - 1);
  const double w = (t - c[j - 1]) / (c[j] - c[j - 1]);
  return (1.0 - w) * d.costate_omega[j - 1] + w * d.costate_omega[j];
}

}  // namespace

bool rate_bound_active(const ReorientationProblem& p, const DirectSolution& d, double& peak) {
  peak = 0.0;
  for (const auto& w : d.omega_body)
    peak = std::max(peak, w.cwiseAbs().maxCoeff());
  return p.has_rate_bound() && peak > p.rate_max * (1.0 - 1e-4);
}

RateBoundStructure read_rate_bound_structure(const ReorientationProblem& p, const DirectSolution& d) {
  RateBoundStructure s;
  if (p.objective != Objective::minimum_time || p.bound != TorqueBound::per_axis) {
    s.refused = "boundary arcs are handled for minimum time with per-axis torque bounds only";
    return s;
  }
  const double r = p.rate_max, T = d.final_time;
  const std::size_t N = d.time.size();
  std::vector<RateBoundEvent> events;
  for (int i = 0; i < 3; ++i) {
    // The boundary arcs of axis i: stretches of ≥ 2 samples at the bound.
    std::vector<std::pair<std::size_t, std::size_t>> arcs;
    for (std::size_t j = 0; j < N;) {
      if (std::abs(d.omega_body[j][i]) < (1.0 - 1e-3) * r) {
        ++j;
        continue;
      }
      std::size_t e = j;
      const double side = d.omega_body[j][i] > 0 ? 1.0 : -1.0;
      while (e + 1 < N && d.omega_body[e + 1][i] * side >= (1.0 - 1e-3) * r)
        ++e;
      if (e > j) arcs.emplace_back(j, e);
      j = e + 1;
    }
    auto on_arc = [&](std::size_t j) {
      for (const auto& [a, b] : arcs)
        if (j >= a && j <= b) return true;
      return false;
    };
    // Saturated samples off the arcs: the signs; an arc between two of them takes the place of a switch.
    const double umax = p.torque_max[i];
    int last = -1;
    double inside_since = -1.0;
    std::size_t next_arc = 0;
    for (std::size_t j = 0; j < N; ++j) {
      if (on_arc(j)) {
        inside_since = -1.0;
        continue;
      }
      const double u = d.torque_body[j][i];
      if (std::abs(u) < 0.95 * umax) {
        if (inside_since < 0.0) inside_since = d.time[j];
        if (d.time[j] - inside_since > 0.05 * T && s.refused.empty())
          s.refused = "u" + std::to_string(i + 1) +
                      " is inside its bound off the rate bound from t = " + format_number(inside_since, 6) +
                      " s to " + format_number(d.time[j], 6) + " s (a singular arc?)";
      } else {
        inside_since = -1.0;
      }
      if (std::abs(u) <= 0.5 * umax) continue;
      const double sign = u > 0 ? 1.0 : -1.0;
      // Arcs passed since the last saturated sample.
      bool crossed_arc = false;
      while (next_arc < arcs.size() && arcs[next_arc].second < j) {
        const auto [a, b] = arcs[next_arc++];
        RateBoundEvent enter, leave;
        enter.kind = Kind::entry;
        leave.kind = Kind::exit;
        enter.axis = leave.axis = i;
        enter.side = leave.side = d.omega_body[a][i] > 0 ? 1.0 : -1.0;
        enter.time = d.time[a];
        leave.time = d.time[b];
        leave.sign_after = sign;
        events.push_back(enter);
        events.push_back(leave);
        crossed_arc = true;
      }
      if (last < 0) {
        s.initial_sign[i] = sign;
      } else if (!crossed_arc && (u > 0) != (d.torque_body[static_cast<std::size_t>(last)][i] > 0)) {
        double t0 = d.time[static_cast<std::size_t>(last)];
        for (std::size_t k = static_cast<std::size_t>(last); k < j; ++k) {
          const double a = d.torque_body[k][i], b = d.torque_body[k + 1][i];
          if ((a > 0) != (b > 0)) {
            t0 = d.time[k] + (d.time[k + 1] - d.time[k]) * a / (a - b);
            break;
          }
        }
        RateBoundEvent e;
        e.axis = i;
        e.time = t0;
        events.push_back(e);
      }
      last = static_cast<int>(j);
    }
    if (next_arc < arcs.size()) {
      s.refused = "the rate bound of axis " + std::to_string(i + 1) + " is active up to the final time";
      return s;
    }
  }
  std::stable_sort(events.begin(), events.end(),
                   [](const auto& a, const auto& b) { return a.time < b.time; });
  // Pair each entry with the next exit of its axis.
  for (std::size_t k = 0; k < events.size(); ++k)
    if (events[k].kind == Kind::entry)
      for (std::size_t l = k + 1; l < events.size(); ++l)
        if (events[l].kind == Kind::exit && events[l].axis == events[k].axis && events[l].pair < 0) {
          events[k].pair = static_cast<int>(l);
          events[l].pair = static_cast<int>(k);
          break;
        }
  s.events = events;
  return s;
}

IndirectSolution solve_rate_bounded(const ReorientationProblem& p, const DirectSolution& d,
                                    const ShootingOptions& o) {
  IndirectSolution out;
  const RateBoundStructure s = read_rate_bound_structure(p, d);
  if (!s.refused.empty()) {
    out.status = "not applied: the rate bound is active and " + s.refused;
    return out;
  }
  // Initial costates as solve_indirect: p_θ(0) = R_0ᵀ mean_k(R_k p_θ,k), p_ω(0) extrapolated.
  Vec3 pi_space = Vec3::Zero();
  for (std::size_t k = 0; k < d.costate_time.size(); ++k) {
    const auto it = std::lower_bound(d.time.begin(), d.time.end(), d.costate_time[k]);
    const std::size_t j =
        std::min<std::size_t>(static_cast<std::size_t>(it - d.time.begin()), d.time.size() - 1);
    pi_space += d.attitude[j].toRotationMatrix() * d.costate_attitude_body[k];
  }
  pi_space /= static_cast<double>(d.costate_time.size());
  if (p.free_final_attitude) pi_space.setZero();
  const RateBoundShooter shooter(p, s, o.integration_tolerance);
  Eigen::VectorXd x(shooter.size());
  x.segment<3>(0) = p.attitude_initial.toRotationMatrix().transpose() * pi_space;
  x.segment<3>(3) = direct_costate_omega(d, 0.0);
  x[6] = d.final_time;
  for (std::size_t k = 0; k < s.events.size(); ++k)
    x[7 + static_cast<int>(k)] = s.events[k].time;
  Eigen::VectorXd F;
  double norm = shooter.residual(x, F) ? F.cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
  if (!std::isfinite(norm)) {
    out.status = "not converged: the direct solution's costates give no admissible initial shot";
    return out;
  }
  bool stalled = false;
  int it = rate_newton(shooter, o, x, F, norm, stalled);
  double used_tolerance = o.integration_tolerance;
  if (norm > o.tolerance && norm < 100.0 * o.tolerance) {
    used_tolerance = o.integration_tolerance / 10.0;
    const RateBoundShooter polish(p, s, used_tolerance);
    if (Eigen::VectorXd Fp; polish.residual(x, Fp)) {
      F = Fp;
      norm = Fp.cwiseAbs().maxCoeff();
      it += rate_newton(polish, o, x, F, norm, stalled);
    }
  }
  const bool floor =
      norm > o.tolerance && stalled && used_tolerance < o.integration_tolerance && norm <= 10.0 * o.tolerance;
  out.iterations = it;
  out.residual = norm;
  out.converged = norm <= o.tolerance || floor;
  const std::string arcs =
      std::to_string((s.events.size() - static_cast<std::size_t>(std::count_if(
                                            s.events.begin(), s.events.end(),
                                            [](const auto& e) { return e.kind == Kind::sign_change; }))) /
                     2) +
      " boundary arc(s) at the rate bound";
  out.status =
      floor ? "converged (residual " + format_number(norm, 3) + " at its round-off floor; " + arcs + ")"
      : out.converged ? "converged (" + arcs + ")"
                      : "not converged: shooting residual " + format_number(norm, 3) + " after " +
                            std::to_string(it) + " Newton iterations (" + arcs + ")";
  out.final_time = x[6];
  out.costate_attitude_initial = x.segment<3>(0);
  out.costate_omega_initial = x.segment<3>(3);
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t k = 0; k < s.events.size(); ++k)
    order.emplace_back(x[7 + static_cast<int>(k)], k);
  std::sort(order.begin(), order.end());
  for (const auto& [t, k] : order) {
    out.switch_times.push_back(t);
    out.switch_axes.push_back(s.events[k].axis);
    if (s.events[k].kind == Kind::entry)
      out.rate_bound_arcs.push_back({s.events[k].axis, s.events[k].side, t, x[7 + s.events[k].pair]});
  }
  const RateBoundShooter result(p, s, used_tolerance);
  const Mat3 J_inv = p.inertia_body.inverse();
  PmpState y;
  Vec3 u;
  result.integrate(x, o.samples_per_arc, y, u, nullptr,
                   [&](double t, const PmpState& yy, const Vec3& uu, const Vec3& mu) {
                     const PmpView v = unpack(yy);
                     out.time.push_back(t);
                     out.attitude.push_back(v.R);
                     out.omega_body.push_back(v.omega);
                     out.torque_body.push_back(uu);
                     out.costate_attitude.push_back(v.P);
                     out.costate_attitude_body.push_back(attitude_costate_body(v.R, v.P));
                     out.costate_omega.push_back(v.p_omega);
                     out.switching_function.push_back(J_inv * v.p_omega);
                     out.hamiltonian.push_back(hamiltonian(p, J_inv, v, uu));
                     out.rate_bound_multiplier.push_back(mu);
                     out.cost = v.cost;
                   });
  return out;
}

}  // namespace poinsot::optimal::detail
