#include "multiple_shooting.hpp"

// GCC 12 reports -Wmaybe-uninitialized, -Wuninitialized and -Wrestrict inside Boost.Odeint's stepper copy
// constructors when they are inlined here (false positives in library code: the work arrays are resized
// before use).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wrestrict"
#pragma GCC diagnostic ignored "-Wuninitialized"

#include <Eigen/Dense>
#include <Eigen/SparseCore>
#include <algorithm>
#include <boost/numeric/odeint.hpp>
#include <cmath>

#include "poinsot/core/linear_solvers.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::optimal::detail {

namespace odeint = boost::numeric::odeint;

/// The largest turn (rad) of a norm-bound torque between two output samples: the replay's local cubic then
/// errs by about ū (0.02)⁴/4! ≈ 7e-9 ū in the fastest turn.
constexpr double kMaxSampleTurn = 0.02;
/// The largest turn (rad) of a norm-bound torque over one piece of the shooting residual's integration.
constexpr double kMaxPieceTurn = 0.5;

Shooter::Shooter(const ReorientationProblem& p, const ShootingOptions& o, const SwitchGuess& s,
                 bool bang_bang, std::vector<Mat3> node_attitude, double omega_scale,
                 std::vector<double> node_fraction)
    : p_(p),
      options_(o),
      s_(s),
      bang_(bang_bang),
      rev_(!bang_bang && !s.reversals.empty()),
      ref_(std::move(node_attitude)),
      omega_scale_(omega_scale),
      fraction_(std::move(node_fraction)),
      J_inv_(p.inertia_body.inverse()),
      R0_(p.attitude_initial.toRotationMatrix()),
      Rf_(p.attitude_final.toRotationMatrix()) {
  if (fraction_.empty())
    for (int m = 1; m < nodes(); ++m)
      fraction_.push_back(static_cast<double>(m) / nodes());
}

Vec3 Shooter::arc_torque(const Eigen::VectorXd& x, double t_mid) const {
  Vec3 u;
  for (int i = 0; i < 3; ++i) {
    double sign = s_.initial_sign[i];
    for (std::size_t k = 0; k < s_.axes.size(); ++k)
      if (s_.axes[k] == i && switch_time(x, k) < t_mid) sign = -sign;
    u[i] = sign * p_.torque_max[i];
  }
  return u;
}

PmpState Shooter::node_state(const Eigen::VectorXd& x, int m) const {
  if (m == 0) return pack(R0_, p_.omega_initial, 0.5 * R0_ * so3::hat(x.segment<3>(0)), x.segment<3>(3), 0.0);
  const int b = node_base(m);
  const Mat3 R = ref_[m - 1] * so3::exp(x.segment<3>(b));
  return pack(R, x.segment<3>(b + 3), 0.5 * R * so3::hat(x.segment<3>(b + 6)), x.segment<3>(b + 9), 0.0);
}

void Shooter::set_node(Eigen::VectorXd& x, int m, const Mat3& R, const Vec3& omega, const Vec3& p_theta,
                       const Vec3& p_omega) const {
  const int b = node_base(m);
  x.segment<3>(b) = so3::log(ref_[m - 1].transpose() * R);
  x.segment<3>(b + 3) = omega;
  x.segment<3>(b + 6) = p_theta;
  x.segment<3>(b + 9) = p_omega;
}

bool Shooter::seed_nodes_forward(Eigen::VectorXd& x, const std::vector<Vec3>& switching_space) {
  std::vector<Knot> knots;
  if (!sorted_knots(x, knots)) return false;
  for (int m = 1; m < nodes(); ++m) {
    SegmentEnd end;
    integrate_segment(x, m - 1, knots, 2, end, nullptr);
    const PmpView v = unpack(end.y);
    ref_[static_cast<std::size_t>(m - 1)] = v.R;
    set_node(
        x, m, v.R, v.omega, attitude_costate_body(v.R, v.P),
        switching_space.empty()
            ? v.p_omega
            : Vec3(p_.inertia_body * (v.R.transpose() * switching_space[static_cast<std::size_t>(m - 1)])));
  }
  return true;
}

