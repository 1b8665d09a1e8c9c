// The scenario driver: integrate, write the trajectory and the report (scenario.hpp).
#include <chrono>
#include <ctime>
#include <fstream>
#include <ostream>

#include <fmt/format.h>
#include <fmt/ostream.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::multibody {
namespace {

void write_row(std::ofstream& out, const State& st) {
  out << fmt::format("{:.17g}", st.time);
  for (const BodyState& b : st.bodies) {
    const Quat q(b.R_space_body);
    out << fmt::format(
        ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:."
        "17g}",
        b.x_space.x(), b.x_space.y(), b.x_space.z(), q.w(), q.x(), q.y(), q.z(), b.v_space.x(), b.v_space.y(),
        b.v_space.z(), b.omega_body.x(), b.omega_body.y(), b.omega_body.z());
  }
  out << '\n';
}

/// The columns of diagnostics.csv (scenario.hpp documents them).
constexpr const char* kDiagnosticsHeader =
    "t,energy,energy_error,kinetic,potential,linear_momentum,L_space_x,L_space_y,L_space_z,joint_gap,"
    "joint_angle,orthogonality\n";

/// One row of diagnostics.csv: E = T + V summed as total_energy does (observables.cpp), so that
/// energy_error is the quantity RunSummary::max_energy_error takes the maximum of.
void write_diagnostics_row(std::ofstream& out, const System& sys, const State& st, double energy_initial) {
  const double T = kinetic_energy(sys, st);
  const double V = potential_energy(sys, st.bodies);
  const double E = T + V;
  const Vec3 L = angular_momentum(sys, st);
  const ConstraintViolation v = constraint_violation(sys, st);
  out << fmt::format(
      "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n",
      st.time, E, E - energy_initial, T, V, linear_momentum(sys, st).norm(), L.x(), L.y(), L.z(), v.joint_gap,
      v.joint_angle, v.orthogonality);
}

void write_report(std::ostream& out, const Scenario& sc, const State& st, const RunSummary& s) {
  const System& sys = sc.system;
  out << "multibody run\n";
  if (!sc.title.empty()) out << fmt::format("  {}\n", sc.title);
  if (!sc.source.empty()) out << fmt::format("  scenario: {}\n", sc.source);
  for (std::size_t i = 0; i < sc.body_descriptions.size() && i < sys.bodies().size(); ++i) {
    if (!sc.body_descriptions[i].empty())
      out << fmt::format("  body '{}': {}\n", sys.bodies()[i].name, sc.body_descriptions[i]);
  }
  out << fmt::format("  bodies: {}, joints: {} ({} constraint rows), solver: {}\n", sys.body_count(),
                     sys.joint_count(), sys.constraint_rows(), kkt_method_description(s.kkt_method));
  const bool rk4 = sc.method == MultibodyMethod::projected_rk4;
  out << fmt::format("  method: {}, dt: {} s, steps: {}, final time: {} s\n",
                     rk4             ? "RK4 projected onto the joints (order 4, not symplectic)"
                     : sc.order == 4 ? "RATTLE, order 4 (triple-jump composition)"
                                     : "RATTLE, order 2",
                     format_number(sc.dt), s.steps, format_number(st.time));
  out << fmt::format("  energy: initial {} J, final {} J, max |E - E0| {} J\n",
                     format_number(s.energy_initial), format_number(s.energy_final),
                     format_number(s.max_energy_error));
  out << fmt::format("  linear momentum: {} kg·m/s\n", format_vector(linear_momentum(sys, st)));
  out << fmt::format("  angular momentum (origin): {} kg·m²/s\n", format_vector(angular_momentum(sys, st)));
  out << fmt::format(
      "  constraint violation (max over the run): joint gap {} m, joint angle {}, |RᵀR − I| {}\n",
      format_number(s.max_joint_gap), format_number(s.max_joint_angle), format_number(s.max_orthogonality));
  out << fmt::format("  {} per step: mean {}, max {}\n", rk4 ? "projection iterations" : "Newton iterations",
                     format_number(s.mean_newton_iterations, 3), s.max_newton_iterations);
  out << fmt::format("  cpu time per step: {} µs\n", format_number(1e6 * s.cpu_seconds_per_step, 3));
  const ExactMultipliers ex = exact_multipliers(sys, st);
  for (int j = 0; j < sys.joint_count(); ++j) {
    const auto ju = static_cast<std::size_t>(j);
    out << fmt::format("  joint '{}': reaction force on '{}' {} N, couple {} N·m\n", sys.joints()[ju].name,
                       sys.bodies()[static_cast<std::size_t>(sys.joints()[ju].body_a)].name,
                       format_vector(ex.joint_force_space[ju]), format_vector(ex.joint_torque_space[ju]));
  }
  for (int i = 0; i < sys.body_count(); ++i) {
    const auto iu = static_cast<std::size_t>(i);
    out << fmt::format("  body '{}': x {} m, Lambda (body frame, J) {}\n", sys.bodies()[iu].name,
                       format_vector(st.bodies[iu].x_space), format_matrix(ex.Lambda_body[iu]));
  }
}

// The run with the scenario's method (methods.hpp: step, last_iterations, kkt_method).
RunSummary run_with(const Scenario& sc, MultibodyIntegrator& integrator, std::ostream* report,
                    const std::string& trajectory_csv, const std::string& diagnostics_csv) {
  State st = sc.initial;
  RunSummary s;
  s.kkt_method = integrator.kkt_method();
  s.tree_solver = s.kkt_method != KktMethod::sparse_lu;
  s.energy_initial = total_energy(sc.system, st);
  std::ofstream out;
  if (!trajectory_csv.empty()) {
    out.open(trajectory_csv);
    if (!out)
      throw InvalidInput(fmt::format("multibody: cannot write the trajectory to '{}'", trajectory_csv));
    out << "t";
    for (const Body& b : sc.system.bodies()) {
      for (const char* c : {"x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"}) {
        out << ',' << b.name << '.' << c;
      }
    }
    out << '\n';
    write_row(out, st);
  }
  std::ofstream diag;
  if (!diagnostics_csv.empty()) {
    diag.open(diagnostics_csv);
    if (!diag)
      throw InvalidInput(fmt::format("multibody: cannot write the diagnostics to '{}'", diagnostics_csv));
    diag << kDiagnosticsHeader;
    write_diagnostics_row(diag, sc.system, st, s.energy_initial);
  }
  const long steps = std::lround(sc.duration / sc.dt);
  long iterations = 0;
  const std::clock_t c0 = std::clock();
  for (long n = 0; n < steps; ++n) {
    try {
      integrator.step(st);
      // Sample times t₀ + n h exactly, as the single-body runs have them (the integrator adds h each step,
      // whose rounding would otherwise accumulate: 0.5000000000000002 s after 50 steps of 0.01 s).
      st.time = sc.initial.time + static_cast<double>(n + 1) * sc.dt;
    } catch (const ComputationFailed&) {
      if (out.is_open()) out.flush();
      if (diag.is_open()) diag.flush();
      throw;
    }
    iterations += integrator.last_iterations();
    s.max_newton_iterations = std::max(s.max_newton_iterations, integrator.last_iterations());
    const ConstraintViolation v = constraint_violation(sc.system, st);
    s.max_joint_gap = std::max(s.max_joint_gap, v.joint_gap);
    s.max_joint_angle = std::max(s.max_joint_angle, v.joint_angle);
    s.max_orthogonality = std::max(s.max_orthogonality, v.orthogonality);
    s.max_energy_error =
        std::max(s.max_energy_error, std::abs(total_energy(sc.system, st) - s.energy_initial));
    if ((n + 1) % sc.output_every == 0 || n + 1 == steps) {
      if (out.is_open()) write_row(out, st);
      if (diag.is_open()) write_diagnostics_row(diag, sc.system, st, s.energy_initial);
    }
  }
  s.steps = steps;
  s.cpu_seconds_per_step =
      steps > 0 ? static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC / static_cast<double>(steps) : 0.0;
  s.mean_newton_iterations = steps > 0 ? static_cast<double>(iterations) / static_cast<double>(steps) : 0.0;
  s.energy_final = total_energy(sc.system, st);
  if (report != nullptr) write_report(*report, sc, st, s);
  return s;
}

}  // namespace

RunSummary run_scenario(const Scenario& sc, std::ostream* report, const std::string& trajectory_csv,
                        const std::string& diagnostics_csv) {
  check_consistent(sc.system, sc.initial);
  const auto integrator = multibody_method_info(sc.method).make(sc.system, sc.dt, sc.order);
  return run_with(sc, *integrator, report, trajectory_csv, diagnostics_csv);
}

}  // namespace poinsot::multibody
