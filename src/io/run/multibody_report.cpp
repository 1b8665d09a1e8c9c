// The text report and summary.json of a multibody run (see multibody_run.hpp).
#include <algorithm>
#include <cmath>
#include <iterator>
#include <numeric>
#include <vector>

#include <fmt/format.h>

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/run/multibody_run.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/observables.hpp"
#include "report_format.hpp"
#include "run_json.hpp"

namespace poinsot::io {
namespace {

using detail::report_number;
using detail::report_vector;

using multibody::MultibodyMethod;

/// How many rows of the reaction and multiplier tables the report shows; the files hold them all.
constexpr std::size_t kTableRows = 5;

/// An error or a residual: its order of magnitude is what matters.
std::string err(double x) {
  return fmt::format("{:.2e}", x);
}

std::string method_description(const multibody::Scenario& sc) {
  const multibody::MultibodyMethodInfo& info = multibody::multibody_method_info(sc.method);
  return fmt::format("{} (order {}{})", info.label, sc.order, info.symplectic ? "" : ", not symplectic");
}

/// Rows of cells printed with every column padded to its widest cell (two spaces between columns), indented
/// by two spaces; the first row is the header.
void print_table(std::back_insert_iterator<std::string> o,
                 const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width;
  const auto length = [](const std::string& s) {  // characters, not bytes (units such as "N·m")
    return static_cast<std::size_t>(std::count_if(
        s.begin(), s.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
  };
  for (const auto& row : rows) {
    width.resize(std::max(width.size(), row.size()), 0);
    for (std::size_t c = 0; c < row.size(); ++c)
      width[c] = std::max(width[c], length(row[c]));
  }
  for (const auto& row : rows) {
    std::string line = " ";
    for (std::size_t c = 0; c < row.size(); ++c) {
      line += ' ' + row[c];
      if (c + 1 < row.size()) line += std::string(width[c] - length(row[c]) + 1, ' ');
    }
    fmt::format_to(o, "{}\n", line);
  }
}

/// The indices 0..n-1 of the `kTableRows` largest `size(i)`, largest first (all of them, in order, when
/// there are at most kTableRows).
template <class Size>
std::vector<std::size_t> largest(std::size_t n, Size size) {
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), std::size_t{0});
  if (n <= kTableRows) return idx;
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return size(a) > size(b); });
  idx.resize(kTableRows);
  return idx;
}

/// "; the 5 largest of 16 by |F|, all in FILE" (nothing when every row is shown).
std::string selection_note(std::size_t n, const char* by, const std::string& file) {
  if (n <= kTableRows) return "";
  return fmt::format("; the {} largest of {} by {}{}", kTableRows, n, by,
                     file.empty() ? "" : fmt::format(", all in {}", file));
}

}  // namespace