bool Shooter::sorted_knots(const Eigen::VectorXd& x, std::vector<Knot>& knots) const {
  const double T = final_time(x);
  if (!(T > 0.0)) return false;
  knots.clear();
  for (std::size_t k = 0; k < knot_count(); ++k) {
    const double t = switch_time(x, k);
    if (!(t > 0.0 && t < T)) return false;
    knots.emplace_back(t, k);
  }
  std::sort(knots.begin(), knots.end());
  return true;
}

void Shooter::integrate_segment(const Eigen::VectorXd& x, int m, const std::vector<Knot>& knots, int samples,
                                SegmentEnd& end, const SampleFn& observe) const {
  const double t_a = node_time(x, m), t_b = m + 1 == nodes() ? final_time(x) : node_time(x, m + 1);
  PmpState y = node_state(x, m);
  // Reversals: on each arc u = −ū σ/‖σ‖ with σ's sign locked to the side of `side` (σ(0) on the first arc,
  // reversed at each reversal), so that the control is continued smoothly through σ = 0 up to the arc's end
  // and the knot conditions σ(t_k)·side = 0 are smooth in t_k.
  Vec3 side = J_inv_ * x.segment<3>(3);
  std::vector<Knot> inside;
  for (const auto& k : knots) {
    if (k.first < t_a)
      side = -side;
    else if (k.first < t_b)
      inside.push_back(k);
  }
  std::vector<double> cuts{t_a};
  for (const auto& k : inside)
    cuts.push_back(k.first);
  cuts.push_back(t_b);
  end.knot_sigma.clear();
  // Output samples of a norm-bound torque, which turns fast where σ passes near 0 (by π within about
  // ‖σ‖_min/‖σ̇‖): an interval over which the torque turns by more than kMaxSampleTurn, or whose second
  // difference exceeds kMaxSmoothSampleCurvature of ū, is halved, so that the replay's local cubics resolve
  // the turn and its approach (with 64 uniform samples a random slew with ‖σ‖_min 2e-4 of its largest was
  // replayed 2.2e-2 rad off; with second differences up to 1e-4 ū, one whose ‖σ‖_min is 1.1e-3 of its
  // largest, 1.1e-6 rad/s off in rate).
  // The residual's own integration is cut likewise where the torque turns by more than kMaxPieceTurn: over a
  // long piece RKF78's stages can straddle a fast turn and its error estimate miss it (a random slew then
  // converged with H(T) = 0 while H(0) = −2.7e-8, the samples' refined integration showing the gap).
  // The smooth torques of the other objectives (u = −σ/2 or −σ/(2w), clipped to the bound) have their output
  // intervals halved by the second difference alone (kMaxSmoothSampleCurvature; 64 uniform samples replayed
  // random minimum-energy slews of 4.5 and 15 s 1.0e-6 and 1.5e-6 rad off, above the replay's threshold).
  const bool refine = !bang_ && p_.objective == Objective::minimum_time && p_.bound == TorqueBound::norm;
  const bool refine_smooth = !bang_ && p_.objective != Objective::minimum_time && observe;
  SmoothSampleRule smooth_rule;
  const double max_turn = observe ? kMaxSampleTurn : kMaxPieceTurn;
  for (std::size_t a = 0; a + 1 < cuts.size(); ++a) {
    const double t0 = cuts[a], t1 = cuts[a + 1];
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
    auto rhs = [&](const PmpState& yy, PmpState& dy, double) { pmp_rhs(p_, J_inv_, yy, dy, control(yy)); };
    // Integrates y from ta to ts and observes it there; an output interval that does not resolve a
    // norm-bound torque (above) is halved (at most 30 times) and integrated again from ta.
    const std::function<void(double, double, int)> advance = [&](double ta, double ts, int depth) {
      const PmpState y_a = y;
      const Vec3 u_a = control(y);
      auto step = [&](double from, double to) {
        odeint::integrate_adaptive(odeint::make_controlled<odeint::runge_kutta_fehlberg78<PmpState>>(
                                       options_.integration_tolerance, options_.integration_tolerance),
                                   rhs, y, from, to, (to - from) / 4);
      };
      // Output samples: the midpoint too, whose second difference ‖u_a − 2u_m + u_b‖ ≈ h²‖ü‖/4 bounds the
      // replay's cubic error where the turn rate changes over the interval (near the turn, where the angle
      // alone allows intervals as long as their distance to it).
      Vec3 u_m = Vec3::Zero();
      const double mid = 0.5 * (ta + ts);
      const bool by_curvature = (refine && observe) || refine_smooth;
      if (by_curvature) {
        step(ta, mid);
        u_m = control(y);
        step(mid, ts);
      } else {
        step(ta, ts);
      }
      const Vec3 u_b = control(y);
      const bool curved = by_curvature && smooth_rule.curves(u_a, u_m, u_b);
      const bool turned = refine && std::atan2(u_a.cross(u_b).norm(), u_a.dot(u_b)) > max_turn;
      if ((refine || refine_smooth) && depth < kMaxSampleHalvings && (curved || turned)) {
        y = y_a;
        advance(ta, mid, depth + 1);
        advance(mid, ts, depth + 1);
        return;
      }
      if (observe) observe(ts, y, u_b);
    };
    const int n = std::max(2, samples);
    if (observe) observe(t0, y, control(y));
    for (int i = 1; i < n && t1 > t0; ++i)
      advance(t0 + (t1 - t0) * (i - 1) / (n - 1), t0 + (t1 - t0) * i / (n - 1), 0);
    if (observe && !(t1 > t0))
      for (int i = 1; i < n; ++i)
        observe(t1, y, control(y));
    if (a + 1 < inside.size() + 1) {
      const Vec3 sigma = J_inv_ * Eigen::Map<const Vec3>(y.data() + 21);
      const std::size_t k = inside[a].second;
      end.knot_sigma.emplace_back(k,
                                  (bang_ ? sigma[s_.axes[k]] : sigma.dot(side.normalized())) * knot_scale(k));
      side = -side;
    }
    end.u = control(y);
  }
  end.y = y;
}

