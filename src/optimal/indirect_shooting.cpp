#include "poinsot/optimal/indirect_shooting.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <fmt/format.h>

#include "arc_shooting.hpp"
#include "multiple_shooting.hpp"
#include "pmp_system.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/core/linear_solvers.hpp"
#include "switching_structure.hpp"

namespace poinsot::optimal {

namespace {

/// Multiple shooting: Newton iterations from the chosen seed before the re-seeding starts, and between
/// re-seedings (on Betts' problem and the other tested ones Newton converges in 1 to 7; on the tumbling
/// racket's example 10 iterations reach 3.4e-7 and seven re-seedings of 3 iterations converge).
constexpr int kNewtonBeforeReseeding = 10;
constexpr int kNewtonPerReseeding = 3;

using detail::PmpState;
using detail::read_reversals;
using detail::read_switch_guess;
using detail::Shooter;
using detail::SwitchGuess;
using detail::with_switch_pairs_at_dips;
using detail::without_short_end_arcs;
using detail::without_vanishing_end_arcs;

/// The direct solution's state at t (linear in ω, normalised linear in q; t clamped to the samples).
void direct_state_at(const DirectSolution& d, double t, Mat3& R, Vec3& omega) {
  const auto it = std::upper_bound(d.time.begin(), d.time.end(), t);
  const std::size_t j = std::clamp<std::size_t>(it - d.time.begin(), 1, d.time.size() - 1);
  const double w = std::clamp((t - d.time[j - 1]) / (d.time[j] - d.time[j - 1]), 0.0, 1.0);
  Quat q0 = d.attitude[j - 1], q1 = d.attitude[j];
  if (q0.dot(q1) < 0.0) q1.coeffs() = -q1.coeffs();
  R = Quat(((1.0 - w) * q0.coeffs() + w * q1.coeffs()).normalized()).toRotationMatrix();
  omega = (1.0 - w) * d.omega_body[j - 1] + w * d.omega_body[j];
}

/// The direct estimate of p_ω at t: linear between interval centres, extrapolated beyond them.
Vec3 direct_costate_omega_at(const DirectSolution& d, double t) {
  const auto& c = d.costate_time;
  const auto it = std::upper_bound(c.begin(), c.end(), t);
  const std::size_t j = std::clamp<std::size_t>(it - c.begin(), 1, c.size() - 1);
  const double w = (t - c[j - 1]) / (c[j] - c[j - 1]);
  return (1.0 - w) * d.costate_omega[j - 1] + w * d.costate_omega[j];
}

/// The interior nodes as fractions of T for M segments: m/M, each moved by at most 7/16 of a segment so that
/// it lies at least a quarter of a segment from every knot of the guess (`knots`, fractions of T), or as far
/// from them as those moves allow. A knot's condition is evaluated on the segment that contains it: at a
/// node it would be evaluated from the previous segment's integrated end on one side and from the node's
/// unknowns on the other, and a norm-bound reversal there (σ ≈ 0 at the node) makes the control's direction
/// at the start of the segment depend on the node's p_ω components across σ's line, where −σ/‖σ‖ is not
/// smooth: Newton stalls at 1e-9 … 1e-7 (docs/optimal_control_theory.md, section 3).
std::vector<double> node_fractions(int M, const std::vector<double>& knots) {
  std::vector<double> out;
  const double segment = 1.0 / M;
  const auto gap = [&](double tau) {
    double g = 1.0;
    for (const double k : knots)
      g = std::min(g, std::abs(tau - k));
    return g;
  };
  for (int m = 1; m < M; ++m) {
    double best = m * segment;
    for (int i = 0; i <= 7 && gap(best) < 0.25 * segment; ++i)
      for (const double sign : {1.0, -1.0}) {
        const double tau = (m + sign * i / 16.0) * segment;
        if (gap(tau) > gap(best)) best = tau;
      }
    out.push_back(best);
  }
  return out;
}

/// The least-squares polynomial of degree ≤ 2 in t/T through the space-frame switching vectors λ_k = R_k σ_k
/// given at `times`, evaluated at `at` (a constant where fewer than 6 samples are given). Along an extremal
/// with a free final attitude λ̇ = R J⁻¹(Jω × σ) (docs/optimal_control_theory.md, section 3): constant where
/// the torque opposes the angular momentum, slowly varying near it; the fit keeps that trend and averages out
/// the scatter of the direct estimates (2.5e-3 of ‖λ‖ on the racket) and what Newton leaves in the node
/// costates along the near-null directions.
std::vector<Vec3> fitted_space_switching(const std::vector<double>& times, const std::vector<Vec3>& lambda,
                                         double T, const std::vector<double>& at) {
  const int degree = times.size() >= 6 ? 2 : 0;
  Eigen::MatrixXd A(static_cast<Eigen::Index>(times.size()), degree + 1);
  Eigen::MatrixXd B(A.rows(), 3);
  for (Eigen::Index k = 0; k < A.rows(); ++k) {
    for (int i = 0; i <= degree; ++i)
      A(k, i) = std::pow(times[static_cast<std::size_t>(k)] / T, i);
    B.row(k) = lambda[static_cast<std::size_t>(k)].transpose();
  }
  const Eigen::MatrixXd C = solve_col_piv_qr(A, B);
  std::vector<Vec3> out;
  for (const double t : at) {
    Eigen::RowVectorXd a(degree + 1);
    for (int i = 0; i <= degree; ++i)
      a[i] = std::pow(t / T, i);
    out.emplace_back((a * C).transpose());
  }
  return out;
}

/// Re-seeds x forward from the exact initial state (Shooter::seed_nodes_forward) with the switching vector
/// carried through the space frame: λ(t) fitted to the samples (`times`, `lambda`), σ(0) = R_0ᵀλ(0) and at
/// node m σ_m = R_mᵀλ(t_m) with R_m the integrated attitude. Returns the residual's
/// max norm (infinity where the seed is not admissible); `shooter` takes the integrated node attitudes as its
/// references.
double reseed_forward(const ReorientationProblem& p, Shooter& shooter, Eigen::VectorXd& x, Eigen::VectorXd& F,
                      const std::vector<double>& times, const std::vector<Vec3>& lambda) {
  const double T = shooter.final_time(x);
  std::vector<double> at{0.0};
  for (int m = 1; m < shooter.nodes(); ++m)
    at.push_back(shooter.node_time(x, m));
  std::vector<Vec3> fit = fitted_space_switching(times, lambda, T, at);
  const Mat3 R0 = p.attitude_initial.toRotationMatrix();
  x.segment<3>(3) = p.inertia_body * (R0.transpose() * fit.front());
  fit.erase(fit.begin());
  if (!shooter.seed_nodes_forward(x, fit) || !shooter.residual(x, F))
    return std::numeric_limits<double>::infinity();
  return F.cwiseAbs().maxCoeff();
}

/// The space-frame switching vectors λ_m = R_m J⁻¹ p_ω,m at the nodes m = 0 … M−1 of x, with their times.
void node_space_switching(const ReorientationProblem& p, const Shooter& shooter, const Eigen::VectorXd& x,
                          std::vector<double>& times, std::vector<Vec3>& lambda) {
  const Mat3 J_inv = p.inertia_body.inverse();
  times.clear();
  lambda.clear();
  for (int m = 0; m < shooter.nodes(); ++m) {
    const detail::PmpView v = detail::unpack(shooter.node_state(x, m));
    times.push_back(shooter.node_time(x, m));
    lambda.push_back(v.R * (J_inv * v.p_omega));
  }
}

/// A shooting problem's set-up besides its unknowns: the nodes' fractions of T, their attitude references
/// and the rate scale the Shooter is built with, and the direct solution's space-frame switching vectors that
/// the forward re-seeding fits (multiple shooting).
struct ShootingSetup {
  ShootingSetup(const ReorientationProblem& problem, const SwitchGuess& guess, bool bang)
      : p(problem), sw(guess), bang_bang(bang) {}
  const ReorientationProblem& p;
  const SwitchGuess& sw;
  bool bang_bang = false;
  std::vector<double> tau;
  std::vector<Mat3> node_R;
  double omega_scale = 1.0;
  std::vector<double> lambda_time;
  std::vector<Vec3> lambda;

