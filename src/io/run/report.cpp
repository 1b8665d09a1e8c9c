// The text report of a run (see report.hpp).
#include "poinsot/io/run/report.hpp"

#include <cmath>
#include <iterator>

#include <fmt/format.h>

#include "poinsot/core/format.hpp"
#include "report_format.hpp"

namespace poinsot::io {
namespace {

using detail::report_number;
using detail::report_vector;

std::string symmetry_note(const std::string& sym) {
  if (sym == "asymmetric")
    return "asymmetric, I1 < I2 < I3: rotation about the intermediate axis is unstable";
  if (sym == "prolate") return "prolate, I1 < I2 = I3 (a symmetric top)";
  if (sym == "oblate") return "oblate, I1 = I2 < I3 (a symmetric top)";
  return "spherical, I1 = I2 = I3";
}

std::string rel_diff(double measured, double theory) {
  if (theory == 0.0) return "";
  return fmt::format("relative difference {:.1e}", std::abs(measured - theory) / std::abs(theory));
}

using Out = std::back_insert_iterator<std::string>;

/// The flips of the intermediate axis beside their closed-form interval.
void format_flips(Out o, const RunSummary& s) {
  const auto& flips = s.result.flip_times;
  fmt::format_to(o, "  flips of the intermediate axis (sign changes of L2, body frame): {}\n", flips.size());
  if (!flips.empty()) {
    std::string list;
    const std::size_t shown = std::min<std::size_t>(flips.size(), 12);
    for (std::size_t i = 0; i < shown; ++i)
      list += (i ? ", " : "") + report_number(flips[i], 6);
    if (shown < flips.size()) list += ", ...";
    fmt::format_to(o, "    at t = {} s\n", list);
  }
  if (flips.size() >= 2) {
    const double mean = (flips.back() - flips.front()) / static_cast<double>(flips.size() - 1);
    fmt::format_to(o, "    interval between flips: measured {} s (mean)", report_number(mean, 10));
    if (s.flip_interval_theory) {
      fmt::format_to(o, ", theory 2K(k)/ω_p = {} s, {}", report_number(*s.flip_interval_theory, 10),
                     rel_diff(mean, *s.flip_interval_theory));
    }
    fmt::format_to(o, "\n");
  } else if (s.flip_interval_theory) {
    fmt::format_to(o, "    theory: interval between flips 2K(k)/ω_p = {} s\n",
                   report_number(*s.flip_interval_theory, 10));
  }
  if (s.period_theory && s.symmetry == "asymmetric") {
    fmt::format_to(o, "    period of omega: theory 4K(k)/ω_p = {} s\n", report_number(*s.period_theory, 10));
  }
  if (!s.flip_interval_theory && s.symmetry == "asymmetric") {
    if (s.free_body_regime.empty()) {
      fmt::format_to(o, "    (no closed-form interval: a torque acts)\n");
    } else {
      fmt::format_to(o, "    theory: no flips in this regime ({})\n", s.free_body_regime);
    }
  } else if (!s.free_body_regime.empty()) {
    fmt::format_to(o, "    regime of the torque-free motion: {}\n", s.free_body_regime);
  }
}

/// A top's precession and nutation, measured beside the theory's predictions.
void format_top(Out o, const TopEvents& t) {
  const std::string about = t.kind == dynamics::TopKind::heavy ? "the vertical (−g)" : "L_space";
  fmt::format_to(o,
                 "  {}: figure axis {} (body frame), spin omega3 = {} rad/s, I3 = {} kg·m², I1 = {} kg·m²\n",
                 dynamics::to_string(t.kind), report_vector(t.axis_body, 4), report_number(t.spin),
                 report_number(t.moment_axial), report_number(t.moment_transverse));
  fmt::format_to(o, "    precession about {}: measured mean {} rad/s\n", about,
                 t.precession_rate_mean ? report_number(*t.precession_rate_mean) : "n/a");
  const auto beside = [&](const char* name, const std::optional<double>& theory,
                          const std::optional<double>& measured) {
    if (!theory) return;
    fmt::format_to(o, "      {} {} rad/s", name, report_number(*theory));
    if (measured) fmt::format_to(o, " ({})", rel_diff(*measured, *theory));
    fmt::format_to(o, "\n");
  };
  if (t.kind == dynamics::TopKind::heavy) {
    beside("exact heavy top (Goldstein §5.7) Δφ/T_nut =", t.precession_rate_exact, t.precession_rate_mean);
    beside("fast top (the notes) M g l/(I3 omega3) =", t.precession_rate_theory, t.precession_rate_mean);
  } else {
    beside("theory |L|/I1 =", t.precession_rate_theory, t.precession_rate_mean);
  }
  fmt::format_to(o, "    nutation: tilt of the axis from {} between {} and {} rad", about,
                 report_number(t.theta_min), report_number(t.theta_max));
  if (t.theta_min_theory && t.theta_max_theory) {
    fmt::format_to(o, " (exact: {} to {} rad)", report_number(*t.theta_min_theory),
                   report_number(*t.theta_max_theory));
  }
  fmt::format_to(o, "\n");
  if (t.nutation_frequency)
    fmt::format_to(o, "      measured frequency {} rad/s\n", report_number(*t.nutation_frequency));
  beside("exact heavy top 2π/T_nut =", t.nutation_frequency_theory, t.nutation_frequency);
  beside("fast top I3 omega3/I1 =", t.nutation_frequency_fast_top, t.nutation_frequency);
  if (t.sleeping) {
    fmt::format_to(o, "    sleeping-top criterion omega3² > 4 I1 M g l/I3²: {}\n",
                   *t.sleeping ? "holds" : "fails");
  }
}

/// The body, the initial state and the run's settings and outcome.
void format_setup(Out o, const RunSummary& s) {
  const auto& r = s.result;
  fmt::format_to(o, "poinsot run: {} ({})\n", s.scenario, s.source);
  if (!s.title.empty()) fmt::format_to(o, "  {}\n", s.title);
  fmt::format_to(o, "\nbody\n  given as: {}\n", s.body_description);
  fmt::format_to(o, "  principal moments I1, I2, I3 = {} kg·m² about the rotation point\n",
                 report_vector(s.principal_moments, 7));
  fmt::format_to(o, "  symmetry: {}\n", symmetry_note(s.symmetry));
  fmt::format_to(o, "  torque: {}\n", s.torque);

  fmt::format_to(o, "\ninitial state (t = 0)\n");
  fmt::format_to(o, "  omega_body = {} rad/s, |omega| = {} rad/s\n", report_vector(s.initial.omega_body),
                 report_number(s.initial.omega_body.norm()));
  fmt::format_to(o, "  energy E0 = {} J, L_space = {} kg·m²/s, |L| = {} kg·m²/s\n",
                 report_number(s.energy0, 9), report_vector(s.L_space0), report_number(s.L_space0.norm(), 9));

  fmt::format_to(o, "\nrun\n  method {}, t_end = {} s, a sample every {} s ({} samples)\n", s.method,
                 report_number(s.t_end), report_number(s.sample_dt), s.samples);
  if (!s.failure.empty()) fmt::format_to(o, "  FAILED: {}\n", s.failure);
  if (r.interrupted)
    fmt::format_to(o, "  INTERRUPTED at t = {} s (the files are complete up to there)\n",
                   report_number(r.final_state.time));
  fmt::format_to(o, "  final: t = {} s, omega_body = {} rad/s\n", report_number(r.final_state.time),
                 report_vector(r.final_state.omega_body));

  fmt::format_to(o, "\ninvariants: worst relative error over the run\n");
  fmt::format_to(o, "  energy            {:.2e}\n", r.errors.energy_rel_max);
  if (s.torque.rfind("none", 0) == 0)
    fmt::format_to(o, "  L_space           {:.2e}\n", r.errors.L_space_rel_max);
  fmt::format_to(o, "  |L|               {:.2e}\n", r.errors.L_norm_rel_max);
  fmt::format_to(o, "  ‖RᵀR − I‖_F       {:.2e} (absolute)\n", r.errors.orthogonality_max);
}

}  // namespace

std::string format_report(const RunSummary& s) {
  std::string out;
  auto o = std::back_inserter(out);
  const auto& r = s.result;
  format_setup(o, s);
  fmt::format_to(o, "\nevents\n");
  const auto& flips = r.flip_times;
  if (s.symmetry == "asymmetric" || !flips.empty()) format_flips(o, s);
  if (s.top) format_top(o, *s.top);
  if (s.symmetry != "asymmetric" && flips.empty() && !s.top)
    fmt::format_to(o, "  none tracked for this body\n");

  if (!s.lambda_lines.empty()) {
    fmt::format_to(o, "\nLagrange multipliers Λ (Vallée & Dumitriu 2002)\n");
    for (const auto& line : s.lambda_lines)
      fmt::format_to(o, "  {}\n", line);
  }

  fmt::format_to(o, "\ncost\n  {} steps ({} rejected), wall time {:.3f} s", r.steps, r.rejected_steps,
                 r.wall_time_s);
  if (r.wall_time_s > 0.0)
    fmt::format_to(o, ", {:.3g} steps/s", static_cast<double>(r.steps) / r.wall_time_s);
  fmt::format_to(o, "\n");
  if (!s.out_dir.empty()) {
    fmt::format_to(o, "\nfiles\n  {} ({} rows)\n  {}\n", s.trajectory_file, s.samples, s.summary_file);
  }
  return out;
}
}  // namespace poinsot::io
