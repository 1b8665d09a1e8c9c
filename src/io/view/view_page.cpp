// view.html (see view_page.hpp and docs/viewer.md): the run folder read into the page's data, and the page
// assembled from the embedded template, style and scripts.
#include "poinsot/io/view/view_page.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <variant>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/io/run/summary.hpp"
#include "poinsot/io/scenario/scenario_file.hpp"
#include "poinsot/multibody/joint_types.hpp"
#include "view_assets.hpp"
#include "view_data.hpp"
#include "view_json.hpp"
#include "view_multipliers.hpp"
#include "view_optimal.hpp"

namespace poinsot::io {
namespace {

namespace fs = std::filesystem;
using json = detail::ViewJson;
using detail::check_page_budget;
using detail::frames_header;
using detail::gather;
using detail::mat;
using detail::shapes_json;
using detail::vec;

Mat3 read_mat(const json& j) {
  Mat3 m;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k)
      m(i, k) = j.at(i).at(k).get<double>();
  return m;
}

/// summary.json of a finished run in `dir`, or InvalidInput saying what is missing.
json read_finished_summary(const std::string& dir) {
  const std::string hint = "expected the output folder of a finished `poinsot run` or `poinsot optimize`";
  if (!fs::is_directory(dir)) throw InvalidInput(fmt::format("view: \"{}\" is not a folder; {}", dir, hint));
  const fs::path summary = fs::path(dir) / "summary.json";
  const fs::path trajectory = fs::path(dir) / "trajectory.csv";
  for (const fs::path& p : {summary, trajectory}) {
    if (!fs::is_regular_file(p)) {
      throw InvalidInput(fmt::format("view: \"{}\" has no {}; {}", dir, p.filename().string(), hint));
    }
  }
  std::ifstream in(summary);
  json j = json::parse(in, nullptr, false);
  if (j.is_discarded() || !j.is_object()) {
    throw InvalidInput(fmt::format("view: \"{}\" is not valid JSON; {}", summary.string(), hint));
  }
  if (j.value("kind", "") != "multibody" && !detail::is_optimal_summary(j)) {
    const std::string status =
        j.contains("status") && j["status"].is_string() ? j["status"].get<std::string>() : "";
    if (status != "completed") {
      throw InvalidInput(
          fmt::format("view: \"{}\" says status \"{}\"; expected \"completed\" (a finished run)",
                      summary.string(), status));
    }
  }
  return j;
}

/// The scenario that made the run, when it can still be read: the given path, else the one in summary.json.
std::optional<AnyScenario> try_load_scenario(const ViewOptions& options, const json& summary) {
  if (!options.scenario_path.empty()) return load_any_scenario(options.scenario_path);
  for (const char* key : {"source", "scenario"}) {
    if (!summary.contains(key) || !summary[key].is_string()) continue;
    const std::string path = summary[key].get<std::string>();
    if (!fs::is_regular_file(path)) continue;
    try {
      return load_any_scenario(path);
    } catch (const Error&) {
      // The file changed since the run: the page is drawn from the run's own files alone.
    }
  }
  return std::nullopt;
}

}  // namespace

void check_view_options(const ViewOptions& options) {
  if (options.frames < kViewFramesMin || options.frames > kViewFramesMax) {
    throw InvalidInput(fmt::format("view: --frames {} is out of range; expected an integer in [{}, {}]",
                                   options.frames, kViewFramesMin, kViewFramesMax));
  }
}