  Shooter shooter(const ShootingOptions& o) const {
    return Shooter(p, o, sw, bang_bang, node_R, omega_scale, tau);
  }
};

/// The first shot from the direct solution, into x and F; returns the residual's max norm (infinity when no
/// seed is admissible). Initial costates: R p_θ is constant, so p_θ(t) = R(t)ᵀ · mean_k(R_k p_θ,k); p_ω
/// linear between the direct estimates (extrapolated to t = 0). Multiple shooting: R and ω at the nodes from
/// the direct samples, and the forward seed as well (reseed_forward, from the direct estimates of the
/// space-frame switching vector), whose nodes lie on one trajectory from the initial state; the seed with the
/// smaller residual is kept. The direct nodes carry the direct solution's phase errors, which an unstable
/// tumble turns into near-null directions that Newton cannot correct (docs/measurements/optimal_shooting.md,
/// "The tumbling racket").
double seed_from_direct(const DirectSolution& d, const ShootingOptions& o, ShootingSetup& s,
                        Eigen::VectorXd& x, Eigen::VectorXd& F) {
  const ReorientationProblem& p = s.p;
  Vec3 pi_space = Vec3::Zero();
  for (std::size_t k = 0; k < d.costate_time.size(); ++k) {
    // attitude at the costate time: nearest sample (interval centres coincide with midpoints)
    const auto it = std::lower_bound(d.time.begin(), d.time.end(), d.costate_time[k]);
    const std::size_t j = std::min<std::size_t>(it - d.time.begin(), d.time.size() - 1);
    pi_space += d.attitude[j].toRotationMatrix() * d.costate_attitude_body[k];
  }
  pi_space /= static_cast<double>(d.costate_time.size());
  if (p.free_final_attitude) pi_space.setZero();  // p_θ ≡ 0: R p_θ is constant and p_θ(T) = 0
  const int M = o.shooting_nodes;
  std::vector<double> knot_fraction;
  for (const double t : s.sw.times)
    knot_fraction.push_back(t / d.final_time);
  for (const double t : s.sw.reversals)
    knot_fraction.push_back(t / d.final_time);
  s.tau = node_fractions(M, knot_fraction);
  s.node_R.resize(static_cast<std::size_t>(M - 1));
  std::vector<Vec3> node_omega(s.node_R.size());
  s.omega_scale = std::max(p.omega_initial.norm(), p.omega_final.norm());
  for (int m = 1; m < M; ++m) {
    direct_state_at(d, d.final_time * s.tau[m - 1], s.node_R[m - 1], node_omega[m - 1]);
    s.omega_scale = std::max(s.omega_scale, node_omega[m - 1].norm());
  }
  if (!(s.omega_scale > 0.0)) s.omega_scale = 1.0;
  const Shooter shooter = s.shooter(o);
  x.resize(shooter.size());
  x.segment<3>(0) = p.attitude_initial.toRotationMatrix().transpose() * pi_space;
  x.segment<3>(3) = direct_costate_omega_at(d, 0.0);
  if (p.free_final_time()) x[6] = d.final_time;
  for (std::size_t k = 0; k < s.sw.times.size(); ++k)
    x[shooter.knot_base() + static_cast<int>(k)] = s.sw.times[k];
  for (std::size_t k = 0; k < s.sw.reversals.size(); ++k)
    x[shooter.knot_base() + static_cast<int>(k)] = s.sw.reversals[k];
  for (int m = 1; m < M; ++m) {
    const Mat3& R = s.node_R[m - 1];
    shooter.set_node(x, m, R, node_omega[m - 1], R.transpose() * pi_space,
                     direct_costate_omega_at(d, d.final_time * s.tau[m - 1]));
  }
  double norm = shooter.residual(x, F) ? F.cwiseAbs().maxCoeff() : std::numeric_limits<double>::infinity();
  if (M > 1) {
    const Mat3 J_inv = p.inertia_body.inverse();
    for (std::size_t k = 0; k < d.costate_time.size(); ++k) {
      Mat3 R;
      Vec3 w;
      direct_state_at(d, d.costate_time[k], R, w);
      s.lambda_time.push_back(d.costate_time[k]);
      s.lambda.push_back(R * (J_inv * d.costate_omega[k]));
    }
    Shooter forward = s.shooter(o);
    Eigen::VectorXd x_fw = x, F_fw;
    const double norm_fw = reseed_forward(p, forward, x_fw, F_fw, s.lambda_time, s.lambda);
    if (norm_fw < norm) {
      x = x_fw;
      F = F_fw;
      norm = norm_fw;
      s.node_R = forward.node_references();
    }
  }
  return norm;
}

/// Multiple shooting not converged after the first Newton iterations: re-seed forward from the iterate's own
/// space-frame switching vectors (fitted: the fit averages out the scatter Newton leaves along the near-null
/// directions), Newton again, and so on while iterations are left; x, F, norm and the node references become
/// the best iterate's. Returns the Newton iterations spent; `stalled` says whether the best missed the
/// tolerance.
int reseed_until_converged(const ShootingOptions& o, ShootingSetup& s, Eigen::VectorXd& x, Eigen::VectorXd& F,
                           double& norm, int iterations, bool& stalled) {
  Eigen::VectorXd x_best = x, F_best = F;
  double best = norm;
  std::vector<Mat3> best_R = s.node_R;
  ShootingOptions cycle = o;
  int it = iterations;
  while (best > o.tolerance && it < o.max_iterations) {
    Shooter work = s.shooter(o);
    node_space_switching(s.p, work, x, s.lambda_time, s.lambda);
    Eigen::VectorXd x_r = x, F_r;
    double norm_r = reseed_forward(s.p, work, x_r, F_r, s.lambda_time, s.lambda);
    if (!std::isfinite(norm_r)) break;
    cycle.max_iterations = std::min(kNewtonPerReseeding, o.max_iterations - it);
    it += std::max(1, newton(work, cycle, x_r, F_r, norm_r, stalled));
    x = x_r;
    F = F_r;
    norm = norm_r;
    s.node_R = work.node_references();
    if (norm < best) {
      x_best = x;
      F_best = F;
      best = norm;
      best_R = s.node_R;
    }
  }
  x = x_best;
  F = F_best;
  norm = best;
  s.node_R = best_R;
  stalled = norm > o.tolerance;
  return it - iterations;
}

/// The solution's samples, switching times (ascending, with their axes), nodes and bang-bang arcs from the
/// converged (or best) shot x.
void fill_solution(const ReorientationProblem& p, const SwitchGuess& sw, const Shooter& shooter,
                   const Eigen::VectorXd& x, IndirectSolution& out) {
  out.final_time = shooter.final_time(x);
  out.costate_attitude_initial = x.segment<3>(0);
  out.costate_omega_initial = x.segment<3>(3);
  std::vector<std::size_t> idx(shooter.knot_count());
  for (std::size_t k = 0; k < idx.size(); ++k)
    idx[k] = k;
  std::sort(idx.begin(), idx.end(),
            [&](auto a, auto b) { return shooter.switch_time(x, a) < shooter.switch_time(x, b); });
  for (const std::size_t k : idx) {
    out.switch_times.push_back(shooter.switch_time(x, k));
    out.switch_axes.push_back(out.bang_bang ? sw.axes[k] : -1);
  }
  const Mat3 J_inv = p.inertia_body.inverse();
  shooter.propagate(x, [&](double t, const PmpState& y, const Vec3& u) {
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
  for (int m = 1; m < shooter.nodes(); ++m) {
    const detail::PmpView v = detail::unpack(shooter.node_state(x, m));
    out.node_time.push_back(shooter.node_time(x, m));
    out.node_attitude.push_back(v.R);
    out.node_omega_body.push_back(v.omega);
  }
  if (out.bang_bang) {
    std::vector<double> knots{0.0};
    knots.insert(knots.end(), out.switch_times.begin(), out.switch_times.end());
    knots.push_back(out.final_time);
    for (std::size_t a = 0; a + 1 < knots.size(); ++a)
      out.arcs.push_back({knots[a], knots[a + 1], shooter.arc_torque(x, 0.5 * (knots[a] + knots[a + 1]))});
  }
}

/// Whether the direct solution has a dip (read_arc_structure's `dips`) in a structure the shooting over arcs
/// handles.
bool has_dips(const ReorientationProblem& p, const DirectSolution& d) {
  const detail::ArcStructure s =
      detail::read_arc_structure(p, d, detail::kShortestSingularArc, 0.0, 0.0, true);
  return s.refused.empty() && std::any_of(s.events.begin(), s.events.end(), [](const detail::ArcEvent& e) {
           return e.kind == detail::ArcEvent::Kind::entry && e.arc == detail::ArcEvent::Arc::singular;
         });
}

/// Whether an extremal shot over arcs ends with none (every singular arc amended into bang arcs where its
/// torque left the bound: with_bounded_singular_torque) and its control has σ_i's sign at a sample: a
/// bang-bang extremal that does not minimise H, which the shooting over the switches may still mend.
bool bang_bang_against_sigma(const IndirectSolution& s) {
  return s.singular_arcs.empty() && s.rate_bound_arcs.empty() &&
         detail::switching_sign_violations(s).sum() > 0;
}

/// Whether a bang-bang extremal's control has σ_i's sign at a sample on an axis i that is not principal;
/// `violations` are its switching_sign_violations.
bool grazes_off_principal(const ReorientationProblem& p, const Eigen::Vector3i& violations) {
  const Mat3 J_inv = p.inertia_body.inverse();
  for (int i = 0; i < 3; ++i)
    if (violations[i] > 0 && !detail::principal_axis(J_inv, i)) return true;
  return false;
}

/// Shoots from the direct solution over the switches (bang-bang) or reversals (norm bound) of `sw`: Newton,
/// with re-seeding for multiple shooting and a polish with a tighter integration near the tolerance; the
/// solution's status, samples and arcs from the best iterate.
IndirectSolution shoot_switching_structure(const ReorientationProblem& p, const DirectSolution& d,
                                           const ShootingOptions& o, const SwitchGuess& sw, bool bang_bang) {
  IndirectSolution out;
  out.bang_bang = bang_bang;
  ShootingSetup setup(p, sw, out.bang_bang);
  Eigen::VectorXd x, F;
  double norm = seed_from_direct(d, o, setup, x, F);
  if (!std::isfinite(norm)) {
    out.status = "not converged: the direct solution's costates give no admissible initial shot";
    return out;
  }
  const bool multiple = o.shooting_nodes > 1;
  bool stalled = false;
  ShootingOptions first = o;
  if (multiple) first.max_iterations = std::min(o.max_iterations, kNewtonBeforeReseeding);
  int it = newton(setup.shooter(o), first, x, F, norm, stalled);
  if (multiple && norm > o.tolerance) it += reseed_until_converged(o, setup, x, F, norm, it, stalled);
  // The residual's floor is the integration's error: when Newton stalls just above the tolerance, polish
  // once with a tenfold tighter integration (e.g. the reversal of a sphere's slew: 3.5e-12 at 1e-13).
  ShootingOptions used = o;
  if (norm > o.tolerance && norm < 100.0 * o.tolerance) {
    ShootingOptions tight = o;
    tight.integration_tolerance = o.integration_tolerance / 10.0;
    const Shooter polish = setup.shooter(tight);
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
  out.iterations = it;
  out.residual = norm;
  out.converged = norm <= o.tolerance || floor;
  out.status = floor           ? "converged (residual " + format_number(norm, 3) + " at its round-off floor)"
               : out.converged ? "converged"
                               : "not converged: shooting residual " + format_number(norm, 3) + " after " +
                                     std::to_string(it) + " Newton iterations";
  fill_solution(p, sw, setup.shooter(used), x, out);
  return out;
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
  if (o.shooting_nodes < 1 || o.shooting_nodes > 1000)
    throw InvalidInput("indirect: shooting_nodes = " + std::to_string(o.shooting_nodes) +
                       "; expected an integer in 1 … 1000 (1: single shooting)");
  IndirectSolution out;
  out.bang_bang = p.objective == Objective::minimum_time && p.bound == TorqueBound::per_axis;

  if (p.wheels) {
    out.status =
        "not applied: the actuators are reaction wheels (a gyrostat, whose costate equations the shooting "
        "method does not have)";
    return out;
  }
  // An active pointing constraint: its arcs (or touch points) are not handled by the shooting; a cone the
  // direct solution stays clear of leaves the unconstrained extremal, whose margins the verification checks.
  if (const std::string active = active_pointing_constraint(p, d); !active.empty()) {
    out.status = "not applied: " + active +
                 "; attitude path constraints on their active arcs are not handled by the shooting method";
    return out;
  }

  // An active rate bound: boundary arcs (arc_shooting.hpp), for minimum time with per-axis bounds.
  if (double rate_peak = 0.0; detail::rate_bound_active(p, d, rate_peak)) {
    if (p.objective == Objective::minimum_time && p.bound == TorqueBound::per_axis)
      return detail::solve_over_arcs(p, d, o);
    out.status = "not applied: the rate bound is active (peak |ω_i| = " + format_number(rate_peak, 8) +
                 " rad/s); state-constrained arcs are handled for minimum time with per-axis bounds only";
    return out;
  }
  SwitchGuess sw = out.bang_bang ? read_switch_guess(p, d) : SwitchGuess{};
  if (p.objective == Objective::minimum_time && p.bound == TorqueBound::norm)
    sw.reversals = read_reversals(p, d);
  // A torque inside its bound over a stretch: singular arcs (arc_shooting.hpp).
  if (!sw.singular.empty()) return detail::solve_over_arcs(p, d, o);

  out = shoot_switching_structure(p, d, o, sw, out.bang_bang);
  // The bang-bang structure `trimmed` shot where `out` has not converged; its extremal kept if it converges.
  const auto shoot_instead = [&](const SwitchGuess& trimmed) {
    if (IndirectSolution retry = shoot_switching_structure(p, d, o, trimmed, true); retry.converged)
      out = std::move(retry);
  };
  // A first or last bang arc that the extremal does not have holds Newton at a switch near 0 or T: shot
  // again without it (switching_structure.hpp, kVanishingEndArc). Where Newton stalled with such a switch
  // inside (0, T), without the end arcs that the direct solution shows short (kShortEndArc).
  if (SwitchGuess trimmed; out.bang_bang && !out.converged && without_vanishing_end_arcs(sw, out, trimmed))
    shoot_instead(trimmed);
  if (SwitchGuess trimmed;
      out.bang_bang && !out.converged && without_short_end_arcs(sw, d.final_time, trimmed))
    shoot_instead(trimmed);
  // A u_i that dips towards 0 and returns to the same bound over a few samples (is_torque_dip) where no
  // bang-bang structure converged, or the one that did has σ's sign somewhere: a singular arc shorter than
  // the mesh resolves, where σ_i touches 0 (shot over those arcs: read_arc_structure's `dips`), or else a
  // pulse of the other sign, where σ_i crosses 0 twice in quick succession (a pair of switches at each dip:
  // with_switch_pairs_at_dips). Either extremal is kept only without samples of a bang torque of σ_i's sign:
  // where the optimum holds a singular arc the pair converges too, with σ_i of the wrong sign between its
  // switches, and the arcs of the dips can all be amended away (bang_bang_against_sigma).
  const Eigen::Vector3i against_sigma = out.bang_bang && out.converged
                                            ? detail::switching_sign_violations(out)
                                            : Eigen::Vector3i::Zero().eval();
  const bool unmet = out.bang_bang && (!out.converged || against_sigma.sum() > 0);
  if (unmet && has_dips(p, d)) {
    IndirectSolution over_dips = detail::solve_over_arcs(p, d, o, detail::kShortestSingularArc, true);
    if (over_dips.converged && !bang_bang_against_sigma(over_dips)) return over_dips;
  }
  if (SwitchGuess paired; unmet && with_switch_pairs_at_dips(p, d, sw, paired)) {
    IndirectSolution pulse = shoot_switching_structure(p, d, o, paired, true);
    if (pulse.converged && detail::switching_sign_violations(pulse).sum() == 0) return pulse;
  }
  // A σ_i that grazes 0 along a bang arc, where the extremal's control takes σ_i's sign: the direct control
  // may be inside its bound there over a stretch too short for read_switch_guess to call it a singular
  // arc. Shot over the singular arcs of at least kShortestGrazedSingularArc of T instead, where that
  // converges and the axis is not principal (about a principal axis a singular arc is of order two, and the
  // grazing is the extremal's finite stand-in for the chattering into it: optimal_control_arcs.md).
  if (out.bang_bang && out.converged && grazes_off_principal(p, against_sigma)) {
    IndirectSolution over_arcs = detail::solve_over_arcs(p, d, o, detail::kShortestGrazedSingularArc);
    if (over_arcs.converged && !bang_bang_against_sigma(over_arcs)) return over_arcs;
  }
  return out;
}

}  // namespace poinsot::optimal
