#include "arc_shooting.hpp"

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
#include <functional>
#include <limits>

#include "pmp_system.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/core/linear_solvers.hpp"
#include "poinsot/dynamics/tabulated_torque.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::optimal::detail {

namespace {

namespace odeint = boost::numeric::odeint;
using Kind = ArcEvent::Kind;
using Arc = ArcEvent::Arc;

/// The control of one arc: the bang signs of the free axes, the set of held axes with their sides, and the
/// set of singular axes.
struct ArcMode {
  Vec3 sign = Vec3::Ones();
  std::array<bool, 3> held{false, false, false};
  Vec3 side = Vec3::Zero();
  std::array<bool, 3> singular{false, false, false};
};

/// σ̇ = J⁻¹(Jω × σ − p_θ) − ω × σ (arc_shooting.hpp) at the body rate ω, switching vector σ = J⁻¹p_ω and
/// attitude costate p_θ, off the boundary arcs (no rate multiplier in ṗ_ω).
Vec3 switching_rate(const Mat3& J, const Mat3& J_inv, const Vec3& w, const Vec3& sigma, const Vec3& p_theta) {
  return J_inv * ((J * w).cross(sigma) - p_theta) - w.cross(sigma);
}

/// σ̈ (arc_shooting.hpp) at the same point and the torque u, off the boundary arcs.
Vec3 switching_second_derivative(const Mat3& J, const Mat3& J_inv, const Vec3& w, const Vec3& sigma,
                                 const Vec3& p_theta, const Vec3& u) {
  const Vec3 Jw = J * w;
  const Vec3 w_dot = J_inv * (u - w.cross(Jw));
  const Vec3 sigma_dot = switching_rate(J, J_inv, w, sigma, p_theta);
  const Vec3 p_theta_dot = p_theta.cross(w);
  return J_inv * ((J * w_dot).cross(sigma) + Jw.cross(sigma_dot) - p_theta_dot) - w_dot.cross(sigma) -
         w.cross(sigma_dot);
}

/// The singular components u_S of the control on a singular arc: σ̈_S = 0 with the other axes at their bang
/// values, C_SS u_S = −σ̈_S(u with u_S = 0), C = ∂σ̈/∂u (switching_torque_gain).
void singular_control(const Mat3& J, const Mat3& J_inv, const ArcMode& mode, const PmpView& v, Vec3& u) {
  std::vector<int> S;
  for (int k = 0; k < 3; ++k)
    if (mode.singular[static_cast<std::size_t>(k)]) {
      S.push_back(k);
      u[k] = 0.0;
    }
  const Vec3 sigma = J_inv * v.p_omega;
  const Vec3 b = switching_second_derivative(J, J_inv, v.omega, sigma, attitude_costate_body(v.R, v.P), u);
  const Mat3 C = switching_torque_gain(J_inv, sigma);
  const auto n = static_cast<Eigen::Index>(S.size());
  Eigen::MatrixXd M(n, n);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index a = 0; a < n; ++a) {
    for (Eigen::Index e = 0; e < n; ++e)
      M(a, e) = C(S[static_cast<std::size_t>(a)], S[static_cast<std::size_t>(e)]);
    rhs[a] = -b[S[static_cast<std::size_t>(a)]];
  }
  const Eigen::VectorXd uS = DenseLu(M).solve(rhs);
  for (Eigen::Index a = 0; a < n; ++a)
    u[S[static_cast<std::size_t>(a)]] = uS[a];
}

