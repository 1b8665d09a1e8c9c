// Optimal motions of multibody systems by direct collocation (multibody_direct.hpp).
#include "poinsot/optimal/multibody_direct.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iterator>
#include <numbers>
#include <vector>

#include <fmt/format.h>

#include "hermite_simpson_nlp.hpp"
#include "multibody_controls.hpp"
#include "multibody_final_conditions.hpp"
#include "multibody_minimal_model.hpp"
#include "multibody_rate_rows.hpp"
#include "multibody_rotation_model.hpp"
#include "path_inequality_nlp.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::optimal {
namespace {

using detail::CollocationModel;
using detail::HermiteSimpsonNlp;
using detail::PathInequalityNlp;
using detail::PointFunctions;
using detail::SparseNlp;

/// Solves the transcription of `model` and fills the parts of the optimum common to both formulations.
/// `decode(w, t)` gives the multibody state of the point variables w, `state_vector(state)` the state y of a
/// multibody state (for a warm start), `naive(s)` the naive guess of y at the fraction s = t/T; `rates` the
/// hinge rates of the problem's rate bounds at a point (multibody_rate_rows.hpp), bounded at every point but
/// the first.
template <class Decode, class Encode, class Naive>
MultibodyOptimum solve_model(const MultibodyProblem& problem, const CollocationModel& model,
                             const Eigen::VectorXd& y0, const Eigen::VectorXd& yf,
                             const Eigen::MatrixXd& final_rows, const PointFunctions& rates,
                             const MultibodyOptions& options, Decode decode, Encode state_vector, Naive naive,
                             std::chrono::steady_clock::time_point start) {
  const bool free_time = problem.objective == MultibodyObjective::minimum_time;
  const HermiteSimpsonNlp base(
      model,
      problem.mesh.empty() ? detail::CollocationMesh::uniform(problem.intervals)
                           : detail::CollocationMesh::from_fractions(problem.mesh),
      y0, final_rows, final_rows * yf,
      free_time ? detail::CollocationTime{0.0, {problem.final_time_min}, {problem.final_time_max}}
                : detail::CollocationTime::at(problem.final_time),
      free_time ? detail::CollocationObjective{1.0, problem.energy_weight}
                : detail::CollocationObjective{0.0, 1.0});
  std::vector<double> rate_max;
  for (const RateBound& b : problem.rate_bounds)
    rate_max.push_back(b.rate_max);
  std::vector<double> rate_min(rate_max.size());
  std::transform(rate_max.begin(), rate_max.end(), rate_min.begin(), [](double r) { return -r; });
  rate_min.resize(static_cast<std::size_t>(rates.rows()), 0.0);  // the no-twist rows: = 0
  rate_max.resize(static_cast<std::size_t>(rates.rows()), 0.0);
  const PathInequalityNlp bounded(base, rates, rate_min, rate_max);
  const SparseNlp& nlp = rates.rows() > 0 ? static_cast<const SparseNlp&>(bounded) : base;
  const int nw = model.point_size();
  const int ny = model.state_size();
  std::vector<double> guess(static_cast<std::size_t>(nlp.num_variables()), 0.0);
  // With a free final time the warm start is read at the same fraction τ = t/T of its own final time, which
  // is also the guess of T.
  const double T_guess =
      free_time && options.warm_start != nullptr ? options.warm_start->time.back() : problem.final_time;
  if (free_time) guess[static_cast<std::size_t>(base.time_index())] = T_guess;
  const std::vector<double> guess_times = base.point_times(guess.data());
  for (int p = 0; p < base.points(); ++p) {
    const double s = static_cast<double>(p) / (base.points() - 1);
    Eigen::Map<Eigen::VectorXd> y(guess.data() + nw * p, ny);
    if (options.warm_start == nullptr) {
      y = naive(s);
      continue;
    }
    const MultibodyOptimum& warm = *options.warm_start;
    const double t = guess_times[static_cast<std::size_t>(p)];
    const auto after = std::upper_bound(warm.time.begin(), warm.time.end(), t);
    const std::size_t j =
        std::min(static_cast<std::size_t>(std::max(after - warm.time.begin(), std::ptrdiff_t{1})),
                 warm.time.size() - 1);
    const double f = std::clamp((t - warm.time[j - 1]) / (warm.time[j] - warm.time[j - 1]), 0.0, 1.0);
    y = (1.0 - f) * state_vector(warm.states[j - 1]) + f * state_vector(warm.states[j]);
    const Eigen::VectorXd u = control_at(warm, t);
    for (std::size_t k = 0; k < model.control_indices().size(); ++k)
      guess[static_cast<std::size_t>(nw * p + model.control_indices()[k])] = u(static_cast<Eigen::Index>(k));
  }
  detail::IpoptSettings settings;
  settings.tolerance = options.nlp_tolerance;
  settings.max_iterations = options.max_nlp_iterations;
  settings.print_level = options.print_level;
  settings.mumps_scaling = options.mumps_scaling;
  // Where Ipopt fails, it is restarted from the same guess with other settings (detail::restart_settings).
  detail::RestartProgress progress;
  if (options.progress) {
    progress = [&](int attempt, int iteration, double objective, double infeasibility) {
      options.progress(DirectProgress{.mesh_iteration = 1,
                                      .intervals = problem.intervals,
                                      .restart = attempt,
                                      .nlp_iteration = iteration,
                                      .objective = objective,
                                      .infeasibility = infeasibility});
    };
  }
  const detail::RestartedSolution run = detail::solve_with_restarts(
      nlp, guess, settings, [](const detail::NlpSolution& s) { return s.solved; }, progress);
  const detail::NlpSolution& sol = run.solution;
  MultibodyOptimum out;
  out.nlp_iterations = run.iterations;
  out.nlp_restarts = run.restarts;
  out.converged = sol.solved;
  out.status = sol.solved ? "converged"
                          : fmt::format("not converged: {}, also when restarted with {} other settings",
                                        sol.status, run.restarts);
  out.cost = sol.objective;
  std::vector<double> g(static_cast<std::size_t>(nlp.num_constraints()));
  nlp.constraints(sol.x.data(), g.data());
  std::vector<double> lo, up, glo, gup;
  nlp.bounds(lo, up, glo, gup);
  for (std::size_t r = 0; r < g.size(); ++r)
    out.max_constraint_error = std::max({out.max_constraint_error, glo[r] - g[r], g[r] - gup[r]});
  const std::vector<double> times = base.point_times(sol.x.data());
  for (int p = 0; p < base.points(); ++p) {
    const double* w = sol.x.data() + nw * p;
    out.time.push_back(times[static_cast<std::size_t>(p)]);
    out.states.push_back(decode(w, times[static_cast<std::size_t>(p)]));
    Eigen::VectorXd u(static_cast<Eigen::Index>(model.control_indices().size()));
    for (std::size_t k = 0; k < model.control_indices().size(); ++k)
      u(static_cast<Eigen::Index>(k)) = w[model.control_indices()[k]];
    out.controls.push_back(u);
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

/// Each body's turn from `from` to `to`, log(R₀ᵀR_f) in its initial body frame (rad): the geodesic of SO(3)
/// between its two rotations is R(s) = R₀ exp(s log(R₀ᵀR_f)).
///
/// A half-turn has two geodesics, about n and −n, and the sign of log's axis then follows the round-off of
/// the boundary states. Within 1e-6 rad of π the turn is taken about the axis whose first component above
/// 1e-3 of the norm is positive, so that the guess does not depend on the last bits of the input (the falling
/// cat's halves, each turned by π, then turn in opposite senses about the spine).
std::vector<Vec3> body_turns(const multibody::State& from, const multibody::State& to) {
  constexpr double kHalfTurnTolerance = 1e-6;  // rad
  std::vector<Vec3> turns;
  for (std::size_t i = 0; i < from.bodies.size(); ++i) {
    Vec3 turn = so3::log(from.bodies[i].R_space_body.transpose() * to.bodies[i].R_space_body);
    if (std::numbers::pi - turn.norm() < kHalfTurnTolerance) {
      const auto first =
          std::find_if(turn.begin(), turn.end(), [&](double c) { return std::abs(c) > 1e-3 * turn.norm(); });
      if (*first < 0.0) turn = -turn;
    }
    turns.push_back(turn);
  }
  return turns;
}

/// Whether the straight line between the boundary states' matrices comes near a singular matrix, where the
/// naive guess of the rotation-matrix transcription follows the geodesics instead: some body turns (`turns`,
/// body_turns) by more than 2π/3 (halfway across a turn Q by θ the line passes through R₀ (I + Q)/2, whose
/// singular values are 1 and cos(θ/2), twice). Below it the straight line is kept: it meets every joint row
/// that is linear in (x, R) at every point, which the geodesics with linear positions do not.
bool straight_line_degenerates(const std::vector<Vec3>& turns) {
  return std::any_of(turns.begin(), turns.end(),
                     [](const Vec3& turn) { return turn.norm() > 2.0 * std::numbers::pi / 3.0; });
}

/// The geodesic guess of the rotation-matrix transcription at the fraction s = t/T of the motion: every body
/// turned along its geodesic by s times its turn (`turns`, body_turns), so that every guessed R is a
/// rotation; positions, velocities and body rates interpolated linearly.
multibody::State geodesic_guess(const multibody::State& from, const multibody::State& to,
                                const std::vector<Vec3>& turns, double s) {
  multibody::State out = from;
  for (std::size_t i = 0; i < out.bodies.size(); ++i) {
    const multibody::BodyState& a = from.bodies[i];
    const multibody::BodyState& b = to.bodies[i];
    multibody::BodyState& g = out.bodies[i];
    g.R_space_body = a.R_space_body * so3::exp(s * turns[i]);
    g.x_space = (1.0 - s) * a.x_space + s * b.x_space;
    g.v_space = (1.0 - s) * a.v_space + s * b.v_space;
    g.omega_body = (1.0 - s) * a.omega_body + s * b.omega_body;
  }
  return out;
}

/// Throws InvalidInput unless `warm` is a solution of `problem` on some mesh (multibody_direct.hpp).
void check_warm_start(const MultibodyProblem& problem, const MultibodyOptimum& warm) {
  // With a free final time any T within the bounds will do (the warm start is read at the same τ = t/T).
  const bool free_time = problem.objective == MultibodyObjective::minimum_time;
  const double T = free_time && !warm.time.empty() ? warm.time.back() : problem.final_time;
  const bool spans = warm.time.size() >= 3 && warm.states.size() == warm.time.size() &&
                     warm.controls.size() == warm.time.size() && warm.time.front() == 0.0 &&
                     std::abs(warm.time.back() - T) <= 1e-12 * T &&
                     (!free_time || (T >= problem.final_time_min && T <= problem.final_time_max));
  if (!spans || warm.states.front().bodies.size() != static_cast<std::size_t>(problem.system.body_count()) ||
      warm.controls.front().size() != control_count(problem)) {
    throw InvalidInput(fmt::format(
        "optimal control: warm_start: got {} points ending at t = {:.6g} s; expected an optimum of the same "
        "problem (points spanning [0, {:.6g}] s, {} bodies, {} controls)",
        warm.time.size(), warm.time.empty() ? 0.0 : warm.time.back(), T, problem.system.body_count(),
        control_count(problem)));
  }
}

/// A body that turns by more than π/2 between two neighbouring collocation points is not resolved by the mesh
/// (Hermite–Simpson's cubic cannot follow it), and in R-coordinates it is the sign of a spurious solution:
/// the stabilising term R S (S symmetric) can carry R across a half-turn Q in one interval, since R(Q − I) is
/// of that form. Such a result is reported as not converged, never as an optimum.
void check_resolved_rotations(const MultibodyProblem& problem, MultibodyOptimum& out) {
  if (!out.converged) return;
  for (std::size_t p = 1; p < out.states.size(); ++p) {
    for (std::size_t i = 0; i < out.states[p].bodies.size(); ++i) {
      const Mat3 step =
          out.states[p - 1].bodies[i].R_space_body.transpose() * out.states[p].bodies[i].R_space_body;
      const double angle = std::acos(std::clamp(0.5 * (step.trace() - 1.0), -1.0, 1.0));
      if (angle > 0.5 * std::numbers::pi) {
        out.converged = false;
        out.status = fmt::format(
            "not converged: body '{}' turns by {:.3g} rad between the collocation points at t = {:.4g} s and "
            "{:.4g} s; expected at most π/2 (a mesh that resolves the motion)",
            problem.system.bodies()[i].name, angle, out.time[p - 1], out.time[p]);
        return;
      }
    }
  }
}

/// With bounded stabilising variables (MultibodyOptions::stabilisation_step c > 0), a result that uses more
/// than half of a bound is shaped by the bounds (a mesh too coarse for the motion, or the remains of a
/// spurious jump): reported as not converged. Below it no bound is active, so the result is also a KKT point
/// of the transcription without them.
void check_stabilisation(const MultibodyOptions& options, MultibodyOptimum& out) {
  const double limit = 0.5 * options.stabilisation_step;
  if (!out.converged || options.stabilisation_step <= 0.0 || out.stabilisation_step <= limit) return;
  out.converged = false;
  out.status = fmt::format(
      "not converged: the stabilising variables carry a step of {:.3g}; expected at most {:.3g} (half of "
      "their bound: a mesh that resolves the motion)",
      out.stabilisation_step, limit);
}

}  // namespace

MultibodyOptimum solve_multibody(const MultibodyProblem& problem, const MultibodyOptions& options) {
  validate(problem);
  if (options.warm_start != nullptr) check_warm_start(problem, *options.warm_start);
  constexpr int kScalings[] = {-2, -1, 0, 1, 3, 4, 7, 8, 77};  // Ipopt's mumps_scaling values
  if (std::find(std::begin(kScalings), std::end(kScalings), options.mumps_scaling) == std::end(kScalings)) {
    throw InvalidInput(
        fmt::format("optimal control: mumps_scaling: got {}; expected one of MUMPS' scalings -2, -1, 0, 1, "
                    "3, 4, 7, 8 or 77",
                    options.mumps_scaling));
  }
  const auto start = std::chrono::steady_clock::now();
  if (options.coordinates == MultibodyCoordinates::minimal) {
    const detail::MultibodyMinimalModel model(problem);
    const Eigen::VectorXd y0 = model.state_vector(problem.initial_state);
    const Eigen::VectorXd yf = model.state_vector(problem.final_state);
    // The local coordinates at the target: the identity, but a floating base's quaternion has three.
    const Eigen::MatrixXd F = model.local_coordinates(yf);
    const Eigen::MatrixXd rows = detail::model_final_rows(
        problem, F, F.transpose(), [&](const Eigen::VectorXd& y) { return model.state_of(y.data(), 0.0); },
        [&](const multibody::State& s) { return model.state_vector(s); });
    MultibodyOptimum out = solve_model(
        problem, model, y0, yf, rows, detail::minimal_rate_rows(problem, model), options,
        [&](const double* w, double t) { return model.state_of(w, t); },
        [&](const multibody::State& s) { return model.state_vector(s); },
        [&](double s) -> Eigen::VectorXd { return (1.0 - s) * y0 + s * yf; }, start);
    // No multiplier is a variable here: the reactions and Λ of the continuous equations at each point's
    // state and controls (one KKT solve each, multibody/multipliers.hpp).
    for (std::size_t p = 0; p < out.states.size(); ++p) {
      out.multipliers.push_back(multibody::exact_multipliers(
          detail::system_with_controls(problem, out.controls[p]), out.states[p]));
    }
    check_resolved_rotations(problem, out);
    return out;
  }
  if (!(options.stabilisation_step >= 0.0 && options.stabilisation_step < 0.6)) {
    throw InvalidInput(
        fmt::format("optimal control: stabilisation_step: got {}; expected a number from 0 to 0.6 "
                    "(0: unbounded)",
                    options.stabilisation_step));
  }
  const detail::MultibodyRotationModel model(problem, options.stabilisation_step);
  const Eigen::VectorXd y0 = model.state_vector(problem.initial_state);
  const Eigen::VectorXd yf = model.state_vector(problem.final_state);
  // The tangent space of the constraints at the target: an orthonormal basis N of the null space of the
  // position and velocity rows' Jacobian, β = N δy and δy = Nᵀβ.
  const Eigen::MatrixXd N = detail::null_space(model.invariant_jacobian(problem.final_state)).transpose();
  const Eigen::MatrixXd rows = detail::model_final_rows(
      problem, N, N.transpose(), [&](const Eigen::VectorXd& y) { return model.state_of(y.data(), 0.0); },
      [&](const multibody::State& s) { return model.state_vector(s); });
  const std::vector<Vec3> turns = body_turns(problem.initial_state, problem.final_state);
  const bool geodesic = straight_line_degenerates(turns);
  std::vector<multibody::Multipliers> multipliers;
  double stabilisation = 0.0;
  MultibodyOptimum out = solve_model(
      problem, model, y0, yf, rows, detail::rotation_rate_rows(problem, model), options,
      [&](const double* w, double t) {
        multipliers.push_back(model.multipliers_of(w));
        stabilisation = std::max(stabilisation, model.stabilisation_step(w));
        return model.state_of(w, t);
      },
      [&](const multibody::State& s) { return model.state_vector(s); },
      [&](double s) -> Eigen::VectorXd {
        if (!geodesic) return (1.0 - s) * y0 + s * yf;
        return model.state_vector(geodesic_guess(problem.initial_state, problem.final_state, turns, s));
      },
      start);
  out.multipliers = std::move(multipliers);
  out.stabilisation_step = stabilisation;
  check_stabilisation(options, out);
  check_resolved_rotations(problem, out);
  return out;
}

Eigen::VectorXd control_at(const MultibodyOptimum& optimum, double t) {
  if (optimum.time.size() < 3 || optimum.controls.size() != optimum.time.size()) {
    throw InvalidInput(
        fmt::format("optimal control: control_at: the optimum has {} points and {} controls; "
                    "expected a solution of solve_multibody (at least 3 points, one control each)",
                    optimum.time.size(), optimum.controls.size()));
  }
  // The interval [t_2k, t_2k+2] that holds t (the first or last beyond the ends), on any mesh.
  const int intervals = (static_cast<int>(optimum.time.size()) - 1) / 2;
  int k = 0, last = intervals - 1;  // the largest k ≤ intervals − 1 with t_2k ≤ t (bisection)
  while (k < last) {
    const int mid = (k + last + 1) / 2;
    if (optimum.time[static_cast<std::size_t>(2 * mid)] <= t)
      k = mid;
    else
      last = mid - 1;
  }
  const double t0 = optimum.time[static_cast<std::size_t>(2 * k)];
  const double s = (t - t0) / (optimum.time[static_cast<std::size_t>(2 * k + 2)] - t0);
  const auto u = [&](int p) -> const Eigen::VectorXd& {
    return optimum.controls[static_cast<std::size_t>(p)];
  };
  return 2.0 * (s - 0.5) * (s - 1.0) * u(2 * k) - 4.0 * s * (s - 1.0) * u(2 * k + 1) +
         2.0 * s * (s - 0.5) * u(2 * k + 2);
}

}  // namespace poinsot::optimal