bool Shooter::segment_ends(const Eigen::VectorXd& x, std::vector<SegmentEnd>& ends) const {
  std::vector<Knot> knots;
  if (!sorted_knots(x, knots)) return false;
  ends.assign(static_cast<std::size_t>(nodes()), SegmentEnd{});
  for (int m = 0; m < nodes(); ++m)
    integrate_segment(x, m, knots, 2, ends[static_cast<std::size_t>(m)], nullptr);
  return true;
}

bool Shooter::assemble(const Eigen::VectorXd& x, const std::vector<SegmentEnd>& ends,
                       Eigen::VectorXd& F) const {
  const PmpView v = unpack(ends.back().y);
  const double T = final_time(x);
  F.resize(size());
  const Mat3 E = Rf_.transpose() * v.R;
  // Free final attitude: p_θ(T) = 0, i.e. p_θ(0) = 0 (R p_θ is constant and continuous at the nodes).
  F.segment<3>(0) = p_.free_final_attitude ? Vec3(x.segment<3>(0)) : Vec3(0.5 * so3::vee(E - E.transpose()));
  F.segment<3>(3) = (v.omega - p_.omega_final) * T;
  if (p_.free_final_time()) F[6] = hamiltonian(p_, J_inv_, v, ends.back().u);
  for (const auto& e : ends)
    for (const auto& [k, value] : e.knot_sigma)
      F[knot_base() + static_cast<int>(k)] = value;
  const double ubar = p_.torque_norm_limit();
  for (int m = 1; m < nodes(); ++m) {
    const PmpView a = unpack(ends[static_cast<std::size_t>(m - 1)].y);
    const int b = node_base(m);
    const Mat3 Rm = ref_[m - 1] * so3::exp(x.segment<3>(b));
    const Mat3 D = Rm.transpose() * a.R;
    F.segment<3>(b) = 0.5 * so3::vee(D - D.transpose());
    F.segment<3>(b + 3) = (a.omega - x.segment<3>(b + 3)) * T;
    F.segment<3>(b + 6) = (attitude_costate_body(a.R, a.P) - x.segment<3>(b + 6)) * omega_scale_;
    F.segment<3>(b + 9) = J_inv_ * (a.p_omega - x.segment<3>(b + 9)) * ubar;
  }
  return F.allFinite();
}

bool Shooter::residual(const Eigen::VectorXd& x, Eigen::VectorXd& F) const {
  std::vector<SegmentEnd> ends;
  return segment_ends(x, ends) && assemble(x, ends, F);
}