namespace {

json single_body_data(const std::string& dir, const json& summary, const ViewOptions& options) {
  const std::string path = (fs::path(dir) / "trajectory.csv").string();
  const long long rows = count_csv_rows(path);
  const long long kept = static_cast<long long>(frame_rows(rows, options.frames).size());
  check_page_budget(dir, kept, 12, options.frames);
  const CsvFrames f = read_csv_frames(path, options.frames);
  if (f.values.size() < 2) {
    throw InvalidInput(fmt::format("view: \"{}\" has {} rows; expected at least 2", path, f.values.size()));
  }
  json j;
  j["kind"] = "body";
  j.update(frames_header(f, path));
  j["q"] = gather(f, {"qw", "qx", "qy", "qz"}, path);
  j["omega_body"] = gather(f, {"wx", "wy", "wz"}, path);
  j["energy"] = gather(f, {"energy"}, path);
  j["L_space"] = gather(f, {"L_space_x", "L_space_y", "L_space_z"}, path);

  const json& b = summary.at("body");
  const Mat3 inertia = read_mat(b.at("inertia"));  // about the rotation point
  Mat3 inertia_com = inertia;
  double mass = 0.0;
  Vec3 pivot_to_com = Vec3::Zero();
  Vec3 gravity = Vec3::Zero();
  bool from_scenario = false;
  std::shared_ptr<const inertia::TriangleMesh> surface;
  if (auto any = try_load_scenario(options, summary)) {
    if (const auto* sc = std::get_if<Scenario>(&*any)) {
      // Used only when it still describes this run's body (same J about the rotation point).
      if ((sc->body.inertia() - inertia).norm() <= 1e-12 * inertia.norm()) {
        from_scenario = true;
        inertia_com = sc->body.inertia_com();
        mass = sc->body.mass();
        pivot_to_com = sc->body.pivot_to_com();
        gravity = sc->gravity_space;
        surface = sc->body_surface;
      }
    }
  }
  json body;
  body["description"] = b.value("description", "");
  body["inertia"] = mat(inertia);
  body["principal_moments"] = b.at("principal_moments");
  // The principal axes of J about the rotation point (columns, body frame): the inertia ellipsoid's axes.
  body["inertia_axes"] = mat(dynamics::RigidBody::from_inertia(inertia).principal_axes());
  body["mass"] = mass > 0.0 ? json(mass) : json(nullptr);
  body["pivot_to_com"] = vec(pivot_to_com);
  body["has_pivot"] = pivot_to_com.norm() > 0.0;
  body["model_from_scenario"] = from_scenario;
  // Without a mass the shapes are those of 1 kg (their proportions are the body's; the size is arbitrary).
  body["shapes"] = shapes_json(inertia_com, mass > 0.0 ? mass : 1.0, surface.get());
  j["body"] = body;
  j["torque"] = summary.value("torque", "none");
  j["gravity"] = vec(gravity);
  j["initial"] = summary.at("initial");
  j["top"] = summary.contains("top") ? summary["top"] : json(nullptr);
  j["events"] = summary.contains("events") ? summary["events"] : json(nullptr);
  return j;
}

json multibody_data(const std::string& dir, const json& summary, const ViewOptions& options) {
  const std::string path = (fs::path(dir) / "trajectory.csv").string();
  const std::string diag_path = (fs::path(dir) / "diagnostics.csv").string();
  const bool has_diag = fs::is_regular_file(diag_path);
  const long long rows = count_csv_rows(path);
  const long long kept = static_cast<long long>(frame_rows(rows, options.frames).size());
  const int bodies_in_summary = summary.value("bodies", 0);
  // The model, when the scenario still reads and has the run's bodies (checked by name below).
  std::optional<multibody::Scenario> mb;
  if (auto any = try_load_scenario(options, summary)) {
    if (auto* m = std::get_if<multibody::Scenario>(&*any)) {
      if (m->system.body_count() == bodies_in_summary) mb = std::move(*m);
    }
  }
  // Per frame: t, per body x, q, ω (10), energy_error; with the model, 6 multipliers per joint and per body.
  const long long multiplier_values =
      mb ? 6LL * (static_cast<long long>(mb->system.joints().size()) + bodies_in_summary) : 0;
  check_page_budget(dir, kept, 1 + 10LL * bodies_in_summary + (has_diag ? 1 : 0) + multiplier_values,
                    options.frames);
  const CsvFrames f = read_csv_frames(path, options.frames);
  if (f.values.size() < 2) {
    throw InvalidInput(fmt::format("view: \"{}\" has {} rows; expected at least 2", path, f.values.size()));
  }
  std::vector<std::string> names;
  for (const auto& c : f.columns)
    if (c.size() > 2 && c.compare(c.size() - 2, 2, ".x") == 0) names.push_back(c.substr(0, c.size() - 2));
  json j;
  j["kind"] = "multibody";
  j.update(frames_header(f, path));
  if (has_diag) {
    const CsvFrames d = read_csv_frames(diag_path, options.frames);
    if (d.rows == f.rows) j["energy_error"] = gather(d, {"energy_error"}, diag_path);
  }
  if (mb) {
    bool same = mb->system.body_count() == static_cast<int>(names.size());
    for (int i = 0; same && i < mb->system.body_count(); ++i)
      same = mb->system.bodies()[static_cast<std::size_t>(i)].name == names[static_cast<std::size_t>(i)];
    if (!same) mb.reset();
  }
  FrameMultipliers multipliers;
  if (mb) multipliers = frame_multipliers(mb->system, f, path);
  // Frame after frame, the 6 numbers of item k (of `count` items a frame) in `all`.
  const auto per_item = [&](const std::vector<double>& all, std::size_t k, std::size_t count) {
    std::vector<double> out;
    out.reserve(f.values.size() * 6);
    for (std::size_t r = 0; r < f.values.size(); ++r)
      for (std::size_t c = 0; c < 6; ++c)
        out.push_back(all[(r * count + k) * 6 + c]);
    return out;
  };
  json bodies = json::array();
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& n = names[i];
    json b;
    b["name"] = n;
    b["x"] = gather(f, {n + ".x", n + ".y", n + ".z"}, path);
    b["q"] = gather(f, {n + ".qw", n + ".qx", n + ".qy", n + ".qz"}, path);
    b["omega_body"] = gather(f, {n + ".wx", n + ".wy", n + ".wz"}, path);
    if (mb) {
      const multibody::Body& body = mb->system.bodies()[i];
      b["mass"] = body.mass;
      b["inertia"] = mat(body.inertia);
      b["shapes"] = shapes_json(body.inertia, body.mass,
                                i < mb->body_surfaces.size() ? mb->body_surfaces[i].get() : nullptr);
      b["lambda"] = per_item(multipliers.lambda, i, names.size());
    } else {
      b["mass"] = nullptr;
      b["shapes"] = nullptr;
      b["lambda"] = nullptr;
    }
    bodies.push_back(b);
  }
  j["bodies"] = bodies;
  json joints = json::array();
  if (mb) {
    const std::size_t count = mb->system.joints().size();
    for (std::size_t k = 0; k < count; ++k) {
      const multibody::Joint& jt = mb->system.joints()[k];
      joints.push_back({{"name", jt.name},
                        {"type", std::string(multibody::joint_type_info(jt.type).name)},
                        {"body_a", jt.body_a},
                        {"point_a", vec(jt.point_a)},
                        {"body_b", jt.body_b},  // −1: the world (point_b in the space frame)
                        {"point_b", vec(jt.point_b)},
                        {"reaction", per_item(multipliers.reactions, k, count)}});
    }
  }
  j["joints"] = joints;
  j["gravity"] = mb ? vec(mb->system.gravity()) : json(nullptr);
  j["model_from_scenario"] = mb.has_value();
  return j;
}