std::string format_multibody_report(const multibody::Scenario& sc, const MultibodyRunSummary& s) {
  const multibody::System& sys = sc.system;
  const multibody::RunSummary& r = s.run;
  const multibody::State& st = r.final_state;
  std::string out;
  auto o = std::back_inserter(out);
  fmt::format_to(o, "multibody run: {}{}\n", s.scenario, sc.source.empty() ? "" : " (" + sc.source + ")");
  if (!sc.title.empty()) fmt::format_to(o, "  {}\n", sc.title);

  fmt::format_to(o, "\nsystem\n  bodies {}, joints {} ({} constraint rows), gravity {} m/s²\n",
                 sys.body_count(), sys.joint_count(), sys.constraint_rows(), report_vector(sys.gravity()));
  fmt::format_to(o, "  solver: {}\n", multibody::kkt_method_description(r.kkt_method));
  // Each body's description, a run of identical ones said once.
  for (std::size_t i = 0; i < sc.body_descriptions.size() && i < sys.bodies().size();) {
    std::size_t j = i + 1;
    while (j < sc.body_descriptions.size() && j < sys.bodies().size() &&
           sc.body_descriptions[j] == sc.body_descriptions[i])
      ++j;
    if (!sc.body_descriptions[i].empty()) {
      const std::string who = j == i + 1 ? fmt::format("body '{}'", sys.bodies()[i].name)
                                         : fmt::format("bodies '{}' to '{}' ({})", sys.bodies()[i].name,
                                                       sys.bodies()[j - 1].name, j - i);
      fmt::format_to(o, "  {}: {}\n", who, sc.body_descriptions[i]);
    }
    i = j;
  }
  fmt::format_to(o, "{}", detail::not_modelled_block(sc.not_modelled, "run"));

  fmt::format_to(o, "\nrun\n  method: {}\n", method_description(sc));
  fmt::format_to(o, "  dt = {} s, duration = {} s, a row every {} steps ({} rows)\n", report_number(sc.dt),
                 report_number(sc.duration), sc.output_every, s.rows);
  if (!r.failure.empty()) fmt::format_to(o, "  FAILED: {}\n", r.failure);
  if (r.interrupted)
    fmt::format_to(o, "  INTERRUPTED at t = {} s (the files are complete up to there)\n",
                   report_number(st.time));
  fmt::format_to(o, "  final: t = {} s after {} steps\n", report_number(st.time), r.steps);

  fmt::format_to(o, "\nconserved quantities and constraints (worst over every step)\n");
  fmt::format_to(o, "  energy             E0 = {} J, final {} J, max |E − E0| = {} J\n",
                 report_number(r.energy_initial), report_number(r.energy_final), err(r.max_energy_error));
  fmt::format_to(o, "  linear momentum    final {} kg·m/s\n",
                 report_vector(multibody::linear_momentum(sys, st)));
  fmt::format_to(o, "  angular momentum   final {} kg·m²/s (about the origin)\n",
                 report_vector(multibody::angular_momentum(sys, st)));
  fmt::format_to(o, "  joint gap          {} m\n", err(r.max_joint_gap));
  fmt::format_to(o, "  joint angle        {} rad\n", err(r.max_joint_angle));
  fmt::format_to(o, "  |RᵀR − I|          {} (largest entry)\n", err(r.max_orthogonality));
  fmt::format_to(o, "  {} per step: mean {}, max {}\n",
                 sc.method == MultibodyMethod::projected_rk4 ? "projection iterations" : "Newton iterations",
                 format_number(r.mean_newton_iterations, 3), r.max_newton_iterations);

  if (s.final_multipliers) {
    const multibody::ExactMultipliers& ex = *s.final_multipliers;
    const std::size_t nj = sys.joints().size();
    if (nj > 0) {
      fmt::format_to(o, "\njoint reactions at t = {} s, on body a at the joint, space frame{}\n",
                     report_number(st.time), selection_note(nj, "|F|", s.reactions_file));
      std::vector<std::vector<std::string>> rows = {
          {"joint", "on body", "|F| (N)", "F (N)", "|couple| (N·m)"}};
      for (std::size_t j : largest(nj, [&](std::size_t k) { return ex.joint_force_space[k].norm(); })) {
        const multibody::Joint& joint = sys.joints()[j];
        rows.push_back({"'" + joint.name + "'",
                        "'" + sys.bodies()[static_cast<std::size_t>(joint.body_a)].name + "'",
                        report_number(ex.joint_force_space[j].norm()), report_vector(ex.joint_force_space[j]),
                        report_number(ex.joint_torque_space[j].norm())});
      }
      print_table(o, rows);
    }
    const std::size_t nb = sys.bodies().size();
    fmt::format_to(o, "\nmultipliers Λ at t = {} s, body frame{}\n", report_number(st.time),
                   selection_note(nb, "‖Λ‖_F", s.multipliers_file));
    std::vector<std::vector<std::string>> rows = {
        {"body", "x (m)", "‖Λ‖_F (J)", "eigenvalues of sym Λ (J), ascending"}};
    for (std::size_t i : largest(nb, [&](std::size_t k) { return ex.Lambda_body[k].norm(); })) {
      rows.push_back({"'" + sys.bodies()[i].name + "'", report_vector(st.bodies[i].x_space),
                      report_number(ex.Lambda_body[i].norm()),
                      report_vector(analysis::sorted_eigenvalues(ex.Lambda_body[i]))});
    }
    print_table(o, rows);
  }

  fmt::format_to(o, "\ncost\n  {} steps, cpu time {} µs per step\n", r.steps,
                 format_number(1e6 * r.cpu_seconds_per_step, 3));
  if (!s.trajectory_file.empty() || !s.out_dir.empty()) {
    fmt::format_to(o, "\nfiles\n");
    for (const std::string* f : {&s.trajectory_file, &s.diagnostics_file, &s.reactions_file,
                                 &s.multipliers_file, &s.report_file, &s.summary_file}) {
      if (!f->empty()) fmt::format_to(o, "  {}\n", *f);
    }
  }
  return out;
}

std::string multibody_summary_json(const multibody::Scenario& sc, const MultibodyRunSummary& s) {
  using detail::json;
  using detail::num;
  using detail::text_or_null;
  const multibody::RunSummary& r = s.run;
  json j;
  j["scenario"] = sc.source;
  j["title"] = sc.title;
  j["kind"] = "multibody";
  j["not_modelled"] = sc.not_modelled;
  j["status"] = detail::run_status(r.failure, r.interrupted);
  j["interrupted"] = r.interrupted;
  j["failure"] = text_or_null(r.failure);
  j["bodies"] = sc.system.body_count();
  j["joints"] = sc.system.joint_count();
  j["steps"] = r.steps;
  j["rows"] = s.rows;
  j["dt"] = sc.dt;
  j["t_end"] = sc.duration;
  j["t_final"] = r.final_state.time;
  j["output_every"] = sc.output_every;
  j["energy_initial"] = num(r.energy_initial);
  j["energy_final"] = num(r.energy_final);
  j["energy_abs_error_max"] = num(r.max_energy_error);
  j["joint_gap_max"] = num(r.max_joint_gap);
  j["joint_angle_error_max"] = num(r.max_joint_angle);
  j["orthogonality_error_max"] = num(r.max_orthogonality);
  j["newton_iterations_mean"] = r.mean_newton_iterations;
  j["newton_iterations_max"] = r.max_newton_iterations;
  j["method"] = multibody::multibody_method_name(sc.method);  // rattle or rk4
  j["order"] = sc.order;
  j["solver"] = multibody::kkt_method_name(r.kkt_method);  // ball_chain, tree or sparse_lu
  j["cpu_seconds_per_step"] = r.cpu_seconds_per_step;
  j["files"] = {
      {"trajectory", text_or_null(s.trajectory_file)}, {"diagnostics", text_or_null(s.diagnostics_file)},
      {"reactions", text_or_null(s.reactions_file)},   {"multipliers", text_or_null(s.multipliers_file)},
      {"report", text_or_null(s.report_file)},         {"summary", text_or_null(s.summary_file)}};
  return j.dump(2) + "\n";
}

}  // namespace poinsot::io
