#include "poinsot/optimal/phased_collocation.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "collocation_nlp.hpp"
#include "collocation_solution.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "sparse_nlp.hpp"
#include "switching_structure.hpp"

namespace poinsot::optimal {

namespace {

using detail::CollocationNlp;
using detail::kP;

void require_minimum_time(const ReorientationProblem& p) {
  if (p.objective != Objective::minimum_time)
    throw InvalidInput("phased collocation: objective " + std::string(objective_name(p.objective)) +
                       "; expected minimum_time (a control with switches)");
}

/// Norm bound: the arcs between the reversals of u, each fixed at ±ū along the body axis its saturated
/// torques (‖u‖ > ū/2) all stay within 1e-4 rad of. Refused otherwise: with u free on an arc, a jump of u
/// between two collocation points is invisible to the transcription and the discrete optimum moves the
/// reversal off the phase boundary (measured: the sphere's reversal off by half an interval).
SwitchingStructure norm_structure(const ReorientationProblem& p, std::vector<double> reversals, double T,
                                  const std::vector<double>& t, const std::vector<Vec3>& u) {
  SwitchingStructure s;
  std::sort(reversals.begin(), reversals.end());
  s.switch_times = reversals;
  const double ubar = p.torque_max[0];
  std::vector<double> knots{0.0};
  knots.insert(knots.end(), reversals.begin(), reversals.end());
  knots.push_back(T);
  for (std::size_t a = 0; a + 1 < knots.size(); ++a) {
    Vec3 sum = Vec3::Zero();
    std::vector<Vec3> saturated;
    for (std::size_t j = 0; j < t.size(); ++j)
      if (t[j] > knots[a] && t[j] < knots[a + 1] && u[j].norm() > 0.5 * ubar) {
        saturated.push_back(u[j].normalized());
        sum += saturated.back();
      }
    int axis = 0;
    sum.cwiseAbs().maxCoeff(&axis);
    const double sign = sum[axis] > 0.0 ? 1.0 : -1.0;
    bool along_axis = !saturated.empty();
    for (const Vec3& e : saturated)
      along_axis = along_axis && sign * e[axis] > std::cos(1e-4);
    if (!along_axis)
      throw InvalidInput("phased collocation: the torque on arc " + std::to_string(a + 1) + " (from " +
                         format_number(knots[a], 6) +
                         " s) does not stay along one body axis; expected a "
                         "norm-bound control of fixed direction on every arc");
    Vec3 fixed = Vec3::Zero();
    fixed[axis] = sign * ubar;
    s.torque_lower.push_back(fixed);
    s.torque_upper.push_back(fixed);
  }
  return s;
}

/// The direct solution's state and torque at time t (linear interpolation between samples; q renormalised).
void sample_guess(const DirectSolution& d, double t, double* zp) {
  const auto it = std::upper_bound(d.time.begin(), d.time.end(), t);
  const std::size_t j1 = std::clamp<std::size_t>(it - d.time.begin(), 1, d.time.size() - 1), j0 = j1 - 1;
  const double dt = d.time[j1] - d.time[j0];
  const double s = dt > 0.0 ? std::clamp((t - d.time[j0]) / dt, 0.0, 1.0) : 0.0;
  Eigen::Vector4d q0(d.attitude[j0].w(), d.attitude[j0].x(), d.attitude[j0].y(), d.attitude[j0].z());
  Eigen::Vector4d q1(d.attitude[j1].w(), d.attitude[j1].x(), d.attitude[j1].y(), d.attitude[j1].z());
  if (q0.dot(q1) < 0.0) q1 = -q1;
  const Eigen::Vector4d q = ((1.0 - s) * q0 + s * q1).normalized();
  const Vec3 w = (1.0 - s) * d.omega_body[j0] + s * d.omega_body[j1];
  const Vec3 u = (1.0 - s) * d.torque_body[j0] + s * d.torque_body[j1];
  for (int i = 0; i < 4; ++i)
    zp[i] = q[i];
  for (int i = 0; i < 3; ++i) {
    zp[4 + i] = w[i];
    zp[7 + i] = u[i];
  }
  zp[10] = 0.0;
}

}  // namespace

SwitchingStructure read_switching_structure(const ReorientationProblem& p, const DirectSolution& d) {
  validate(p);
  require_minimum_time(p);
  if (d.time.size() < 2)
    throw InvalidInput("phased collocation: the direct solution has " + std::to_string(d.time.size()) +
                       " samples; expected a solve_direct result");
  if (p.bound == TorqueBound::norm)
    return norm_structure(p, detail::read_reversals(p, d), d.final_time, d.time, d.torque_body);
  const detail::SwitchGuess g = detail::read_switch_guess(p, d);
  if (!g.singular.empty())
    throw InvalidInput("phased collocation: " + g.singular + "; expected bang arcs only");
  std::vector<std::size_t> order(g.times.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](auto a, auto b) { return g.times[a] < g.times[b]; });
  SwitchingStructure s;
  Vec3 sign = g.initial_sign;
  const auto push_arc = [&] {
    const Vec3 u = sign.cwiseProduct(p.torque_max);
    s.torque_lower.push_back(u);
    s.torque_upper.push_back(u);
  };
  push_arc();
  for (const std::size_t k : order) {
    if (!s.switch_times.empty() && g.times[k] - s.switch_times.back() < 1e-9 * d.final_time)
      throw InvalidInput("phased collocation: switches at " + format_number(s.switch_times.back(), 12) +
                         " s and " + format_number(g.times[k], 12) +
                         " s coincide; expected distinct switch times");
    s.switch_times.push_back(g.times[k]);
    sign[g.axes[k]] = -sign[g.axes[k]];
    push_arc();
  }
  return s;
}

