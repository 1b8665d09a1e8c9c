#include "poinsot/optimal/direct_collocation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <memory>
#include <numbers>
#include <optional>

#include <fmt/format.h>
#include "collocation_nlp.hpp"
#include "collocation_solution.hpp"
#include "initial_guess.hpp"
#include "poinsot/optimal/direct_replay.hpp"

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "sparse_nlp.hpp"

namespace poinsot::optimal {

namespace {

using detail::CollocationNlp;
using detail::IntervalSample;
using detail::kP;
using detail::sample_interval;
using detail::Vec11;
using detail::Vec4;
using detail::Vec7;

/// The previous solution's interpolants evaluated at the points of `next` (τ is shared: same T).
std::vector<double> interpolate(const CollocationNlp& prev, const std::vector<double>& z,
                                const CollocationNlp& next) {
  std::vector<double> out(next.num_variables(), 0.0);
  int k = 0;
  for (int pt = 0; pt < next.points(); ++pt) {
    const double tau = next.mesh().point_fraction(pt);
    while (k + 1 < prev.intervals() && prev.tau()[k + 1] <= tau)
      ++k;
    const double s = std::clamp((tau - prev.tau()[k]) / (prev.tau()[k + 1] - prev.tau()[k]), 0.0, 1.0);
    const IntervalSample smp = sample_interval(prev, z, k, s);
    Eigen::Map<Vec7>(out.data() + kP * pt) = smp.x;
    Eigen::Map<Vec4>(out.data() + kP * pt + 7) = smp.v;
  }
  if (next.free_time()) out[next.time_index()] = z[prev.time_index()];
  return out;
}

/// Splits every interval whose error exceeds the tolerance (detail::refinement_pieces).
std::vector<double> refine(const std::vector<double>& tau, const std::vector<double>& err, double tol) {
  std::vector<double> out{0.0};
  for (std::size_t k = 0; k + 1 < tau.size(); ++k) {
    const int pieces = detail::refinement_pieces(err[k], tol);
    for (int i = 1; i <= pieces; ++i)
      out.push_back(tau[k] + (tau[k + 1] - tau[k]) * i / pieces);
  }
  out.back() = 1.0;
  return out;
}

}  // namespace

void validate(const CollocationOptions& options) {
  if (options.initial_intervals < 2 || options.max_intervals < options.initial_intervals)
    throw InvalidInput("collocation.initial_intervals: " + std::to_string(options.initial_intervals) +
                       "; expected 2 ≤ initial_intervals ≤ max_intervals (" +
                       std::to_string(options.max_intervals) + ")");
  if (options.max_mesh_iterations < 1)
    throw InvalidInput("collocation.max_mesh_iterations: " + std::to_string(options.max_mesh_iterations) +
                       "; expected at least 1");
  if (options.max_nlp_iterations < 1)
    throw InvalidInput("collocation.max_nlp_iterations: " + std::to_string(options.max_nlp_iterations) +
                       "; expected at least 1");
  if (!(options.mesh_tolerance > 0.0) || !std::isfinite(options.mesh_tolerance))
    throw InvalidInput("collocation.mesh_tolerance: " + format_number(options.mesh_tolerance) +
                       "; expected a finite positive tolerance");
  if (!(options.nlp_tolerance > 0.0) || !std::isfinite(options.nlp_tolerance))
    throw InvalidInput("collocation.nlp_tolerance: " + format_number(options.nlp_tolerance) +
                       "; expected a finite positive tolerance");
  if (options.starts < 1 || options.starts > kMaxStarts)
    throw InvalidInput("collocation.starts: " + std::to_string(options.starts) + "; expected 1 … " +
                       std::to_string(kMaxStarts));
}

namespace {

/// The Ipopt settings of the first attempt on each mesh (solve_direct's restarts, direct_collocation.hpp).
detail::IpoptSettings first_settings(const CollocationOptions& options) {
  detail::IpoptSettings ipopt;
  ipopt.tolerance = options.nlp_tolerance;
  ipopt.acceptable_tolerance = options.nlp_tolerance;
  ipopt.max_iterations = options.max_nlp_iterations;
  ipopt.print_level = options.print_level;
  return ipopt;
}

/// The most iterations of the first Ipopt run on a mesh whose start is an optimum (the previous mesh's or,
/// for a widening, the same mesh's); a run that has not converged by then goes on to the restarts
/// (detail::restart_settings). On the 64 problems of seed 3 of the benchmark's per_axis, spin, rate and
/// keep_out families, such a first run took at most 130 iterations where it converged; two ran to their
/// 1000 iterations without converging (12 s on the second mesh of spin problem 3, 66 s on the fourth of
/// per_axis problem 15, both about a singular arc of order two), and the monotone restart solved them in 22
/// and 127.
constexpr int kFirstIterationsFromAnOptimum = 300;

/// The first Ipopt settings on a mesh of a problem with cones whose start is an optimum (the previous mesh's,
/// interpolated, or that of the same mesh before its cones were widened, continue_widened): kept off its
/// bounds by 1e-9 only (IpoptSettings::warm_start), the barrier started at
/// μ = 1e-6 instead of 0.1, and the bound multipliers at μ/slack
/// (IpoptSettings::bound_multipliers_from_barrier), large on the bounds that the bang-bang control rides and
/// small elsewhere, instead of 1 on every bound. With Ipopt's defaults the barrier pushed the start off the
/// control's bounds and took about thirty iterations to come back on every mesh, and sometimes left for
/// another local optimum; on the benchmark's keep_out problems, refined to the mesh tolerance (the
/// phase-per-arc re-solve does not run with cones), this halves the Ipopt iterations
/// (measurements/optimal_control.md, "keep_out"). A widening moves the optimum by about the widening: the
/// warm start keeps the local optimum the refinement found, which Ipopt's defaults left for another one (on
/// 48 of the benchmark's keep_out problems, 9 ended higher than the warm start's, by up to 46 %, and 3 lower,
/// by up to 3.3 %). Without cones the refinement stops
/// after a few meshes, where the gain is small, and on the sphere's rate- and norm-bounded slews, whose
/// multipliers are not unique, the warm start's multipliers seeded the shooting to another extremal or beyond
/// its tolerance: there the first settings stay Ipopt's. Where it fails, the restarts are those of a first
/// mesh (detail::restart_settings).
detail::IpoptSettings refined_mesh_settings(const CollocationOptions& options) {
  return detail::near_solution_settings(first_settings(options));
}

/// The optima of one refined mesh that the cost-rise guard (detail::allowed_cost_rise) refused, one per Ipopt
/// attempt. Where every attempt was solved and refused and their optima agree to the allowed rise, the rise
/// is the refined mesh's own, not Ipopt leaving: on a coarse mesh a cone is met at the collocation points
/// only, and the finer mesh, which sees more of the path, goes further round it (a keep-out slew rose by
/// 1.9 % from 10 to 50 intervals, at mesh error 1.5e-3, on all three attempts). The lowest is then taken.
class RefusedRises {
 public:
  /// Records `s`, an attempt's solution, and whether the guard alone refused it.
  void record(const detail::NlpSolution& s, bool refused_by_guard) {
    ++attempts_;
    if (!refused_by_guard) return;
    ++refused_;
    highest_ = std::max(highest_, s.objective);
    if (!lowest_ || s.objective < lowest_->objective) lowest_ = s;
  }
  /// The lowest refused optimum when every attempt was refused by the guard and they agree to `rise`
  /// (relative); else nothing.
  std::optional<detail::NlpSolution> agreed(double rise) const {
    if (!lowest_ || refused_ != attempts_ || attempts_ < detail::kIpoptAttempts) return std::nullopt;
    if (!(highest_ <= lowest_->objective * (1.0 + rise))) return std::nullopt;
    return lowest_;
  }

