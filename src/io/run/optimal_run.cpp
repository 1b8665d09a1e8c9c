#include "poinsot/io/run/optimal_run.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "optimal_pointing_output.hpp"
#include "optimal_wheel_output.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/run/summary.hpp"

namespace poinsot::io {

namespace {

// "t,v1x,v1y,v1z,...,extra...\n" (std::string::append: GCC 12 reports a false -Wrestrict on "," + string).
std::string csv_row(double t, std::initializer_list<Vec3> vs, std::initializer_list<double> extra = {}) {
  std::string s = format_number(t);
  for (const auto& v : vs)
    for (int i = 0; i < 3; ++i)
      s.append(",").append(format_number(v[i]));
  for (double x : extra)
    s.append(",").append(format_number(x));
  return s.append("\n");
}

// "t,qw,qx,qy,qz,ω,u,L\n"
std::string trajectory_row(double t, const Quat& q, const Vec3& w, const Vec3& u, const Vec3& L) {
  std::string s = format_number(t);
  for (double c : {q.w(), q.x(), q.y(), q.z()})
    s.append(",").append(format_number(c));
  return s.append(csv_row(t, {w, u, L}).substr(format_number(t).size()));
}

nlohmann::ordered_json ordered_array(const Vec3& v) {
  return {v[0], v[1], v[2]};
}

}  // namespace

namespace {

bool phased_is_optimum(const OptimalRun& r) {
  return r.phased_applied && r.phased.converged && !r.direct_refined_for_replay;
}

bool indirect_is_solution(const OptimalRun& r) {
  return r.outcome != OptimalOutcome::converged_direct && r.indirect.converged && !r.indirect.time.empty();
}

}  // namespace

const optimal::DirectSolution& direct_optimum(const OptimalRun& r) {
  return phased_is_optimum(r) ? r.phased.solution : r.direct;
}

const char* direct_optimum_source(const OptimalRun& r) {
  return phased_is_optimum(r) ? "phased" : "mesh_refinement";
}

const char* solution_source(const OptimalRun& r) {
  return indirect_is_solution(r) ? "indirect" : "direct";
}

const char* outcome_name(OptimalOutcome outcome) {
  switch (outcome) {
    case OptimalOutcome::optimal:
      return "optimal";
    case OptimalOutcome::converged_direct:
      return "converged_direct";
    case OptimalOutcome::not_converged:
      break;
  }
  return "not_converged";
}

int outcome_exit_code(OptimalOutcome outcome) {
  switch (outcome) {
    case OptimalOutcome::optimal:
      return 0;
    case OptimalOutcome::converged_direct:
      return 3;
    case OptimalOutcome::not_converged:
      break;
  }
  return 1;
}

namespace {

/// The phase-per-arc re-solve where it applies: minimum time (not the regularised problem, whose control is
/// smooth), a converged direct solution, and a switching structure that read_switching_structure accepts
/// (bang arcs per axis, or norm-bound arcs along one body axis); otherwise the reason in phased_status.
void run_phased(OptimalRun& r) {
  const auto& p = r.scenario.problem;
  if (!r.scenario.phased) {
    r.phased_status = "off";
    return;
  }
  if (p.objective != optimal::Objective::minimum_time) {
    r.phased_status = "not applicable: the objective is " +
                      std::string(optimal::objective_name(p.objective)) +
                      " (the re-solve takes bang arcs of a minimum-time control)";
    return;
  }
  if (!r.direct.nlp_solved) {
    r.phased_status = "not applicable: Ipopt did not solve the direct method's last mesh";
    return;
  }
  if (p.wheels) {
    r.phased_status =
        "not applicable: reaction wheels (the indirect method that the re-solve prepares "
        "does not handle them)";
    return;
  }
  if (!p.pointing.empty()) {
    // Its arcs are fixed by the mesh solution's switches, and nothing keeps a cone that this solution
    // grazes from becoming active on them: Ipopt can then spend thousands of iterations on the re-solve.
    r.phased_status =
        "not applicable: pointing constraints (the re-solve takes bang arcs only, without the "
        "cones' junctions)";
    return;
  }
  try {
    const optimal::SwitchingStructure structure = optimal::read_switching_structure(p, r.direct);
    r.phased = optimal::solve_direct_phased(p, r.direct, structure, r.scenario.phased_options);
  } catch (const InvalidInput& e) {
    r.phased_status = fmt::format("not applicable: {}", e.what());
    return;
  }
  r.phased_applied = true;
  r.phased_status = r.phased.status;
}

}  // namespace

namespace {

/// Whether the shooting refused the problem's structure (solve_indirect's "not applied: …"), as opposed to
/// trying it and failing.
bool shooting_refused(const optimal::IndirectSolution& s) {
  return s.status.starts_with("not applied");
}

/// `status` without a leading "not applied: " or "not converged: " (it follows "not verified: ").
std::string reason_of(const std::string& status) {
  for (const std::string_view prefix : {"not applied: ", "not converged: "})
    if (status.starts_with(prefix)) return status.substr(prefix.size());
  return status;
}

/// The replay of the direct optimum, and the continuations of its mesh refinement at tolerances ten times
/// smaller while the target is out of reach and within reach of the refinements left (each divides the
/// replay's error by about ten: the mesh error, times the motion's amplification) and each still helps.
void replay_direct_optimum(OptimalRun& r, const std::function<void(const OptimalProgress&)>& progress) {
  constexpr int kMaxRefinements = 3;
  const auto& p = r.scenario.problem;
  if (!direct_optimum(r).nlp_solved) return;
  if (progress) progress({"replay", {}});
  r.direct_replayed = true;
  r.direct_replay = optimal::replay_direct(p, direct_optimum(r));
  optimal::CollocationOptions options = r.scenario.collocation;
  if (progress) options.progress = [&](const optimal::DirectProgress& d) { progress({"direct", d}); };
  for (int k = 0; k < kMaxRefinements; ++k) {
    const double error = r.direct_replay.scaled_error();
    if (!(error > r.direct_replay_tolerance)) return;  // met, or NaN: DOP853 gave up
    if (error > r.direct_replay_tolerance * std::pow(10.0, kMaxRefinements - k)) return;  // out of reach
    options.mesh_tolerance = 0.1 * std::min(options.mesh_tolerance, r.direct.max_mesh_error);
    optimal::DirectSolution next = optimal::continue_direct(p, r.direct, options);
    ++r.direct_replay_refinements;
    if (!next.nlp_solved) return;
    const optimal::DirectReplay replay = optimal::replay_direct(p, next);
    if (!(replay.scaled_error() < error)) return;
    r.direct = std::move(next);
    r.direct_refined_for_replay = true;
    r.direct_replay = replay;
  }
}

/// Whether `replay`, the re-simulation of a direct solution of r's problem, makes that solution an answer
/// ("converged (direct …)"): it meets the target to r.direct_replay_tolerance, stays out of the keep-out
/// cones (and in the keep-in ones) and within the wheels' momentum bounds.
bool replay_meets_target(const OptimalRun& r, const optimal::DirectReplay& replay) {
  return replay.scaled_error() <= r.direct_replay_tolerance &&
         replay.pointing.worst() >= -optimal::pointing_replay_tolerance &&
         detail::wheel_bounds_held(r.scenario.problem, replay);
}

/// The phase that failed and what to change (OptimalRun::failed_phase, advice).
void explain_failure(OptimalRun& r) {
  const auto& sc = r.scenario;
  const int intervals = sc.collocation.initial_intervals;
  if (!r.direct.nlp_solved && !(r.phased_applied && r.phased.converged)) {
    r.failed_phase = "direct method (Ipopt)";
    r.advice = fmt::format(
        "more initial_intervals (now {}: the first mesh must resolve the motion, e.g. every turn of a spin), "
        "or a problem Ipopt can start from: a final_time or torque bounds that make the target reachable "
        "(the files hold Ipopt's last iterate)",
        intervals);
    return;
  }
  if (!r.indirect.converged) {
    r.failed_phase = "indirect method (shooting)";
    const bool not_applied = shooting_refused(r.indirect);
    if (r.outcome == OptimalOutcome::converged_direct) {
      r.advice = not_applied
                     ? "nothing in the scenario: the shooting method does not handle this structure; the "
                       "direct solution is the answer, checked by its re-simulation"
                     : fmt::format(
                           "more shooting_nodes (now {}: a long or unstable motion needs "
                           "segments, e.g. 8 … 64) may let the shooting converge",
                           sc.shooting.shooting_nodes);
      return;
    }
    const std::string replay =
        r.direct_replayed
            ? fmt::format("; the direct solution's re-simulation misses the target by {} rad (target {})",
                          format_number(r.direct_replay.scaled_error(), 3),
                          format_number(r.direct_replay_tolerance))
            : std::string();
    if (not_applied)
      r.advice = "the shooting method does not handle this structure" + replay +
                 ": a smaller mesh_tolerance (now " + format_number(sc.collocation.mesh_tolerance) +
                 ") or more max_mesh_iterations (now " + std::to_string(sc.collocation.max_mesh_iterations) +
                 ") refine the direct solution until it reaches the target";
    else
      r.advice = fmt::format(
          "more shooting_nodes (now {}: a long or unstable motion needs segments, e.g. 8 … 64), or more "
          "initial_intervals (now {}) and a smaller mesh_tolerance (now {}) for a better start from the "
          "direct "
          "method{}",
          sc.shooting.shooting_nodes, intervals, format_number(sc.collocation.mesh_tolerance), replay);
    return;
  }
  r.failed_phase = "verification";
  if (r.verification.control_gap_where_order_two && r.outcome == OptimalOutcome::converged_direct) {
    r.advice =
        "nothing in the scenario: the optimum chatters into a singular arc of order two, which the shooting "
        "method cannot represent; the direct solution is the answer, checked by its re-simulation";
    return;
  }
  r.advice = fmt::format(
      "the shooting converged but a check failed: a smaller mesh_tolerance (now {}) or more shooting_nodes "
      "(now {}) may lead it to the optimum; a failing re-simulation of an unstable motion needs more "
      "shooting_nodes",
      format_number(sc.collocation.mesh_tolerance), sc.shooting.shooting_nodes);
}

}  // namespace

/// The mesh error (relative) from which run_optimal hands each mesh's direct solution to the shooting and
/// stops refining once the optimum verifies from it. The mesh then only seeds the shooting (its switching
/// structure and costates); the answer is the indirect solution, checked on its own and against the
/// phase-per-arc re-solve, which does not depend on the mesh either. Refining on to the default tolerance
/// 1e-7 added three to five meshes of a few intervals each at the switches (the error of a discontinuous
/// control shrinks as O(h) there; with a rate bound, at the junctions of its boundary arcs), and Ipopt leaves
/// its start on each refined mesh and needs about thirty iterations to come back. Handed over from 1e-4, 1e-5
/// or 1e-6, the benchmark's per_axis, spin and nonprincipal problems verify alike, and 1e-4 takes the least
/// CPU (measurements/optimal_control.md, "Speed").
constexpr double kEarlyShootingMeshError = 1e-4;

/// Whether run_optimal stops the refinement once the shooting verifies: with a rate bound, and where the
/// direct optimum that the indirect solution is checked against does not rest on the mesh, that is where the
/// phase-per-arc re-solve runs (minimum time under a per-axis bound, without wheels or cones: run_phased).
/// A smooth control's direct optimum is the mesh's own, and it is refined to the tolerance.
bool stops_refining_once_verified(const OptimalScenario& sc) {
  const optimal::ReorientationProblem& p = sc.problem;
  return p.has_rate_bound() || (sc.phased && p.objective == optimal::Objective::minimum_time &&
                                p.bound == optimal::TorqueBound::per_axis && !p.wheels && p.pointing.empty());
}

OptimalRun run_optimal(const OptimalScenario& sc,
                       const std::function<void(const OptimalProgress&)>& progress) {
  OptimalRun r;
  r.scenario = sc;
  optimal::CollocationOptions collocation = sc.collocation;
  if (progress) collocation.progress = [&](const optimal::DirectProgress& d) { progress({"direct", d}); };
  optimal::ShootingOptions shooting = sc.shooting;
  // Where stops_refining_once_verified, from a mesh error of kEarlyShootingMeshError on, each mesh's solution
  // is handed to the shooting, and the refinement stops at the first mesh from which the optimum verifies.
  // Where the shooting refuses the structure read from two meshes in a row (a singular arc of order two, a
  // singular arc overlapping a boundary arc), the direct solution is the answer, and the refinement stops at
  // the first such mesh whose re-simulation meets the target: what "converged (direct …)" asks of it, without
  // refining to the mesh tolerance (which took 2408 intervals and 160 s of CPU on problem 2 of the
  // benchmark's rate family). So too where the extremals of two meshes in a row miss the minimum of H where a
  // singular arc would be of order two (VerificationReport::control_gap_where_order_two): their switches
  // stand for a chattering that no finer mesh turns into a verified extremal.
  bool verified_early = false;
  int unverifiable_in_a_row = 0;
  // The shooting from the mesh at which a refused or chattering structure stopped the refinement, and that
  // mesh's cost and size: the indirect part of the answer unless a widening of the path constraints solved
  // another mesh after it.
  std::optional<optimal::IndirectSolution> shot_at_stop;
  double stop_cost = 0.0;
  std::size_t stop_nodes = 0;
  if (stops_refining_once_verified(sc))
    collocation.accept_mesh = [&](const optimal::DirectSolution& d) -> std::optional<std::string> {
      if (!(d.max_mesh_error <= kEarlyShootingMeshError) || d.costate_time.size() < 2) return std::nullopt;
      optimal::IndirectSolution s = optimal::solve_indirect(sc.problem, d, shooting);
      const bool refused = shooting_refused(s);
      bool chattering = false;
      if (!refused && s.converged) {
        const optimal::VerificationReport v = optimal::verify(sc.problem, d, s);
        if (v.passed) {
          r.indirect = std::move(s);
          verified_early = true;
          return "the minimum principle verified from this mesh";
        }
        chattering = v.control_gap_where_order_two;
      }
      if (!refused && !chattering) {
        unverifiable_in_a_row = 0;
        return std::nullopt;
      }
      if (++unverifiable_in_a_row < 2 || !replay_meets_target(r, optimal::replay_direct(sc.problem, d)))
        return std::nullopt;
      shot_at_stop = std::move(s);
      stop_cost = d.cost;
      stop_nodes = d.node_time.size();
      return refused
                 ? "the shooting refused the structures of this mesh and the previous one, and this one's "
                   "re-simulation meets the target"
                 : "the extremals of this mesh and the previous one switch where a singular arc is of order "
                   "two (a chattering), and this one's re-simulation meets the target";
    };
  r.direct = optimal::solve_direct(sc.problem, collocation);
  if (progress) progress({"phased", {}});
  run_phased(r);
  if (progress) progress({"indirect", {}});
  int newton_iterations = 0;
  if (progress) {
    shooting.on_newton_iteration = [&](double residual) {
      progress({"indirect", {}, ++newton_iterations, residual});
    };
  }
  const bool shot_this_mesh =
      shot_at_stop && r.direct.cost == stop_cost && r.direct.node_time.size() == stop_nodes;
  if (shot_this_mesh)
    r.indirect = std::move(*shot_at_stop);
  else if (!verified_early && r.direct.costate_time.size() >= 2)
    r.indirect = optimal::solve_indirect(sc.problem, r.direct, shooting);
  if (progress) progress({"verification", {}});
  if (!r.indirect.time.empty()) {
    r.verification = optimal::verify(sc.problem, direct_optimum(r), r.indirect);
    r.interpretation = optimal::interpret(sc.problem, r.indirect);
    r.has_interpretation = true;
  } else {
    r.verification.failures.push_back(r.indirect.status.empty() ? "indirect method not run"
                                                                : r.indirect.status);
    if (!r.direct.nlp_solved)
      r.verification.failures.insert(r.verification.failures.begin(), r.direct.status);
  }
  r.optimal = direct_optimum(r).nlp_solved && r.indirect.converged && r.verification.passed;
  if (r.optimal) {
    r.outcome = OptimalOutcome::optimal;
    r.status = "optimal (verified)";
    return r;
  }
  const std::string reason =
      !r.indirect.converged
          ? reason_of(r.indirect.status.empty() ? "indirect method not run" : r.indirect.status)
          : r.verification.failures.front();
  replay_direct_optimum(r, progress);
  if (r.direct_replayed && replay_meets_target(r, r.direct_replay)) {
    r.outcome = OptimalOutcome::converged_direct;
    r.status = fmt::format("converged (direct; minimum principle not verified: {})", reason);
  } else {
    r.outcome = OptimalOutcome::not_converged;
    r.status = fmt::format("not converged: {}", r.verification.failures.front());
    if (r.direct_replayed && r.direct_replay.pointing.worst() < -optimal::pointing_replay_tolerance)
      r.status = fmt::format("not converged: the direct control's re-simulation enters a cone by {} rad",
                             format_number(-r.direct_replay.pointing.worst(), 3));
    if (r.direct_replayed && !detail::wheel_bounds_held(sc.problem, r.direct_replay))
      r.status = fmt::format(
          "not converged: the direct control's re-simulation exceeds a wheel's momentum bound by {} "
          "(relative)",
          format_number(r.direct_replay.wheel_momentum_excess, 3));
  }
  explain_failure(r);
  return r;
}

std::string optimal_summary_json(const OptimalRun& r) {
  const auto& p = r.scenario.problem;
  nlohmann::ordered_json j;
  j["kind"] = "optimal";
  j["scenario"] = r.scenario.source;
  j["status"] = r.status;
  j["optimal"] = r.optimal;
  j["outcome"] = outcome_name(r.outcome);
  j["solution_from"] = solution_source(r);
  j["failed_phase"] = r.failed_phase;
  j["advice"] = r.advice;
  j["objective"] = std::string(optimal::objective_name(p.objective));
  const Quat& qf = p.attitude_final;
  j["problem"] = {
      {"torque_bound", p.bound == optimal::TorqueBound::per_axis ? "per_axis" : "norm"},
      {"torque_max", p.bound == optimal::TorqueBound::per_axis ? ordered_array(p.torque_max)
                                                               : nlohmann::ordered_json(p.torque_max[0])},
      {"rate_max", p.has_rate_bound() ? nlohmann::ordered_json(p.rate_max) : nlohmann::ordered_json()},
      {"free_final_attitude", p.free_final_attitude},
      {"attitude_final", {qf.w(), qf.x(), qf.y(), qf.z()}},
      {"omega_final", ordered_array(p.omega_final)}};
  j["direct"] = {{"converged", r.direct.converged},
                 {"status", r.direct.status},
                 {"final_time", r.direct.final_time},
                 {"cost", r.direct.cost},
                 {"intervals", r.direct.node_time.empty() ? 0 : r.direct.node_time.size() - 1},
                 {"mesh_error", r.direct.max_mesh_error},
                 {"nlp_iterations", r.direct.nlp_iterations},
                 {"nlp_solved", r.direct.nlp_solved},
                 {"nlp_restarts", r.direct.nlp_restarts},
                 {"nlp_stalled", r.direct.nlp_stalled},
                 {"optimum_from", direct_optimum_source(r)}};
  nlohmann::ordered_json starts = nlohmann::ordered_json::array();
  for (const optimal::FirstMeshStart& s : r.direct.first_mesh_starts)
    starts.push_back({{"turn_deg", s.turn * 180.0 / std::numbers::pi},
                      {"solved", s.solved},
                      {"cost", s.cost},
                      {"nlp_iterations", s.nlp_iterations}});
  j["direct"]["first_mesh_starts"] = std::move(starts);
  j["direct"]["chosen_start"] = r.direct.chosen_start;
  const auto finite_or_null = [](double x) {
    return std::isfinite(x) ? nlohmann::ordered_json(x) : nlohmann::ordered_json();
  };
  j["pointing"] = detail::pointing_json(r);
  j["reaction_wheels"] = detail::wheels_json(r);
  j["direct_replay"] = {{"run", r.direct_replayed},
                        {"attitude_error", finite_or_null(r.direct_replay.attitude_error)},
                        {"rate_error", finite_or_null(r.direct_replay.rate_error)},
                        {"scaled_error", finite_or_null(r.direct_replay.scaled_error())},
                        {"tolerance", r.direct_replay_tolerance},
                        {"refinements", r.direct_replay_refinements}};
  nlohmann::ordered_json phased = {{"enabled", r.scenario.phased},
                                   {"applied", r.phased_applied},
                                   {"status", r.phased_status},
                                   {"converged", r.phased_applied && r.phased.converged}};
  if (r.phased_applied) {
    phased["intervals_per_arc"] = r.scenario.phased_options.intervals_per_arc;
    phased["final_time"] = r.phased.solution.final_time;
    phased["cost"] = r.phased.solution.cost;
    phased["switch_times"] = r.phased.switch_times;
    phased["nlp_iterations"] = r.phased.nlp_iterations;
  }
  j["phased"] = phased;
  nlohmann::ordered_json ind = {
      {"converged", r.indirect.converged},
      {"status", r.indirect.status},
      {"final_time", r.indirect.final_time},
      {"cost", r.indirect.cost},
      {"residual", r.indirect.residual},
      {"iterations", r.indirect.iterations},
      {"costate_attitude_initial", ordered_array(r.indirect.costate_attitude_initial)},
      {"costate_omega_initial", ordered_array(r.indirect.costate_omega_initial)}};
  ind["switches"] = nlohmann::ordered_json::array();
  for (std::size_t k = 0; k < r.indirect.switch_times.size(); ++k)
    ind["switches"].push_back(
        {{"axis", r.indirect.switch_axes[k] >= 0 ? nlohmann::ordered_json(r.indirect.switch_axes[k] + 1)
                                                 : nlohmann::ordered_json()},
         {"t", r.indirect.switch_times[k]}});
  ind["rate_bound_arcs"] = nlohmann::ordered_json::array();
  for (const auto& a : r.indirect.rate_bound_arcs)
    ind["rate_bound_arcs"].push_back(
        {{"axis", a.axis + 1}, {"side", a.side}, {"t_entry", a.t_entry}, {"t_exit", a.t_exit}});
  ind["singular_arcs"] = nlohmann::ordered_json::array();
  for (const auto& a : r.indirect.singular_arcs)
    ind["singular_arcs"].push_back({{"axis", a.axis + 1}, {"t_entry", a.t_entry}, {"t_exit", a.t_exit}});
  j["indirect"] = ind;
  const auto& v = r.verification;
  j["checks"] = {{"passed", v.passed},
                 {"failures", v.failures},
                 {"hamiltonian_mean", v.hamiltonian_mean},
                 {"hamiltonian_deviation", v.hamiltonian_deviation},
                 {"control_gap", v.control_gap},
                 {"control_gap_time", v.control_gap_time},
                 {"control_gap_axis", v.control_gap_axis},
                 {"control_gap_where_order_two", v.control_gap_where_order_two},
                 {"switching_sign_violations", v.switching_sign_violations},
                 {"costate_drift", v.costate_drift},
                 {"orthogonality", v.orthogonality},
                 {"lambda_torque_error", v.lambda_torque_error},
                 {"resimulated_attitude_error", v.resimulated_attitude_error},
                 {"resimulated_rate_error", v.resimulated_rate_error},
                 {"replay_amplification", v.replay_amplification},
                 {"open_loop_replay_checked", v.open_loop_replay_checked},
                 {"replay_segments", v.replay_segments},
                 {"split_replay_attitude_error", v.split_replay_attitude_error},
                 {"split_replay_rate_error", v.split_replay_rate_error},
                 {"direct_indirect_difference", v.direct_indirect_difference},
                 {"torque_bound_excess", v.torque_bound_excess},
                 {"rate_bound_excess", v.rate_bound_excess},
                 {"rate_multiplier_min", v.rate_multiplier_min},
                 {"kelley_condition_min", v.kelley_condition_min}};
  if (r.has_interpretation) {
    const auto& m = r.interpretation;
    j["interpretation"] = {
        {"peak_tresca", m.peak_tresca},
        {"peak_tresca_time", m.peak_tresca_time},
        {"peak_von_mises", m.peak_von_mises},
        {"eigenaxis_cost",
         m.eigenaxis_available ? nlohmann::ordered_json(m.eigenaxis_cost) : nlohmann::ordered_json()},
        {"saving", m.eigenaxis_available ? nlohmann::ordered_json(m.saving) : nlohmann::ordered_json()}};
  }
  return j.dump(2) + "\n";
}

void write_optimal_files(const OptimalRun& r, const std::string& dir) {
  std::filesystem::create_directories(dir);
  const std::string head = fmt::format("# status: {}\n", r.status);
  const Mat3& J = r.scenario.problem.inertia_body;
  std::string traj = head, control = head, costates = head;
  const auto& cones = r.scenario.problem.pointing;
  const auto& p = r.scenario.problem;
  traj.append("t,qw,qx,qy,qz,wx,wy,wz,")
      .append(detail::control_columns(p))
      .append(",Lx,Ly,Lz")
      .append(detail::wheel_momentum_columns(p));
  for (std::size_t c = 0; c < cones.size(); ++c)
    traj.append(",").append(detail::pointing_column(r.scenario.problem, c));
  traj += "\n";
  // The row's end: each boresight's angle to its cone's axis (rad).
  const auto angles = [&](const Mat3& R) {
    std::string out;
    for (const auto& c : cones)
      out.append(",").append(format_number(c.angle(R)));
    return out;
  };
  control.append("t,").append(detail::control_columns(p)).append("\n");
  costates.append(
      "t,p_theta_x,p_theta_y,p_theta_z,p_omega_x,p_omega_y,p_omega_z,sigma_x,sigma_y,sigma_z,H\n");
  const auto& s = r.indirect;
  if (solution_source(r) == std::string_view("indirect")) {
    for (std::size_t k = 0; k < s.time.size(); ++k) {
      const Quat q(s.attitude[k]);
      traj += trajectory_row(s.time[k], q, s.omega_body[k], s.torque_body[k],
                             s.attitude[k] * (J * s.omega_body[k]));
      traj.insert(traj.size() - 1, angles(s.attitude[k]));
      costates +=
          csv_row(s.time[k], {s.costate_attitude_body[k], s.costate_omega[k], s.switching_function[k]},
                  {s.hamiltonian[k]});
    }
    if (s.bang_bang) {
      for (const auto& a : s.arcs)
        control += csv_row(a.t_begin, {a.torque_body}) + csv_row(a.t_end, {a.torque_body});
    } else {
      for (std::size_t k = 0; k < s.time.size(); ++k)
        control += csv_row(s.time[k], {s.torque_body[k]});
    }
  } else {  // the direct optimum: the best solution found, or the last iterate
    const auto& d = direct_optimum(r);
    for (std::size_t k = 0; k < d.time.size(); ++k) {
      const Quat& q = d.attitude[k];
      // L: the body's angular momentum R J ω, or with wheels the whole spacecraft's R (J_b ω + A h).
      const Vec3 L =
          p.wheels ? optimal::total_momentum_space(J, *p.wheels, q, d.omega_body[k], d.wheel_momentum[k])
                   : Vec3(q.toRotationMatrix() * (J * d.omega_body[k]));
      traj += trajectory_row(d.time[k], q, d.omega_body[k], d.torque_body[k], L);
      traj.insert(traj.size() - 1, detail::wheel_momentum_values(d, k));
      traj.insert(traj.size() - 1, angles(q.toRotationMatrix()));
      control += csv_row(d.time[k], {d.torque_body[k]});
    }
    // σ = ∂H/∂u per unit of the control: J⁻¹ p_ω for body torques, −Aᵀ J_b⁻¹ p_ω for wheel torques.
    const Mat3 sigma_of_p_omega =
        p.wheels ? Mat3(-p.wheels->axes_body.transpose() * p.bus_inertia().inverse()) : Mat3(J.inverse());
    for (std::size_t k = 0; k < d.costate_time.size(); ++k)
      costates +=
          csv_row(d.costate_time[k],
                  {d.costate_attitude_body[k], d.costate_omega[k], sigma_of_p_omega * d.costate_omega[k]},
                  {std::nan("")});
  }
  write_file_atomic(dir + "/trajectory.csv", traj);
  write_file_atomic(dir + "/control.csv", control);
  write_file_atomic(dir + "/costates.csv", costates);
  write_file_atomic(dir + "/summary.json", optimal_summary_json(r));
  write_file_atomic(dir + "/report.txt", optimal_report(r));
}

}  // namespace poinsot::io
