// view.html's data for the output folder of `poinsot optimize` (see view_optimal.hpp).
#include "view_optimal.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/io/scenario/optimal_scenario.hpp"

namespace poinsot::io::detail {
namespace {

namespace fs = std::filesystem;

/// The [optimal_control] scenario that made the run: `--scenario`, else the path summary.json names.
OptimalScenario load_optimal_scenario_of(const std::string& dir, const ViewJson& summary,
                                         const ViewOptions& options) {
  std::string path = options.scenario_path;
  if (path.empty() && summary.contains("scenario") && summary["scenario"].is_string())
    path = summary["scenario"].get<std::string>();
  if (path.empty() || !fs::is_regular_file(path)) {
    throw InvalidInput(fmt::format(
        "view: \"{}\" is a `poinsot optimize` folder whose scenario \"{}\" cannot be read; expected "
        "--scenario FILE (the [optimal_control] scenario that made it: the body, the bounds, the target)",
        dir, path));
  }
  return load_optimal_scenario(path);
}

std::string path_in(const std::string& dir, const char* name) {
  const fs::path p = fs::path(dir) / name;
  if (!fs::is_regular_file(p)) {
    throw InvalidInput(
        fmt::format("view: \"{}\" has no {}; expected the output folder of `poinsot optimize`", dir, name));
  }
  return p.string();
}

}  // namespace

bool is_optimal_summary(const ViewJson& summary) {
  return summary.contains("objective");
}

ViewJson optimal_view_data(const std::string& dir, const ViewJson& summary, const ViewOptions& options) {
  const OptimalScenario sc = load_optimal_scenario_of(dir, summary, options);
  const optimal::ReorientationProblem& pb = sc.problem;
  const std::string traj_path = path_in(dir, "trajectory.csv");
  const std::string control_path = path_in(dir, "control.csv");
  const std::string costates_path = path_in(dir, "costates.csv");
  // Per frame t, q, ω, T, L, u (15 numbers); control.csv and costates.csv keep at most as many rows, 4 each.
  const long long kept = std::max({frame_rows(count_csv_rows(traj_path), options.frames).size(),
                                   frame_rows(count_csv_rows(control_path), options.frames).size(),
                                   frame_rows(count_csv_rows(costates_path), options.frames).size()});
  check_page_budget(dir, kept, 15 + 4 + 4, options.frames);
  const CsvFrames f = read_csv_frames(traj_path, options.frames);
  if (f.values.size() < 2) {
    throw InvalidInput(
        fmt::format("view: \"{}\" has {} rows; expected at least 2", traj_path, f.values.size()));
  }
  const Mat3 J = pb.bus_inertia();  // with reaction wheels the bus's: the energy ½ ωᵀ J_b ω of its rates
  const std::vector<double> omega = gather(f, {"wx", "wy", "wz"}, traj_path);
  std::vector<double> energy;
  energy.reserve(f.values.size());
  for (std::size_t i = 0; i < f.values.size(); ++i) {
    const Vec3 w(omega[3 * i], omega[3 * i + 1], omega[3 * i + 2]);
    energy.push_back(0.5 * w.dot(J * w));
  }
  ViewJson j;
  j["title"] = sc.title;
  j["t_end"] = f.values.back()[csv_column(f, "t", traj_path)];
  j["kind"] = "body";
  j.update(frames_header(f, traj_path));
  j["q"] = gather(f, {"qw", "qx", "qy", "qz"}, traj_path);
  j["omega_body"] = omega;
  j["energy"] = energy;
  const std::vector<double> L = gather(f, {"Lx", "Ly", "Lz"}, traj_path);
  j["L_space"] = L;

  const dynamics::RigidBody rb = dynamics::RigidBody::from_inertia(J);
  ViewJson body;
  body["description"] = sc.body_description;
  body["inertia"] = mat(J);
  body["principal_moments"] = vec(rb.principal_moments());
  body["inertia_axes"] = mat(rb.principal_axes());
  const double mass = sc.body_mass.value_or(0.0);
  body["mass"] = mass > 0.0 ? ViewJson(mass) : ViewJson(nullptr);
  body["pivot_to_com"] = vec(Vec3::Zero());
  body["has_pivot"] = false;
  body["model_from_scenario"] = true;
  // Without a mass the box and ellipsoid are those of 1 kg (the body's proportions, an arbitrary size).
  body["shapes"] = shapes_json(J, mass > 0.0 ? mass : 1.0, sc.body_surface.get());
  j["body"] = body;
  j["torque"] = "optimal";
  j["gravity"] = vec(Vec3::Zero());
  j["initial"] = {{"omega_body", {omega[0], omega[1], omega[2]}},
                  {"L_space", {L[0], L[1], L[2]}},
                  {"energy", energy.front()}};
  j["top"] = nullptr;
  j["events"] = nullptr;

  const CsvFrames control = read_csv_frames(control_path, options.frames);
  const CsvFrames costates = read_csv_frames(costates_path, options.frames);
  ViewJson o;
  o["objective"] = summary.value("objective", "");
  o["status"] = summary.value("status", "");
  o["optimal"] = summary.value("optimal", false);
  o["bound"] = pb.bound == optimal::TorqueBound::norm ? "norm" : "per_axis";
  o["torque_max"] =
      pb.bound == optimal::TorqueBound::norm ? vec(Vec3::Constant(pb.torque_max[0])) : vec(pb.torque_max);
  o["torque_norm_limit"] = pb.torque_norm_limit();
  // The control: body torques, or with reaction wheels the wheels' motor torques u_k (u1, u2, u3); the arrow
  // then draws their vector A u in the body frame (the bus feels −A u), the chart the u_k themselves.
  const std::vector<std::string> u_columns =
      pb.wheels ? std::vector<std::string>{"u1", "u2", "u3"} : std::vector<std::string>{"ux", "uy", "uz"};
  o["control_kind"] = pb.wheels ? "wheels" : "body";
  std::vector<double> u = gather(f, u_columns, traj_path);
  if (pb.wheels)
    for (std::size_t i = 0; i + 2 < u.size(); i += 3) {
      const Vec3 a = pb.wheels->axes_body * Vec3(u[i], u[i + 1], u[i + 2]);
      u[i] = a[0];
      u[i + 1] = a[1];
      u[i + 2] = a[2];
    }
  o["u"] = u;
  o["control"] = {{"t", gather(control, {"t"}, control_path)},
                  {"u", gather(control, u_columns, control_path)}};
  o["costates"] = {{"t", gather(costates, {"t"}, costates_path)},
                   {"sigma", gather(costates, {"sigma_x", "sigma_y", "sigma_z"}, costates_path)}};
  ViewJson switches = ViewJson::array();
  if (summary.contains("indirect") && summary["indirect"].contains("switches"))
    switches = summary["indirect"]["switches"];
  o["switches"] = switches;
  const Quat& target = pb.attitude_final;
  o["target"] =
      pb.free_final_attitude ? ViewJson(nullptr) : ViewJson({target.w(), target.x(), target.y(), target.z()});
  // Pointing constraints: the cones on the sky (space frame) and the boresights (body frame); the page draws
  // each boresight's path R(t) b from the frames' attitudes.
  ViewJson cones = ViewJson::array();
  for (const auto& c : pb.pointing)
    cones.push_back({{"name", c.name},
                     {"kind", std::string(optimal::pointing_kind_name(c.kind))},
                     {"boresight_body", vec(c.boresight_body)},
                     {"direction_space", vec(c.direction_space)},
                     {"half_angle", c.half_angle}});
  o["cones"] = cones;
  j["optimal"] = o;
  return j;
}

}  // namespace poinsot::io::detail