SwitchingStructure read_switching_structure(const ReorientationProblem& p, const IndirectSolution& ind) {
  validate(p);
  require_minimum_time(p);
  if (!ind.converged)
    throw InvalidInput("phased collocation: the indirect solution is '" + ind.status +
                       "'; expected a converged one");
  if (p.bound == TorqueBound::norm)
    return norm_structure(p, ind.switch_times, ind.final_time, ind.time, ind.torque_body);
  SwitchingStructure s;
  s.switch_times = ind.switch_times;
  for (const ControlArc& arc : ind.arcs) {
    s.torque_lower.push_back(arc.torque_body);
    s.torque_upper.push_back(arc.torque_body);
  }
  return s;
}

PhasedSolution solve_direct_phased(const ReorientationProblem& p, const DirectSolution& guess,
                                   const SwitchingStructure& st, const PhasedOptions& o) {
  validate(p);
  require_minimum_time(p);
  if (guess.time.size() < 2 || !(guess.final_time > 0.0))
    throw InvalidInput("phased collocation: the guess has " + std::to_string(guess.time.size()) +
                       " samples; expected a solve_direct result");
  const std::size_t arcs = st.switch_times.size() + 1;
  if (st.torque_lower.size() != arcs || st.torque_upper.size() != arcs)
    throw InvalidInput("phased collocation: structure.torque_lower/upper have " +
                       std::to_string(st.torque_lower.size()) + "/" + std::to_string(st.torque_upper.size()) +
                       " arcs; expected " + std::to_string(arcs) + " (one more than the switch times)");
  for (std::size_t k = 0; k < st.switch_times.size(); ++k) {
    const double prev = k == 0 ? 0.0 : st.switch_times[k - 1];
    if (!(st.switch_times[k] > prev && st.switch_times[k] < guess.final_time))
      throw InvalidInput("phased collocation: structure.switch_times[" + std::to_string(k) + "] = " +
                         format_number(st.switch_times[k]) + " s; expected strictly ascending times in (0, " +
                         format_number(guess.final_time) + ") s");
  }
  if (o.intervals_per_arc < 1)
    throw InvalidInput("phased collocation: intervals_per_arc = " + std::to_string(o.intervals_per_arc) +
                       "; expected at least 1");
  if (o.max_nlp_iterations < 1)
    throw InvalidInput("phased collocation: max_nlp_iterations = " + std::to_string(o.max_nlp_iterations) +
                       "; expected at least 1");
  if (!(o.nlp_tolerance > 0.0) || !std::isfinite(o.nlp_tolerance))
    throw InvalidInput("phased collocation: nlp_tolerance = " + format_number(o.nlp_tolerance) +
                       "; expected a finite positive tolerance");

  detail::CollocationPhases phases;
  std::vector<double> tau;
  for (std::size_t a = 0; a < arcs; ++a) {
    phases.intervals.push_back(o.intervals_per_arc);
    phases.torque_lower.push_back(st.torque_lower[a]);
    phases.torque_upper.push_back(st.torque_upper[a]);
    for (int k = 0; k <= o.intervals_per_arc; ++k)
      tau.push_back(static_cast<double>(k) / o.intervals_per_arc);
  }
  const CollocationNlp nlp(p, std::move(tau), phases);

  std::vector<double> z(nlp.num_variables(), 0.0);
  for (std::size_t a = 0; a < arcs; ++a) {
    const double t0 = a == 0 ? 0.0 : st.switch_times[a - 1];
    const double t1 = a + 1 == arcs ? guess.final_time : st.switch_times[a];
    z[nlp.duration_index(static_cast<int>(a))] = t1 - t0;
  }
  const std::vector<double> t = nlp.point_times(z.data());
  std::vector<double> lower, upper, g_lower, g_upper;
  nlp.bounds(lower, upper, g_lower, g_upper);
  for (int pt = 0; pt < nlp.points(); ++pt) {
    sample_guess(guess, t[pt], z.data() + kP * pt);
    for (int c = 0; c < kP; ++c) {  // start inside the bounds (fixed torques, given boundary values, ν)
      double& v = z[kP * pt + c];
      v = std::clamp(v, lower[kP * pt + c], upper[kP * pt + c]);
    }
  }

  detail::IpoptSettings ipopt;
  ipopt.tolerance = o.nlp_tolerance;
  ipopt.acceptable_tolerance = o.nlp_tolerance;
  ipopt.max_iterations = o.max_nlp_iterations;
  ipopt.print_level = o.print_level;
  ipopt.exact_bounds = true;
  detail::NlpSolution nlp_solution = detail::solve_with_ipopt(nlp, z, ipopt);
  std::vector<double> y;
  if (!nlp_solution.y.empty()) {
    z = std::move(nlp_solution.x);
    y = std::move(nlp_solution.y);
  }

  PhasedSolution out;
  out.nlp_iterations = nlp_solution.iterations;
  out.converged = nlp_solution.solved || nlp_solution.acceptable;
  out.status = out.converged ? "converged"
                             : "not converged: Ipopt status " + std::to_string(nlp_solution.return_code) +
                                   " (" + nlp_solution.status + ")";
  out.solution = detail::extract_solution(nlp, z, y);
  out.solution.converged = out.converged;
  out.solution.nlp_solved = out.converged;
  out.solution.status = out.status;
  out.solution.mesh_iterations = 1;
  out.solution.nlp_iterations = nlp_solution.iterations;
  double start = 0.0;
  for (std::size_t a = 0; a + 1 < arcs; ++a) {
    start += z[nlp.duration_index(static_cast<int>(a))];
    out.switch_times.push_back(start);
  }
  return out;
}

}  // namespace poinsot::optimal
