// The text report of `poinsot optimize` on a single body (see optimal_run.hpp): the problem and the outcome,
// the direct method, the indirect method with the checks of the minimum principle, and the interpretation.
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "optimal_pointing_output.hpp"
#include "optimal_wheel_output.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/run/optimal_run.hpp"

namespace poinsot::io {

namespace {

/// The report's head: the problem (body, objective, bounds, cones), the status, what failed and what to
/// change, the direct re-simulation and what the files hold.
std::string report_problem_and_outcome(const OptimalRun& r) {
  const auto& p = r.scenario.problem;
  std::ostringstream o;
  o << "poinsot optimize: " << r.scenario.source << "\n";
  if (!r.scenario.title.empty()) o << "  " << r.scenario.title << "\n";
  o << "body: " << r.scenario.body_description << "\n";
  o << "objective: " << optimal::objective_name(p.objective);
  if (p.objective == optimal::Objective::minimum_time_regularised)
    o << " (T + " << format_number(p.energy_weight) << " ∫‖u‖²dt: a smoothed minimum-time problem)";
  o << "; torque bound "
    << (p.bound == optimal::TorqueBound::per_axis ? "per axis " + format_vector(p.torque_max)
                                                  : "norm " + format_number(p.torque_max[0]))
    << " N·m";
  if (p.has_rate_bound()) o << "; rate bound " << format_number(p.rate_max) << " rad/s";
  if (p.wheels) o << " (the wheels' motor torques)";
  for (const auto& c : p.pointing)
    o << fmt::format(
        "\n{}: boresight {} (body) {} {} deg of {} (space)", c.label(), format_vector(c.boresight_body),
        c.kind == optimal::PointingKind::keep_out ? "at least" : "within",
        format_number(c.half_angle * 180.0 / std::numbers::pi, 8), format_vector(c.direction_space));
  o << "\nstatus: " << r.status << "\n";
  if (r.outcome == OptimalOutcome::not_converged) {
    o << "failed: " << r.failed_phase << "\n";
    o << "what to change: " << r.advice << "\n";
  } else if (r.outcome == OptimalOutcome::converged_direct) {
    o << "not verified in: " << r.failed_phase << "\n";
    o << "what to change: " << r.advice << "\n";
  }
  if (r.direct_replayed)
    o << fmt::format(
        "direct re-simulation (DOP853, the collocation's control{}): attitude error {} rad, rate error {} "
        "rad/s, max(δθ, T δω) {} rad against the target {}\n",
        r.direct_replay_refinements > 0
            ? fmt::format(", after {} continued mesh refinements", r.direct_replay_refinements)
            : std::string(),
        format_number(r.direct_replay.attitude_error, 3), format_number(r.direct_replay.rate_error, 3),
        format_number(r.direct_replay.scaled_error(), 3), format_number(r.direct_replay_tolerance));
  if (r.direct_replayed && !p.pointing.empty())
    o << detail::pointing_lines("cones on the direct re-simulation (DOP853, steps ≤ 1/16 interval)", p,
                                r.direct_replay.pointing);
  o << detail::wheel_lines(r);
  if (direct_optimum(r).pointing_widening > 0.0)
    o << fmt::format("  cones widened by {} rad at the collocation points so that they hold between them\n",
                     format_number(direct_optimum(r).pointing_widening, 3));
  if (r.outcome != OptimalOutcome::optimal)
    o << "the files hold: "
      << (solution_source(r) == std::string_view("indirect") ? "the indirect solution"
          : direct_optimum(r).nlp_solved                     ? "the direct solution Ipopt solved"
                                                             : "the direct method's last iterate")
      << "\n";
  return o.str();
}

/// The direct method's lines: mesh refinement, the phase-per-arc re-solve, which gave the direct optimum.
std::string report_direct(const OptimalRun& r) {
  std::ostringstream o;
  o << fmt::format(
      "direct (Hermite–Simpson, Ipopt): {}; {} intervals after {} mesh iterations, mesh error {}, "
      "{} Ipopt iterations{}\n  final time {} s, cost {}\n",
      r.direct.status, r.direct.node_time.empty() ? 0 : r.direct.node_time.size() - 1,
      r.direct.mesh_iterations, format_number(r.direct.max_mesh_error, 3), r.direct.nlp_iterations,
      r.direct.nlp_restarts > 0
          ? fmt::format(
                " ({} restarts with other settings{})", r.direct.nlp_restarts,
                r.direct.nlp_stalled > 0
                    ? fmt::format("; {} mesh(es) solved to {} times Ipopt's tolerance, where it stalled",
                                  r.direct.nlp_stalled, optimal::nlp_stall_tolerance_factor)
                    : std::string())
          : std::string(),
      format_number(r.direct.final_time, 12), format_number(r.direct.cost, 12));
  if (const auto& starts = r.direct.first_mesh_starts; !starts.empty()) {
    std::vector<std::string> turns, costs;
    for (const optimal::FirstMeshStart& s : starts) {
      turns.push_back(fmt::format("{}°", format_number(s.turn * 180.0 / std::numbers::pi, 4)));
      costs.push_back(s.solved ? format_number(s.cost, 10) : std::string("not solved"));
    }
    o << fmt::format(
             "  first mesh from {} starts (the guess's transverse bump turned by {} about the eigenaxis): ",
             starts.size(), fmt::join(turns, ", "))
      << fmt::format("costs {}; refined from the start at {}\n", fmt::join(costs, ", "),
                     turns[r.direct.chosen_start]);
  }
  if (r.optimal && !r.direct.converged)
    o << "  the mesh tolerance was not met; the indirect solution is verified on its own\n";
  if (r.phased_applied) {
    o << fmt::format("direct, one phase per arc ({} intervals per arc, Ipopt): {}; {} Ipopt iterations\n",
                     r.scenario.phased_options.intervals_per_arc, r.phased.status, r.phased.nlp_iterations)
      << fmt::format("  final time {} s, cost {}\n", format_number(r.phased.solution.final_time, 14),
                     format_number(r.phased.solution.cost, 14));
    for (const double t : r.phased.switch_times)
      o << fmt::format("  phase boundary at t = {} s\n", format_number(t, 12));
  } else {
    o << "direct, one phase per arc: " << r.phased_status << "\n";
  }
  o << "direct optimum from: "
    << (direct_optimum_source(r) == std::string_view("phased") ? "the phase-per-arc re-solve"
                                                               : "mesh refinement")
    << "\n";
  return o.str();
}

/// What happens at the indirect solution's event k: a switch of u_i, a reversal of a norm-bound torque, or
/// the entry into or the exit from a boundary arc of the rate bound or a singular arc. Two events of one axis
/// at one time (k − 1 and k) are an exit from a boundary arc and the entry into the next, in that order, or
/// the entry into and the exit from an arc of zero length.
std::string event_name(const optimal::IndirectSolution& s, std::size_t k) {
  const int axis = s.switch_axes[k];
  const double t = s.switch_times[k];
  if (axis < 0) return "reversal of u (σ = 0)";
  const bool second_at_this_time = k > 0 && s.switch_axes[k - 1] == axis && s.switch_times[k - 1] == t;
  const optimal::RateBoundArc *ending = nullptr, *starting = nullptr;
  for (const auto& a : s.rate_bound_arcs)
    if (a.axis == axis) {
      if (a.t_exit == t && a.t_entry < t) ending = &a;
      if (a.t_entry == t) starting = &a;
    }
  const bool exit = ending && !(starting && second_at_this_time);
  if (const optimal::RateBoundArc* a = exit ? ending : starting)
    return fmt::format("{} ω{} = {}r",
                       exit || (a->t_exit == t && second_at_this_time) ? "exit from the boundary arc"
                                                                       : "entry into the boundary arc",
                       axis + 1, a->side > 0 ? "" : "−");
  for (const auto& a : s.singular_arcs)
    if (a.axis == axis && (t == a.t_entry || t == a.t_exit))
      return fmt::format("{} of u{} (σ{} = 0)",
                         t == a.t_entry ? "entry into the singular arc" : "exit from the singular arc",
                         axis + 1, axis + 1);
  return fmt::format("switch of u{}", axis + 1);
}

/// The indirect method's lines: the shooting, its switches and reversals, and the checks of the minimum
/// principle.
std::string report_indirect(const OptimalRun& r) {
  const auto& p = r.scenario.problem;
  std::ostringstream o;
  const int segments = r.scenario.shooting.shooting_nodes;
  o << fmt::format("indirect (minimum principle in (R, ω), {}): {}; {} Newton iterations, residual {}\n",
                   segments > 1 ? fmt::format("multiple shooting over {} segments", segments) : "shooting",
                   r.indirect.status, r.indirect.iterations, format_number(r.indirect.residual, 3));
  if (!r.indirect.time.empty()) {
    o << fmt::format("  final time {} s, cost {}\n", format_number(r.indirect.final_time, 14),
                     format_number(r.indirect.cost, 14));
    for (std::size_t k = 0; k < r.indirect.switch_times.size(); ++k)
      o << fmt::format("  {} at t = {} s\n", event_name(r.indirect, k),
                       format_number(r.indirect.switch_times[k], 12));
    const auto& v = r.verification;
    o << "\nchecks:\n"
      << fmt::format("  Hamiltonian: mean {}, max deviation {}\n", format_number(v.hamiltonian_mean, 3),
                     format_number(v.hamiltonian_deviation, 3))
      << fmt::format("  control minimises H: largest gap {}; switching-sign violations {}\n",
                     format_number(v.control_gap, 3), v.switching_sign_violations)
      << fmt::format("  space attitude costate drift {}; ‖RᵀR − I‖ {}; vee(Λ − Λᵀ) − u {}\n",
                     format_number(v.costate_drift, 3), format_number(v.orthogonality, 3),
                     format_number(v.lambda_torque_error, 3))
      << fmt::format(
             "  DOP853 re-simulation: attitude error {} rad, rate error {} rad/s (amplification {}{})\n",
             format_number(v.resimulated_attitude_error, 3), format_number(v.resimulated_rate_error, 3),
             format_number(v.replay_amplification, 3),
             v.open_loop_replay_checked ? ""
                                        : "; not required: its errors, so amplified, exceed the tolerance")
      << (v.replay_segments > 1
              ? fmt::format("  DOP853 re-simulation split at the {} nodes: largest attitude error {} rad "
                            "(segment {}), rate error {} rad/s\n",
                            v.replay_segments - 1, format_number(v.split_replay_attitude_error, 3),
                            v.split_replay_worst_segment, format_number(v.split_replay_rate_error, 3))
              : std::string())
      << fmt::format("  direct vs indirect cost: {} (relative)\n",
                     format_number(v.direct_indirect_difference, 3))
      << (r.indirect.rate_bound_arcs.empty()
              ? std::string()
              : fmt::format("  rate-bound multipliers: smallest {} of the largest (≥ 0 required)\n",
                            format_number(v.rate_multiplier_min, 3)))
      << (r.indirect.singular_arcs.empty()
              ? std::string()
              : fmt::format(
                    "  singular arcs: Kelley's condition −∂σ̈/∂u at least {} (relative; ≥ 0 required)\n",
                    format_number(v.kelley_condition_min, 3)))
      << (p.pointing.empty()
              ? std::string()
              : detail::pointing_lines("  cones along the indirect solution (none active)", p, v.pointing));
    for (const auto& f : v.failures)
      o << "  FAILED: " << f << "\n";
  }
  return o.str();
}

/// The constraint stress and the comparison with the eigenaxis manoeuvre, when computed.
std::string report_interpretation(const OptimalRun& r) {
  std::ostringstream o;
  if (r.has_interpretation) {
    const auto& m = r.interpretation;
    o << fmt::format(
        "\nconstraint stress ∫σ dv = −RΛRᵀ: peak Tresca {} N·m at t = {} s, peak von Mises {} N·m\n",
        format_number(m.peak_tresca, 6), format_number(m.peak_tresca_time, 6),
        format_number(m.peak_von_mises, 6));
    if (m.eigenaxis_available)
      o << fmt::format("eigenaxis manoeuvre with the same bounds: {} ({} saved by the optimum)\n",
                       format_number(m.eigenaxis_cost, 10), format_number(m.saving, 4));
  }
  return o.str();
}

}  // namespace

std::string optimal_report(const OptimalRun& r) {
  return report_problem_and_outcome(r) + "\n" + report_direct(r) + report_indirect(r) +
         report_interpretation(r);
}

}  // namespace poinsot::io