bool Shooter::jacobian(const Eigen::VectorXd& x, const std::vector<SegmentEnd>& ends,
                       const Eigen::VectorXd& F, Eigen::SparseMatrix<double>& jac) const {
  const int n = size();
  std::vector<Eigen::Triplet<double>> entries;
  const int first_node = node_base(1);
  for (int j = 0; j < n; ++j) {
    // Central differences with a step of 1e-5 of the unknown or of 1 % of its group's size: truncation
    // error ~1e-10, integration noise (1e-13) / 1e-5 ~ 1e-8, both relative. The groups of a node (m = 0: the
    // initial costates) are δ (rad: size 1), ω (at least s_ω), p_θ and p_ω; p_θ and p_ω T have the same
    // units, and each is at least the other's size, so that a vanishing p_θ (a free final attitude) still
    // gets a step.
    const int node = j >= first_node ? 1 + (j - first_node) / 12 : j < 6 ? 0 : -1;
    // A free final attitude: p_θ ≡ 0 exactly (R p_θ is constant and p_θ(T) = 0), so the p_θ unknowns stay at
    // their value 0 (identity columns; their rows, p_θ(0) and the p_θ defects, are then exactly zero).
    // Left free they add a weakly determined direction (on the tumbling racket a singular value of 1e-10 of
    // the largest, along which the residual's p_θ(0) row stays at 1e-8).
    const bool attitude_costate = node == 0 ? j < 3 : node > 0 && (j - node_base(node)) / 3 == 2;
    if (attitude_costate && p_.free_final_attitude) {
      entries.emplace_back(j, j, 1.0);
      continue;
    }
    double scale = std::abs(x[j]);
    if (node >= 0) {
      const int base = node == 0 ? -6 : node_base(node);  // node 0: p_θ at 0, p_ω at 3
      const int group = (j - base) / 3;                   // 0 δ, 1 ω, 2 p_θ, 3 p_ω
      const double T = std::max(final_time(x), 1e-300);
      const double p_theta = x.segment<3>(base + 6).cwiseAbs().maxCoeff();
      const double p_omega = x.segment<3>(base + 9).cwiseAbs().maxCoeff();
      scale = group == 0   ? 100.0
              : group == 1 ? std::max(x.segment<3>(base + 3).cwiseAbs().maxCoeff(), omega_scale_)
              : group == 2 ? std::max(p_theta, p_omega / T)
                           : std::max(p_omega, p_theta * T);
    }
    const double h = 1e-5 * std::max({std::abs(x[j]), 1e-2 * scale, 1e-12});
    // An interior node's unknowns move its own segment only: re-integrate that one.
    auto evaluate = [&](const Eigen::VectorXd& xp, Eigen::VectorXd& Fp) {
      if (node < 1) return residual(xp, Fp);
      std::vector<Knot> knots;
      if (!sorted_knots(xp, knots)) return false;
      std::vector<SegmentEnd> changed = ends;
      integrate_segment(xp, node, knots, 2, changed[static_cast<std::size_t>(node)], nullptr);
      return assemble(xp, changed, Fp);
    };
    Eigen::VectorXd xp = x, xm = x, Fp, Fm;
    xp[j] += h;
    xm[j] -= h;
    const bool plus = evaluate(xp, Fp), minus = evaluate(xm, Fm);
    Eigen::VectorXd column;
    if (plus && minus)
      column = (Fp - Fm) / (2.0 * h);
    else if (plus)
      column = (Fp - F) / h;
    else if (minus)
      column = (F - Fm) / h;
    else
      return false;
    for (int i = 0; i < n; ++i)
      if (column[i] != 0.0) entries.emplace_back(i, j, column[i]);
  }
  jac.resize(n, n);
  jac.setFromTriplets(entries.begin(), entries.end());
  return true;
}