/// u and μ on an arc for the state y (arc_shooting.hpp): u_k = sign_k u_max,k off the held and singular sets;
/// on the held set A, (J⁻¹u)_A = (J⁻¹(ω × Jω))_A and μ from (J⁻¹)_AA (μ s)_A = (J⁻¹ g)_A; on the singular
/// set, σ̈_S = 0 (a singular arc never overlaps a boundary arc: read_arc_structure refuses it).
void arc_control(const ReorientationProblem& p, const Mat3& J_inv, const ArcMode& mode, const PmpState& y,
                 Vec3& u, Vec3& mu) {
  const PmpView v = unpack(y);
  const Mat3& J = p.inertia_body;
  u = mode.sign.cwiseProduct(p.torque_max);
  mu.setZero();
  if (mode.singular[0] || mode.singular[1] || mode.singular[2]) {
    singular_control(J, J_inv, mode, v, u);
    return;
  }
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

/// How far outside its bound (a multiple of u_max,k) a held or singular torque may go along a Newton iterate
/// before the shot counts as outside the domain; the converged solution must be within the bound (the
/// verification checks it).
constexpr double kControlEnvelope = 4.0;

/// The widest envelope a first shot outside kControlEnvelope is admitted with: the envelope is widened
/// fourfold at a time up to it, and Newton runs within the first that admits the shot. A singular torque
/// ũ_i = −(σ̈_i without u)/(∂σ̈_i/∂u_i) magnifies the direct costates' errors where ∂σ̈_i/∂u_i is small, as for
/// a nearly spherical body: problem 15 of seed 6 of the benchmark's nonprincipal family (J within 8 % of
/// 5.2 kg·m² times the identity) starts 10 to 16 times outside the bound on its singular arc of u2, and its
/// extremal, within the bound, verifies.
constexpr double kWidestFirstShotEnvelope = 256.0;

class ArcShooter {
 public:
  /// `envelope`: the multiple of u_max,k beyond which a held or singular torque puts the shot outside the
  /// domain.
  ArcShooter(const ReorientationProblem& p, const ArcStructure& s, double tolerance,
             double envelope = kControlEnvelope)
      : p_(p),
        s_(s),
        tol_(tolerance),
        envelope_(envelope),
        J_inv_(p.inertia_body.inverse()),
        R0_(p.attitude_initial.toRotationMatrix()),
        Rf_(p.attitude_final.toRotationMatrix()) {}

  int size() const { return 7 + static_cast<int>(s_.events.size()); }
  double final_time(const Eigen::VectorXd& x) const { return x[6]; }

  /// Integrates 0 → T; observe(t, y, u, μ) at `samples` points of each arc (ends included), and with
  /// `resolve` between them where the torque curves (kMaxSmoothSampleCurvature: a held or singular torque,
  /// smooth inside its arc). At each entry the rows of its arc are written into F (when given). False outside
  /// the domain (T ≤ 0, events outside (0, T), an exit before its entry, two events of one axis out of their
  /// order).
  template <class Observer>
  bool integrate(const Eigen::VectorXd& x, int samples, bool resolve, PmpState& end, Vec3& u_end,
                 Eigen::VectorXd* F, Observer&& observe) const {
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
    bool outside = false;
    PmpState y = pack(R0_, p_.omega_initial, 0.5 * R0_ * so3::hat(x.segment<3>(0)), x.segment<3>(3), 0.0);
    double t0 = 0.0;
    double last_sample = -T;       // the time of the last sample observed
    SmoothSampleRule smooth_rule;  // with `resolve`
    Vec3 u, mu;
    for (std::size_t a = 0; a <= n; ++a) {
      const double t1 = a < n ? order[a].first : T;
      auto rhs = [&](const PmpState& yy, PmpState& dy, double) {
        Vec3 uu, mm;
        arc_control(p_, J_inv_, mode, yy, uu, mm);
        // A held or singular torque far outside its bound (C_SS nearly singular along a poor iterate): the
        // shot is outside the domain; the flow is frozen so that the integrator ends at once.
        if (!uu.allFinite() || (uu.cwiseAbs() - envelope_ * p_.torque_max).maxCoeff() > 0.0) {
          outside = true;
          dy.fill(0.0);
          return;
        }
        pmp_rhs(p_, J_inv_, yy, dy, uu);
        for (int k = 0; k < 3; ++k)
          dy[21 + k] -= mm[k] * mode.side[k];
      };
      // Events at one time (three axes entering together, an exit and a switch of one axis) leave arcs of
      // zero length: integrated, not sampled, so that no time appears more than twice among the samples (the
      // replayed torque table). The next arc's first sample takes the time of the last one sampled: events
      // that Newton left a few ulps apart would otherwise give two samples that far apart, across which the
      // table's cubic interpolant takes a slope of order 1/ulp. Zero length is what the table reads as one
      // time (TabulatedTorque::same_time).
      const double zero_length = dynamics::TabulatedTorque::same_time * T;
      const int m = t1 - t0 > zero_length ? std::max(2, samples) : 1;
      // The last sample is t1 itself, the next arc's first: t0 + (t1 − t0) may round above t1.
      auto sample_time = [&](int i) { return i + 1 >= m ? t1 : t0 + (t1 - t0) * i / (m - 1); };
      auto step = [&](double from, double to) {
        odeint::integrate_adaptive(
            odeint::make_controlled<odeint::runge_kutta_fehlberg78<PmpState>>(tol_, tol_), rhs, y, from, to,
            (to - from) / 4);
      };
      // Integrates y from ta to ts and observes it there; with `resolve`, an interval across which the torque
      // curves more than kMaxSmoothSampleCurvature allows is halved and integrated again from ta.
      const std::function<void(double, double, int)> advance = [&](double ta, double ts, int depth) {
        if (!resolve) {
          step(ta, ts);
          arc_control(p_, J_inv_, mode, y, u, mu);
          observe(ts, y, u, mu);
          return;
        }
        const PmpState y_a = y;
        const Vec3 u_a = u;  // the torque at ta, the sample observed last
        Vec3 u_m, u_b, unused;
        const double mid = 0.5 * (ta + ts);
        step(ta, mid);
        arc_control(p_, J_inv_, mode, y, u_m, unused);
        step(mid, ts);
        arc_control(p_, J_inv_, mode, y, u_b, mu);
        if (depth < kMaxSampleHalvings && smooth_rule.curves(u_a, u_m, u_b)) {
          y = y_a;
          advance(ta, mid, depth + 1);
          advance(mid, ts, depth + 1);
          return;
        }
        u = u_b;
        observe(ts, y, u, mu);
      };
      arc_control(p_, J_inv_, mode, y, u, mu);
      if (m > 1) {
        last_sample = t0 - last_sample <= zero_length ? last_sample : t0;
        observe(last_sample, y, u, mu);
        for (int i = 1; i < m; ++i)
          advance(sample_time(i - 1), sample_time(i), 0);
        last_sample = t1;
      }
      if (m == 1 && t1 > t0)
        odeint::integrate_adaptive(
            odeint::make_controlled<odeint::runge_kutta_fehlberg78<PmpState>>(tol_, tol_), rhs, y, t0, t1,
            t1 - t0);
      if (outside) return false;
      if (a == n) break;
      // The event at t1: its rows, then the next arc's mode.
      const std::size_t k = order[a].second;
      const ArcEvent& e = s_.events[k];
      const PmpView v = unpack(y);
      const Vec3 sigma = J_inv_ * v.p_omega;
      const double ubar = p_.torque_max[e.axis];
      const auto axis = static_cast<std::size_t>(e.axis);
      switch (e.kind) {
        case Kind::sign_change:
          if (F) (*F)[7 + static_cast<int>(k)] = sigma[e.axis] * ubar;
          mode.sign[e.axis] = -mode.sign[e.axis];
          break;
        case Kind::entry:
          if (e.arc == Arc::singular) {
            if (F) {
              const Vec3 sigma_dot =
                  switching_rate(p_.inertia_body, J_inv_, v.omega, sigma, attitude_costate_body(v.R, v.P));
              (*F)[7 + static_cast<int>(k)] = sigma[e.axis] * ubar;
              (*F)[7 + e.pair] = sigma_dot[e.axis] * ubar * T;
            }
            mode.singular[axis] = true;
            break;
          }
          if (F) {
            (*F)[7 + static_cast<int>(k)] = (v.omega[e.axis] - e.side * p_.rate_max) * T;
            (*F)[7 + e.pair] = sigma[e.axis] * ubar;
          }
          mode.held[axis] = true;
          mode.side[e.axis] = e.side;
          break;
        case Kind::exit:
          mode.held[axis] = false;
          mode.singular[axis] = false;
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
    if (!integrate(x, 2, false, y, u, &F, [](double, const PmpState&, const Vec3&, const Vec3&) {}))
      return false;
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
  const ArcStructure& s_;
  double tol_;
  double envelope_;
  Mat3 J_inv_, R0_, Rf_;
};

/// Central-difference Jacobian (steps 1e-6 of the unknown or of its group's size: p_θ and p_ω/T, p_ω and
/// p_θ T, times T) and Newton with a backtracking line search on the max norm; least squares where the
/// Jacobian is singular. Returns the iterations; `stalled` when no step decreased the residual. Calls
/// o.on_newton_iteration, when set, after each iteration with the residual.
int arc_newton(const ArcShooter& sh, const ShootingOptions& o, Eigen::VectorXd& x, Eigen::VectorXd& F,
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

namespace {

/// Newton from x over the structure s (polished and judged as solve_indirect), then the solution's status,
/// events and samples. x holds the last iterate on return.
IndirectSolution shoot_over_arcs(const ReorientationProblem& p, const ArcStructure& s,
                                 const ShootingOptions& o, Eigen::VectorXd& x) {
  IndirectSolution out;
  Eigen::VectorXd F;
  double envelope = kControlEnvelope, norm = std::numeric_limits<double>::infinity();
  for (; envelope <= kWidestFirstShotEnvelope; envelope *= 4.0)
    if (ArcShooter(p, s, o.integration_tolerance, envelope).residual(x, F)) {
      norm = F.cwiseAbs().maxCoeff();
      break;
    }
  const ArcShooter shooter(p, s, o.integration_tolerance, envelope);
  if (!std::isfinite(norm)) {
    out.status = "not converged: the direct solution's costates give no admissible initial shot";
    return out;
  }
  bool stalled = false;
  int it = arc_newton(shooter, o, x, F, norm, stalled);
  double used_tolerance = o.integration_tolerance;
  if (norm > o.tolerance && norm < 100.0 * o.tolerance) {
    used_tolerance = o.integration_tolerance / 10.0;
    const ArcShooter polish(p, s, used_tolerance, envelope);
    if (Eigen::VectorXd Fp; polish.residual(x, Fp)) {
      F = Fp;
      norm = Fp.cwiseAbs().maxCoeff();
      it += arc_newton(polish, o, x, F, norm, stalled);
    }
  }
  const bool floor =
      norm > o.tolerance && stalled && used_tolerance < o.integration_tolerance && norm <= 10.0 * o.tolerance;
  out.iterations = it;
  out.residual = norm;
  out.converged = norm <= o.tolerance || floor;
  auto count_arcs = [&](Arc arc) {
    return std::count_if(s.events.begin(), s.events.end(),
                         [arc](const auto& e) { return e.kind == Kind::entry && e.arc == arc; });
  };
  const auto boundary = count_arcs(Arc::boundary), singular = count_arcs(Arc::singular);
  std::string arcs;
  if (boundary > 0) arcs = std::to_string(boundary) + " boundary arc(s) at the rate bound";
  if (singular > 0) arcs += (arcs.empty() ? "" : ", ") + std::to_string(singular) + " singular arc(s)";
  if (arcs.empty()) arcs = "no boundary or singular arc";
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
    const ArcEvent& e = s.events[k];
    if (e.kind == Kind::entry && e.arc == Arc::boundary)
      out.rate_bound_arcs.push_back({e.axis, e.side, t, x[7 + e.pair]});
    if (e.kind == Kind::entry && e.arc == Arc::singular)
      out.singular_arcs.push_back({e.axis, t, x[7 + e.pair]});
  }
  const ArcShooter result(p, s, used_tolerance, envelope);
  const Mat3 J_inv = p.inertia_body.inverse();
  PmpState y;
  Vec3 u;
  result.integrate(x, o.samples_per_arc, true, y, u, nullptr,
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

/// Shoots over the arcs of `s` from the direct solution's costates and final time; x holds the last iterate.
IndirectSolution shoot_from_direct(const ReorientationProblem& p, const DirectSolution& d,
                                   const ShootingOptions& o, const ArcStructure& s, Eigen::VectorXd& x) {
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
  x.resize(7 + static_cast<int>(s.events.size()));
  x.segment<3>(0) = p.attitude_initial.toRotationMatrix().transpose() * pi_space;
  x.segment<3>(3) = direct_costate_omega(d, 0.0);
  x[6] = d.final_time;
  for (std::size_t k = 0; k < s.events.size(); ++k)
    x[7 + static_cast<int>(k)] = s.events[k].time;
  return shoot_over_arcs(p, s, o, x);
}

/// The number of times a converged shot's structure is amended where its singular torque leaves its bound
/// (with_bounded_singular_torque): each amendment is shot from the previous extremal.
constexpr int kSingularTorqueAmendments = 3;

/// Shoots over the arcs of `s` from the direct solution; a converged extremal whose singular torque leaves
/// its bound is shot again over the amended structure (with_bounded_singular_torque), from its own costates
/// and event times, while that converges. Returns the last converged shot (or the first, unconverged).
IndirectSolution shoot_with_bounded_singular_torque(const ReorientationProblem& p, const DirectSolution& d,
                                                    const ShootingOptions& o, const ArcStructure& s) {
  Eigen::VectorXd x;
  IndirectSolution shot = shoot_from_direct(p, d, o, s, x);
  ArcStructure current = s;
  for (int k = 0; k < kSingularTorqueAmendments && shot.converged; ++k) {
    std::vector<double> times(current.events.size());
    for (std::size_t e = 0; e < times.size(); ++e)
      times[e] = x[7 + static_cast<int>(e)];
    ArcStructure amended;
    if (!with_bounded_singular_torque(p, current, times, shot, amended)) break;
    Eigen::VectorXd y(7 + static_cast<int>(amended.events.size()));
    y.head<7>() = x.head<7>();
    for (std::size_t e = 0; e < amended.events.size(); ++e)
      y[7 + static_cast<int>(e)] = amended.events[e].time;
    IndirectSolution again = shoot_over_arcs(p, amended, o, y);
    if (!again.converged) break;
    shot = std::move(again);
    current = std::move(amended);
    x = y;
  }
  return shot;
}

}  // namespace

IndirectSolution solve_over_arcs(const ReorientationProblem& p, const DirectSolution& d,
                                 const ShootingOptions& o, double shortest_singular_arc, bool dips) {
  const ArcStructure s = read_arc_structure(p, d, shortest_singular_arc, 0.0, 0.0, dips);
  if (s.refused.empty()) return shoot_with_bounded_singular_torque(p, d, o, s);
  IndirectSolution out;
  out.status = "not applied: " + s.refused;
  if (s.singular_at_start < 0 && s.singular_at_end < 0) return out;
  // The direct solution starts (ends) on a singular arc: shot as a short bang arc of either sign before its
  // entry (after its exit).
  const std::vector<double> either{1.0, -1.0}, none{0.0};
  for (const double start : s.singular_at_start >= 0 ? either : none)
    for (const double end : s.singular_at_end >= 0 ? either : none) {
      const ArcStructure entered = read_arc_structure(p, d, shortest_singular_arc, start, end, dips);
      if (!entered.refused.empty()) {  // a structure past the ends that the shooting does not handle
        out.status = "not applied: " + entered.refused;
        return out;
      }
      IndirectSolution shot = shoot_with_bounded_singular_torque(p, d, o, entered);
      if (shot.converged) return shot;
    }
  out.status += s.singular_at_start >= 0
                    ? " (shot as a short bang arc of either sign before its entry: not converged)"
                    : " (shot as a short bang arc of either sign after its exit: not converged)";
  return out;
}

}  // namespace poinsot::optimal::detail
