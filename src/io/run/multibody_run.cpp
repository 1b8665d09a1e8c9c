// Runs a multibody scenario into its files and its summary (see multibody_run.hpp).
#include "poinsot/io/run/multibody_run.hpp"

#include <filesystem>
#include <iterator>

#include <fmt/format.h>

#include "multibody_csv.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/run/line_file.hpp"
#include "poinsot/io/run/summary.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/observables.hpp"

namespace poinsot::io {

void detail::append_trajectory_header(std::string& out, const multibody::System& sys) {
  out += "t";
  for (const multibody::Body& b : sys.bodies()) {
    for (const char* c : {"x", "y", "z", "qw", "qx", "qy", "qz", "vx", "vy", "vz", "wx", "wy", "wz"})
      fmt::format_to(std::back_inserter(out), ",{}.{}", b.name, c);
  }
  out += '\n';
}

void detail::append_trajectory_row(std::string& text, const multibody::State& st) {
  auto out = std::back_inserter(text);
  fmt::format_to(out, "{:.17g}", st.time);
  for (const multibody::BodyState& b : st.bodies) {
    const Quat q(b.R_space_body);
    fmt::format_to(out, ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", b.x_space.x(),
                   b.x_space.y(), b.x_space.z(), q.w(), q.x(), q.y(), q.z());
    fmt::format_to(out, ",{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}", b.v_space.x(), b.v_space.y(),
                   b.v_space.z(), b.omega_body.x(), b.omega_body.y(), b.omega_body.z());
  }
  text += '\n';
}

/// reactions.csv: per joint, the reaction on body a at the joint point (space frame).
std::string detail::reactions_csv(const multibody::System& sys, const multibody::Multipliers& ex, double t,
                                  bool header) {
  std::string out = header ? "t,joint,body_a,body_b,Fx,Fy,Fz,F_norm,Cx,Cy,Cz,C_norm\n" : "";
  for (std::size_t j = 0; j < sys.joints().size(); ++j) {
    const multibody::Joint& joint = sys.joints()[j];
    const auto name_of = [&](int b) {
      return b == multibody::kWorld ? std::string("world") : sys.bodies()[static_cast<std::size_t>(b)].name;
    };
    const Vec3& F = ex.joint_force_space[j];
    const Vec3& C = ex.joint_torque_space[j];
    fmt::format_to(std::back_inserter(out),
                   "{:.17g},{},{},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n", t,
                   joint.name, name_of(joint.body_a), name_of(joint.body_b), F.x(), F.y(), F.z(), F.norm(),
                   C.x(), C.y(), C.z(), C.norm());
  }
  return out;
}

/// multipliers.csv: per body, its centre of mass and Λ (body frame, row by row).
std::string detail::multipliers_csv(const multibody::System& sys, const multibody::State& st,
                                    const multibody::Multipliers& ex, bool header) {
  std::string out = header ? "t,body,x,y,z,Lambda_xx,Lambda_xy,Lambda_xz,Lambda_yx,Lambda_yy,Lambda_yz,"
                             "Lambda_zx,Lambda_zy,Lambda_zz\n"
                           : "";
  for (std::size_t i = 0; i < sys.bodies().size(); ++i) {
    const Vec3& x = st.bodies[i].x_space;
    const Mat3& L = ex.Lambda_body[i];
    fmt::format_to(std::back_inserter(out),
                   "{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
                   "{:.17g},{:.17g},{:.17g}\n",
                   st.time, sys.bodies()[i].name, x.x(), x.y(), x.z(), L(0, 0), L(0, 1), L(0, 2), L(1, 0),
                   L(1, 1), L(1, 2), L(2, 0), L(2, 1), L(2, 2));
  }
  return out;
}

namespace {

using multibody::State;
using multibody::System;

void write_trajectory_header(LineFile& f, const System& sys) {
  detail::append_trajectory_header(f.buffer(), sys);
}

void write_trajectory_row(LineFile& f, const State& st) {
  detail::append_trajectory_row(f.buffer(), st);
  f.line_done();
}

/// The columns of diagnostics.csv (multibody_run.hpp documents them).
constexpr const char* kDiagnosticsHeader =
    "t,energy,energy_error,kinetic,potential,linear_momentum,L_space_x,L_space_y,L_space_z,joint_gap,"
    "joint_angle,orthogonality\n";

/// One row of diagnostics.csv: E = T + V summed as total_energy does (observables.cpp), so that
/// energy_error is the quantity multibody::RunSummary::max_energy_error takes the maximum of.
void write_diagnostics_row(LineFile& f, const System& sys, const State& st, double energy_initial) {
  const double T = multibody::kinetic_energy(sys, st);
  const double V = multibody::potential_energy(sys, st.bodies);
  const double E = T + V;
  const Vec3 L = multibody::angular_momentum(sys, st);
  const multibody::ConstraintViolation v = multibody::constraint_violation(sys, st);
  fmt::format_to(std::back_inserter(f.buffer()),
                 "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},"
                 "{:.17g}\n",
                 st.time, E, E - energy_initial, T, V, multibody::linear_momentum(sys, st).norm(), L.x(),
                 L.y(), L.z(), v.joint_gap, v.joint_angle, v.orthogonality);
  f.line_done();
}

std::string in_dir(const std::string& dir, const char* name) {
  return dir.empty() ? std::string() : (std::filesystem::path(dir) / name).string();
}

}  // namespace

MultibodyRunSummary run_multibody_scenario(const multibody::Scenario& sc,
                                           const MultibodyRunOptions& options) {
  const System& sys = sc.system;
  multibody::check_consistent(sys, sc.initial);  // everything that can be refused, before the first step
  MultibodyRunSummary sum;
  sum.scenario = sc.source.empty() ? "multibody" : std::filesystem::path(sc.source).stem().string();
  sum.out_dir = options.out_dir;
  if (!options.out_dir.empty()) prepare_output_dir(options.out_dir);
  const std::string& dir = options.out_dir;
  sum.trajectory_file =
      options.trajectory_csv.empty() ? in_dir(dir, "trajectory.csv") : options.trajectory_csv;
  sum.diagnostics_file =
      options.diagnostics_csv.empty() ? in_dir(dir, "diagnostics.csv") : options.diagnostics_csv;
  sum.reactions_file = in_dir(dir, "reactions.csv");
  sum.multipliers_file = in_dir(dir, "multipliers.csv");
  sum.report_file = in_dir(dir, "report.txt");
  sum.summary_file = in_dir(dir, "summary.json");

  std::optional<LineFile> traj, diag;
  if (!sum.trajectory_file.empty()) {
    traj.emplace(sum.trajectory_file);
    write_trajectory_header(*traj, sys);
  }
  if (!sum.diagnostics_file.empty()) {
    diag.emplace(sum.diagnostics_file);
    diag->buffer() += kDiagnosticsHeader;
  }
  const double energy_initial = multibody::total_energy(sys, sc.initial);
  const multibody::SampleObserver observer = [&](const State& st) {
    if (traj) write_trajectory_row(*traj, st);
    if (diag) write_diagnostics_row(*diag, sys, st, energy_initial);
    ++sum.rows;
    if (options.on_sample) options.on_sample(st.time);
    return !(options.stop_requested && options.stop_requested());
  };
  sum.run = multibody::simulate(sc, observer);
  if (traj) traj->flush();
  if (diag) diag->flush();
  const State& final_state = sum.run.final_state;
  if (sum.run.failure.empty()) sum.final_multipliers = multibody::exact_multipliers(sys, final_state);
  if (!sum.final_multipliers) sum.reactions_file.clear(), sum.multipliers_file.clear();
  if (sum.final_multipliers && !dir.empty()) {
    write_file_atomic(sum.reactions_file,
                      detail::reactions_csv(sys, *sum.final_multipliers, final_state.time));
    write_file_atomic(sum.multipliers_file,
                      detail::multipliers_csv(sys, final_state, *sum.final_multipliers));
  }
  if (!dir.empty()) {
    write_file_atomic(sum.report_file, format_multibody_report(sc, sum));
    write_file_atomic(sum.summary_file, multibody_summary_json(sc, sum));
  }
  if (!sum.run.failure.empty()) throw ComputationFailed(sum.run.failure);
  return sum;
}

}  // namespace poinsot::io