namespace {

/// The backtracking line search along `step` on the residual's max norm: accepts the first of
/// x + step, x + step/2, … (30 halvings) that decreases it; false when none does.
bool shooting_line_search(const Shooter& shooter, const Eigen::VectorXd& step, Eigen::VectorXd& x,
                          Eigen::VectorXd& F, double& norm) {
  double alpha = 1.0;
  for (int ls = 0; ls < 30 && step.allFinite(); ++ls, alpha *= 0.5) {
    Eigen::VectorXd xn = x + alpha * step, Fn;
    if (shooter.residual(xn, Fn) && Fn.cwiseAbs().maxCoeff() < (1.0 - 1e-4 * alpha) * norm) {
      x = xn;
      F = Fn;
      norm = Fn.cwiseAbs().maxCoeff();
      return true;
    }
  }
  return false;
}

/// How one Newton iteration ended: the iterate moved, the Jacobian could not be formed (a segment not
/// integrable), or no step decreased the residual.
enum class NewtonStep { moved, no_jacobian, stalled };

/// One iteration of newton() (below) from x; x, F and norm become the accepted iterate when it moved.
NewtonStep newton_step(const Shooter& shooter, Eigen::VectorXd& x, Eigen::VectorXd& F, double& norm) {
  std::vector<Shooter::SegmentEnd> ends;
  Eigen::SparseMatrix<double> jac;
  if (!shooter.segment_ends(x, ends) || !shooter.jacobian(x, ends, F, jac)) return NewtonStep::no_jacobian;
  SparseLu lu;
  // A numerically singular Jacobian (SparseLU does not pivot for rank): the least-squares step instead.
  const Eigen::VectorXd step =
      lu.compute(jac) ? lu.solve(-F) : solve_col_piv_qr(Eigen::MatrixXd(jac), Eigen::VectorXd(-F));
  Eigen::VectorXd x_lu = x, F_lu = F;
  double norm_lu = norm;
  const bool lu_ok = shooting_line_search(shooter, step, x_lu, F_lu, norm_lu);
  if (lu_ok && norm_lu < 0.5 * norm) {
    x = x_lu;
    F = F_lu;
    norm = norm_lu;
    return NewtonStep::moved;
  }
  // The Newton step does not halve the residual: try the rank-revealing steps as well, which leave out
  // the directions whose singular values are below 1e-8, 1e-10 or 1e-12 of the largest, and keep the best.
  // Such near-null directions are those of a family of extremals that the boundary conditions pin only
  // through an exponentially small sensitivity (stopping the tumbling racket: the phase of each flip,
  // docs/optimal_control_theory.md section 3); the central-difference Jacobian (relative error ~1e-8)
  // cannot resolve them, and the full step along them is noise that throws the iterate out of the linear
  // range. 1e-8 leaves out what that error cannot resolve; the smaller levels keep the directions that are
  // weakly determined but computed well enough (on the tumbling racket a single level of 1e-12 stalls at
  // a residual of 7e-6 where 1e-8 goes on to 1e-8).
  const ThinSvd svd{Eigen::MatrixXd(jac)};
  Eigen::VectorXd x_svd = x, F_svd = F;
  double norm_svd = lu_ok ? norm_lu : norm;
  bool svd_ok = false;
  for (const double threshold : {1e-8, 1e-10, 1e-12}) {
    Eigen::VectorXd x_t = x, F_t = F;
    double norm_t = norm;
    if (shooting_line_search(shooter, svd.solve(-F, threshold), x_t, F_t, norm_t) && norm_t < norm_svd) {
      x_svd = x_t;
      F_svd = F_t;
      norm_svd = norm_t;
      svd_ok = true;
    }
  }
  if (svd_ok) {
    x = x_svd;
    F = F_svd;
    norm = norm_svd;
    return NewtonStep::moved;
  }
  if (lu_ok) {
    x = x_lu;
    F = F_lu;
    norm = norm_lu;
    return NewtonStep::moved;
  }
  return NewtonStep::stalled;
}

}  // namespace

int newton(const Shooter& shooter, const ShootingOptions& o, Eigen::VectorXd& x, Eigen::VectorXd& F,
           double& norm, bool& stalled) {
  int it = 0;
  stalled = false;
  for (; it < o.max_iterations && norm > o.tolerance; ++it) {
    const NewtonStep step = newton_step(shooter, x, F, norm);
    stalled = step == NewtonStep::stalled;
    if (step != NewtonStep::moved) break;
    if (o.on_newton_iteration) o.on_newton_iteration(norm);
  }
  return it;
}

}  // namespace poinsot::optimal::detail