/// Replaces every `<!-- poinsot:NAME ARG -->` marker of the template.
std::string assemble(const std::string& tmpl, const std::string& data) {
  std::string out;
  out.reserve(tmpl.size() + data.size() + (1u << 20));
  std::size_t pos = 0;
  const std::string open = "<!-- poinsot:";
  while (true) {
    const std::size_t m = tmpl.find(open, pos);
    if (m == std::string::npos) break;
    const std::size_t e = tmpl.find("-->", m);
    out.append(tmpl, pos, m - pos);
    std::istringstream words(tmpl.substr(m + open.size(), e - m - open.size()));
    std::string what, arg;
    words >> what >> arg;
    if (what == "data") {
      out += data;
    } else {
      const std::optional<std::string> text = view_asset(arg);
      if (!text) {
        throw InvalidInput(
            fmt::format("view: this build of poinsot has no {}; expected it to be built with Debian's "
                        "libjs-three installed (scripts/setup.sh), then reconfigured",
                        arg));
      }
      out += what == "style" ? "<style>\n" : "<script>\n";
      out += *text;
      out += what == "style" ? "</style>" : "\n</script>";
    }
    pos = e + 3;
  }
  out.append(tmpl, pos);
  return out;
}

}  // namespace

std::string view_data_json(const std::string& run_dir, const ViewOptions& options) {
  check_view_options(options);
  const json summary = read_finished_summary(run_dir);
  json j;
  j["format"] = "poinsot-view 1";
  j["title"] = summary.value("title", "");
  j["scenario"] = summary.value("scenario", "");
  j["method"] = summary.value("method", "");
  j["t_end"] = summary.value("t_end", 0.0);
  if (detail::is_optimal_summary(summary)) {
    j["method"] = "optimize, " + summary.value("status", std::string());
    j.update(detail::optimal_view_data(run_dir, summary, options));
  } else {
    j.update(summary.value("kind", "") == "multibody" ? multibody_data(run_dir, summary, options)
                                                      : single_body_data(run_dir, summary, options));
  }
  return j.dump();
}

std::string view_page_html(const std::string& run_dir, const ViewOptions& options) {
  std::string data = view_data_json(run_dir, options);
  // Inside <script>, "</" could end the element: JSON allows the escape "<\/".
  for (std::size_t p = data.find("</"); p != std::string::npos; p = data.find("</", p + 3))
    data.replace(p, 2, "<\\/");
  const std::optional<std::string> tmpl = view_asset("page.html");
  if (!tmpl) throw InvalidInput("view: this build of poinsot has no viewer/page.html");
  return assemble(*tmpl, data);
}

std::string write_view_page(const std::string& run_dir, const ViewOptions& options) {
  const std::string html = view_page_html(run_dir, options);
  const std::string path = (fs::path(run_dir) / "view.html").string();
  write_file_atomic(path, html);
  return path;
}

std::size_t view_page_size_bound(long long frames, long long values_per_frame, long long bodies,
                                 long long surface_triangles) {
  // The page's other data: summary.json's values (under 8 KiB) and per body its name, mass, inertia, shapes
  // and joints (under 2 KiB each, with names up to a few hundred characters).
  const std::size_t other = 8 * 1024 + static_cast<std::size_t>(bodies) * 2048 +
                            static_cast<std::size_t>(surface_triangles) * kSurfaceBytesPerTriangle;
  return view_assets_size() + other + static_cast<std::size_t>(frames * values_per_frame) * 25;
}

}  // namespace poinsot::io