 private:
  int attempts_ = 0;
  int refused_ = 0;
  double highest_ = -std::numeric_limits<double>::infinity();
  std::optional<detail::NlpSolution> lowest_;
};

/// What the path constraints imposed at the collocation points are tightened by so that they hold between
/// them: every cone widened by δ (rad; PointingConstraint::widened), every wheel-momentum bound scaled by
/// 1 − ε.
struct PathMargins {
  double cone = 0.0;      ///< δ (rad)
  double momentum = 0.0;  ///< ε (relative)
};

/// The solves a mesh refinement continues: their counts, which its solution adds to, and whether its start is
/// an optimum Ipopt solved on the same mesh.
struct SolvesBefore {
  int mesh_iterations = 0;
  int nlp_iterations = 0;
  int nlp_restarts = 0;
  int nlp_stalled = 0;
  bool start_is_optimum = false;
};

/// The counts of `previous`, whose optimum is the start of a solve on its own mesh (continue_widened).
SolvesBefore solves_of(const DirectSolution& previous) {
  return {previous.mesh_iterations, previous.nlp_iterations, previous.nlp_restarts, previous.nlp_stalled,
          previous.nlp_solved};
}

/// The mesh refinement from `nlp` and its start `z`, an NLP of the problem tightened by `margins`, which
/// each mesh's solution records (also for CollocationOptions::accept_mesh); the counts of `before` are added
/// to. `first_run`, when given, is Ipopt's run on `nlp` already made (from `z`), which the first mesh takes
/// instead of solving it again.
DirectSolution refine_mesh(const ReorientationProblem& problem, std::unique_ptr<CollocationNlp> nlp,
                           std::vector<double> z, const CollocationOptions& options,
                           const SolvesBefore& before, const PathMargins& margins,
                           std::optional<detail::RestartedSolution> first_run = std::nullopt) {
  std::vector<double> y;
  DirectSolution best, previous;  // previous: the last mesh Ipopt solved
  bool have_previous = false;
  std::string failure;
  int nlp_iterations = before.nlp_iterations, restarts = before.nlp_restarts, stalled = before.nlp_stalled;
  for (int it = 0; it < options.max_mesh_iterations; ++it) {
    const int mesh = before.mesh_iterations + it + 1;
    detail::RestartProgress progress;
    if (options.progress) {
      progress = [&](int attempt, int i, double f, double inf) {
        options.progress(DirectProgress{.mesh_iteration = mesh,
                                        .intervals = nlp->intervals(),
                                        .restart = attempt,
                                        .nlp_iteration = i,
                                        .objective = f,
                                        .infeasibility = inf});
      };
    }
    const auto stays_near_previous = [&](const detail::NlpSolution& s) {
      return !have_previous || s.objective <= previous.cost * (1.0 + detail::allowed_cost_rise(previous));
    };
    // The start is an optimum: the previous mesh's, or (it = 0) that of `before` on the same mesh.
    const bool start_is_optimum = have_previous || (it == 0 && before.start_is_optimum);
    RefusedRises refused;
    detail::IpoptSettings settings = start_is_optimum && !problem.pointing.empty()
                                         ? refined_mesh_settings(options)
                                         : first_settings(options);
    if (start_is_optimum) settings.first_attempt_max_iterations = kFirstIterationsFromAnOptimum;
    const auto accept = [&](const detail::NlpSolution& s) {
      const bool solved = s.solved || s.acceptable, near = stays_near_previous(s);
      refused.record(s, solved && !near);
      return solved && near;
    };
    detail::RestartedSolution run = it == 0 && first_run
                                        ? std::move(*first_run)
                                        : detail::solve_with_restarts(*nlp, z, settings, accept, progress);
    nlp_iterations += run.iterations;
    restarts += run.restarts;
    if (run.stalled) ++stalled;
    if (!run.accepted && have_previous) {
      if (std::optional<detail::NlpSolution> lowest = refused.agreed(detail::allowed_cost_rise(previous))) {
        run.solution = std::move(*lowest);
        run.accepted = true;
      }
    }
    detail::NlpSolution& solution = run.solution;
    if (!run.accepted) {
      failure = (solution.solved || solution.acceptable)
                    ? fmt::format(
                          "Ipopt left the previous mesh's optimum on mesh {} with {} intervals (cost {} "
                          "against {}), also when restarted with {} other settings",
                          mesh, nlp->intervals(), format_number(solution.objective, 8),
                          format_number(previous.cost, 8), run.restarts)
                    : fmt::format(
                          "Ipopt did not converge (status {}: {}) on mesh {} with {} intervals, also "
                          "when restarted with {} other settings",
                          solution.return_code, solution.status, mesh, nlp->intervals(), run.restarts);
      if (have_previous) {  // the previous mesh's solution, which Ipopt solved, is the result
        best = std::move(previous);
        failure += fmt::format("; the solution of mesh {} ({} intervals, mesh error {}) is kept", mesh - 1,
                               best.node_time.size() - 1, format_number(best.max_mesh_error, 3));
      } else {  // the last iterate and, where Ipopt finalised, its multipliers
        if (!solution.y.empty()) {
          z = std::move(solution.x);
          y = std::move(solution.y);
        }
        best = detail::extract_solution(*nlp, z, y);
        best.pointing_widening = margins.cone;
        best.wheel_momentum_margin = margins.momentum;
        best.mesh_iterations = mesh;
      }
      break;
    }
    z = std::move(solution.x);
    y = std::move(solution.y);
    best = detail::extract_solution(*nlp, z, y);
    best.pointing_widening = margins.cone;
    best.wheel_momentum_margin = margins.momentum;
    best.nlp_solved = true;
    best.mesh_iterations = mesh;
    best.nlp_iterations = nlp_iterations;
    best.nlp_restarts = restarts;
    best.nlp_stalled = stalled;
    if (best.max_mesh_error <= options.mesh_tolerance) {
      best.converged = true;
      best.status = "converged";
      return best;
    }
    if (options.accept_mesh) {
      if (const std::optional<std::string> reason = options.accept_mesh(best)) {
        best.status = "refinement stopped at mesh error " + format_number(best.max_mesh_error, 3) +
                      " above " + format_number(options.mesh_tolerance) + " after " + std::to_string(mesh) +
                      " mesh iterations: " + *reason;
        return best;
      }
    }
    std::vector<double> next = refine(nlp->tau(), best.mesh_error, options.mesh_tolerance);
    if (static_cast<int>(next.size()) - 1 > options.max_intervals) {
      failure = "mesh error " + format_number(best.max_mesh_error, 3) + " above " +
                format_number(options.mesh_tolerance) + " with the interval limit " +
                std::to_string(options.max_intervals) + " reached";
      break;
    }
    previous = best;
    have_previous = true;
    auto refined = std::make_unique<CollocationNlp>(problem, std::move(next));
    z = interpolate(*nlp, z, *refined);
    nlp = std::move(refined);
  }
  best.nlp_iterations = nlp_iterations;
  best.nlp_restarts = restarts;
  best.nlp_stalled = stalled;
  best.status = failure.empty() ? "mesh error " + format_number(best.max_mesh_error, 3) + " above " +
                                      format_number(options.mesh_tolerance) + " after " +
                                      std::to_string(best.mesh_iterations) + " mesh iterations"
                                : failure;
  return best;
}

PathMargins margins_of(const DirectSolution& s) {
  return {s.pointing_widening, s.wheel_momentum_margin};
}

/// `problem` with its path constraints tightened by `m`.
ReorientationProblem widened(const ReorientationProblem& problem, const PathMargins& m) {
  ReorientationProblem out = problem;
  for (PointingConstraint& c : out.pointing)
    c = c.widened(m.cone);
  if (out.wheels) out.wheels->momentum_max *= 1.0 - m.momentum;
  return out;
}

/// The continuation of `previous`'s refinement on the problem tightened by `m`.
DirectSolution continue_widened(const ReorientationProblem& problem, const DirectSolution& previous,
                                const CollocationOptions& options, const PathMargins& m);

/// Path constraints between the collocation points: while the dense replay (direct_replay.hpp) of
/// `solution`'s control violates a cone by more than pointing_replay_tolerance, or a wheel-momentum bound
/// by more than wheel_momentum_replay_tolerance (relative), the constraints imposed at the points are
/// tightened by twice the violation more (cones widened, bounds scaled down) and the refinement continues
/// from `solution`; at most four times. The margins stay in the result (DirectSolution::pointing_widening,
/// wheel_momentum_margin); a cone widening is dropped when the result is clear of every cone
/// (active_pointing_constraint finds none), whose solution it then did not shape.
DirectSolution meet_path_constraints_between_points(const ReorientationProblem& problem,
                                                    DirectSolution solution,
                                                    const CollocationOptions& options) {
  constexpr int kMaxWidenings = 4;
  const bool momentum = problem.wheels && problem.wheels->has_momentum_bound();
  if (problem.pointing.empty() && !momentum) return solution;
  for (int k = 0; k < kMaxWidenings && solution.nlp_solved; ++k) {
    const DirectReplay replay = replay_direct(problem, solution);
    const double violation = -replay.pointing.worst();
    const double excess = momentum ? replay.wheel_momentum_excess : 0.0;
    const bool cones_met = !(violation > pointing_replay_tolerance);  // met, or NaN: nothing to widen by
    const bool wheels_met = !(excess > wheel_momentum_replay_tolerance);
    if (cones_met && wheels_met) {
      // A solution clear of every widened cone is a KKT point of the NLP with the cones as given (its rows
      // are inactive either way): the widening did not shape it. It comes from an earlier solution that
      // touched a cone, from which Ipopt moved on to one that does not.
      if (solution.pointing_widening > 0.0 && active_pointing_constraint(problem, solution).empty())
        solution.pointing_widening = 0.0;
      return solution;
    }
    PathMargins m = margins_of(solution);
    if (!cones_met) m.cone += 2.0 * violation;
    if (!wheels_met) m.momentum += 2.0 * excess;
    DirectSolution next = continue_widened(problem, solution, options, m);
    if (!next.nlp_solved) {
      solution.status = fmt::format(
          "{}; the path constraints tightened (cones by {} rad, momentum bounds by {}) to hold between the "
          "collocation points could not be solved ({})",
          solution.status, format_number(m.cone, 3), format_number(m.momentum, 3), next.status);
      return solution;
    }
    solution = std::move(next);
  }
  return solution;
}

/// The first mesh solved from the guesses of CollocationOptions::starts, and the start the refinement
/// continues from.
struct FirstMeshFromStarts {
  std::vector<FirstMeshStart> starts;  ///< empty where the one guess is left to refine_mesh to solve
  int chosen = 0;
  std::vector<double> guess;                     ///< the chosen start's guess
  std::optional<detail::RestartedSolution> run;  ///< its Ipopt run; empty: not solved yet
  SolvesBefore others;                           ///< the Ipopt counts of the starts not chosen
};

/// Solves `nlp`, the first mesh, from each start's guess (initial_guess turned by first_mesh_turn) with the
/// first settings and their restarts. The first start is chosen, and a later one replaces the choice when
/// Ipopt solved it and its optimum is lower than the chosen one's by more than kDistinctFirstMeshOptima
/// (relative), or the chosen one was not solved. With one start, or a guess without an eigenaxis to turn its
/// bump about, the first guess only, unsolved.
FirstMeshFromStarts solve_first_mesh_from_starts(const CollocationNlp& nlp, double T0,
                                                 const CollocationOptions& options) {
  FirstMeshFromStarts out;
  for (int k = 0; k < options.starts; ++k) {
    const double turn = first_mesh_turn(k, options.starts);
    detail::Guess guess = detail::initial_guess(nlp, T0, turn);
    if (k == 0 && (options.starts == 1 || !guess.has_eigenaxis)) {
      out.guess = std::move(guess.z);
      return out;
    }
    detail::RestartProgress progress;
    if (options.progress) {
      progress = [&](int attempt, int i, double f, double inf) {
        options.progress(DirectProgress{.mesh_iteration = 1,
                                        .intervals = nlp.intervals(),
                                        .restart = attempt,
                                        .nlp_iteration = i,
                                        .objective = f,
                                        .infeasibility = inf,
                                        .start = k,
                                        .starts = options.starts});
      };
    }
    detail::RestartedSolution run = detail::solve_with_restarts(
        nlp, guess.z, first_settings(options),
        [](const detail::NlpSolution& s) { return s.solved || s.acceptable; }, progress);
    out.starts.push_back({turn, run.accepted, run.solution.objective, run.iterations});
    const auto lower = [&] {
      const double best = out.run->solution.objective;
      return !out.run->accepted || run.solution.objective < best - kDistinctFirstMeshOptima * std::abs(best);
    };
    const bool chosen = k == 0 || (run.accepted && lower());
    detail::RestartedSolution& dropped = chosen && out.run ? *out.run : run;
    if (k > 0) {
      out.others.nlp_iterations += dropped.iterations;
      out.others.nlp_restarts += dropped.restarts;
      if (dropped.stalled) ++out.others.nlp_stalled;
    }
    if (chosen) {
      out.chosen = k;
      out.run = std::move(run);
      out.guess = std::move(guess.z);
    }
  }
  return out;
}

}  // namespace

DirectSolution solve_direct(const ReorientationProblem& problem, const CollocationOptions& options) {
  validate(problem);
  validate(options);

  std::vector<double> tau(options.initial_intervals + 1);
  for (int k = 0; k <= options.initial_intervals; ++k)
    tau[k] = static_cast<double>(k) / options.initial_intervals;
  auto nlp = std::make_unique<CollocationNlp>(problem, tau);
  // Stopping a tumble (free final attitude, ω_f = 0) in minimum time under a norm bound attains the duration
  // bound ‖L_0‖/ū exactly (‖L̇_space‖ = ‖u‖ ≤ ū, and u = −ū L/‖L‖ meets it for any inertia): the guess, the
  // momentum-dumping motion, is then the continuous optimum itself. Otherwise twice the bound.
  const bool dumping_is_optimal = problem.objective == Objective::minimum_time &&
                                  problem.bound == TorqueBound::norm && problem.free_final_attitude &&
                                  problem.omega_final.isZero(0.0) && !problem.has_rate_bound();
  const double T0 = !problem.free_final_time() ? problem.final_time
                    : dumping_is_optimal       ? minimum_duration_bound(problem)
                                               : 2.0 * minimum_duration_bound(problem);
  FirstMeshFromStarts first = solve_first_mesh_from_starts(*nlp, T0, options);
  DirectSolution solution = meet_path_constraints_between_points(
      problem,
      refine_mesh(problem, std::move(nlp), std::move(first.guess), options, first.others, PathMargins{},
                  std::move(first.run)),
      options);
  solution.first_mesh_starts = std::move(first.starts);
  solution.chosen_start = first.chosen;
  return solution;
}

DirectSolution continue_direct(const ReorientationProblem& problem, const DirectSolution& previous,
                               const CollocationOptions& options) {
  validate(problem);
  validate(options);
  DirectSolution solution = meet_path_constraints_between_points(
      problem, continue_widened(problem, previous, options, margins_of(previous)), options);
  solution.first_mesh_starts = previous.first_mesh_starts;
  solution.chosen_start = previous.chosen_start;
  return solution;
}

namespace {

DirectSolution continue_widened(const ReorientationProblem& original, const DirectSolution& previous,
                                const CollocationOptions& options, const PathMargins& margins) {
  const ReorientationProblem problem = widened(original, margins);
  const std::size_t n = previous.node_time.size();
  if (n < 2 || previous.time.size() != 2 * n - 1 || previous.attitude.size() != previous.time.size() ||
      !(previous.final_time > 0.0))
    throw InvalidInput("continue_direct: the previous solution has no single-phase mesh (" +
                       std::to_string(n) + " nodes, " + std::to_string(previous.time.size()) +
                       " samples); expected a solve_direct result");
  std::vector<double> tau(n);
  for (std::size_t k = 0; k < n; ++k)
    tau[k] = previous.node_time[k] / previous.final_time;
  tau.front() = 0.0;
  tau.back() = 1.0;
  auto nlp = std::make_unique<CollocationNlp>(problem, std::move(tau));
  std::vector<double> z(nlp->num_variables(), 0.0);
  for (std::size_t pt = 0; pt < previous.time.size(); ++pt) {
    const Quat& q = previous.attitude[pt];
    const double v[10] = {q.w(),
                          q.x(),
                          q.y(),
                          q.z(),
                          previous.omega_body[pt][0],
                          previous.omega_body[pt][1],
                          previous.omega_body[pt][2],
                          previous.torque_body[pt][0],
                          previous.torque_body[pt][1],
                          previous.torque_body[pt][2]};
    std::copy(v, v + 10, z.begin() + static_cast<std::ptrdiff_t>(kP * pt));  // ν = 0
  }
  if (nlp->free_time()) z[nlp->time_index()] = previous.final_time;
  return refine_mesh(problem, std::move(nlp), std::move(z), options, solves_of(previous), margins);
}

/// The margin (rad) below which a pointing constraint counts as active on a direct solution, beyond the
/// widening of its cones: an interior-point solution keeps an inactive constraint's margin orders of
/// magnitude above its tolerance (1e-10 on the KKT conditions), while an active one sits at the widened edge
/// to that tolerance.
constexpr double kPointingActiveMargin = 1e-6;

}  // namespace

std::string active_pointing_constraint(const ReorientationProblem& p, const DirectSolution& d) {
  for (const PointingConstraint& c : p.pointing) {
    double smallest = std::numeric_limits<double>::infinity(), when = 0.0;
    for (std::size_t i = 0; i < d.time.size(); ++i)
      if (const double m = c.margin(d.attitude[i]); m < smallest) {
        smallest = m;
        when = d.time[i];
      }
    if (smallest - d.pointing_widening < kPointingActiveMargin)
      return fmt::format("the {} cone is active (the boresight reaches {} rad from its edge at t = {} s)",
                         c.label(), format_number(smallest, 3), format_number(when, 6));
  }
  return {};
}

}  // namespace poinsot::optimal
