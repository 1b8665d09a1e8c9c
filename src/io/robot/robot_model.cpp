#include "poinsot/io/robot/robot_model.hpp"

#include <filesystem>
#include <memory>
#include <string_view>

#include <fmt/format.h>

#include "mjcf_include.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/core/text_file.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "robot_readers.hpp"
#include "xml_source.hpp"

namespace poinsot::io {

std::string to_string(RobotFormat f) {
  switch (f) {
    case RobotFormat::urdf:
      return "urdf";
    case RobotFormat::mjcf:
      return "mjcf";
    case RobotFormat::sdf:
      return "sdf";
  }
  return "urdf";
}

std::string SourceLines::file(int line) const {
  if (origin.empty() || line < 1 || line > static_cast<int>(origin.size())) return "";
  const int f = origin[static_cast<std::size_t>(line - 1)].first;
  return f == 0 ? "" : files[static_cast<std::size_t>(f)];
}

int SourceLines::line_in_file(int line) const {
  if (origin.empty() || line < 1 || line > static_cast<int>(origin.size())) return line;
  return origin[static_cast<std::size_t>(line - 1)].second;
}

std::string SourceLines::location(int line) const {
  const std::string f = file(line);
  return fmt::format("{}:{}", f.empty() ? (files.empty() ? "" : files[0]) : f, line_in_file(line));
}

std::string SourceLines::label(int line) const {
  const std::string f = file(line);
  return f.empty() ? fmt::format("line {}", line_in_file(line))
                   : fmt::format("line {} of {}", line_in_file(line), f);
}

RobotModel read_robot_model(std::string text, const std::string& source, const std::string& base_dir,
                            std::size_t max_include_bytes) {
  RobotModel model;
  model.source = source;
  model.lines.files = {source};
  auto parsed = std::make_unique<const detail::XmlSource>(std::move(text), model.lines);
  if (std::string_view(parsed->root()->Name()) == "mujoco" &&
      parsed->text().find("<include") != std::string::npos) {
    detail::ExpandedText e =
        detail::expand_mjcf_includes(parsed->text(), source, base_dir, max_include_bytes);
    model.lines = e.lines;
    parsed = std::make_unique<const detail::XmlSource>(std::move(e.text), std::move(e.lines));
  }
  const detail::XmlSource& xml = *parsed;
  const std::string_view root = xml.root()->Name();
  if (root == "robot") {
    model.format = RobotFormat::urdf;
    detail::read_urdf(xml, base_dir, model);
  } else if (root == "mujoco") {
    model.format = RobotFormat::mjcf;
    detail::read_mjcf(xml, base_dir, model);
  } else if (root == "sdf") {
    model.format = RobotFormat::sdf;
    detail::read_sdf(xml, base_dir, model);
  } else {
    throw InvalidInput(fmt::format("{}: root element <{}>; expected <robot> (URDF), <mujoco> (MJCF) or <sdf>",
                                   xml.where(*xml.root()), root));
  }
  model.text = xml.text();
  return model;
}

RobotModel load_robot_model(const std::string& path, std::size_t max_bytes) {
  std::string text = read_file_limited(path, "model", max_bytes, "--max-file-bytes");
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return read_robot_model(std::move(text), path, parent.empty() ? "." : parent.string(), max_bytes);
}

namespace detail {

Mat3 tensor_from_entries(double ixx, double iyy, double izz, double ixy, double ixz, double iyz) {
  Mat3 J;
  J << ixx, ixy, ixz, ixy, iyy, iyz, ixz, iyz, izz;
  return J;
}

Mat3 rotation_from_rpy(const Vec3& roll_pitch_yaw, std::string_view where) {
  const auto refuse = [&] {
    return InvalidInput(fmt::format("{}: got {}, expected angles (rad) whose rotation is finite", where,
                                    format_vector(roll_pitch_yaw)));
  };
  if (!roll_pitch_yaw.allFinite()) throw refuse();
  const Mat3 R = so3::rotation_from_euler(so3::EulerSequence::ZYX(),
                                          Vec3(roll_pitch_yaw.z(), roll_pitch_yaw.y(), roll_pitch_yaw.x()));
  if (!R.allFinite()) throw refuse();
  return R;
}

std::string resolve_mesh_path(const std::string& uri, const std::string& base_dir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto existing = [&](const fs::path& p) {
    return fs::is_regular_file(p, ec) ? p.lexically_normal().string() : std::string();
  };
  std::string_view u = uri;
  if (u.starts_with("file://")) {
    u.remove_prefix(7);
    return existing(fs::path(u));
  }
  for (const std::string_view scheme : {"package://", "model://"}) {
    if (u.starts_with(scheme)) {
      u.remove_prefix(scheme.size());
      const std::size_t slash = u.find('/');
      if (slash == std::string_view::npos) return {};
      const fs::path rest(u.substr(slash + 1));
      for (const fs::path& root : {fs::path(base_dir), fs::path(base_dir) / ".."}) {
        if (std::string p = existing(root / rest); !p.empty()) return p;
      }
      return {};
    }
  }
  if (u.find("://") != std::string_view::npos) return {};
  const fs::path p(u);
  return existing(p.is_absolute() ? p : fs::path(base_dir) / p);
}

void finish_inertial(RobotLink& link) {
  link.inertia_link = inertia::reexpress(link.inertia_file, link.R_link_inertial);
}

void set_spans(RobotLink& link, const std::vector<std::optional<TextSpan>>& spans) {
  link.value_spans.clear();
  for (const auto& span : spans)
    if (!span) return;
  for (const auto& span : spans)
    link.value_spans.push_back({span->begin, span->end});
}

RobotLink read_link_element(const XmlSource& xml, const tinyxml2::XMLElement& e, const std::string& base_dir,
                            InertialReader read_inertial, GeometryPoseReader read_pose,
                            const ShapeSyntax& syntax) {
  RobotLink link;
  const char* name = e.Attribute("name");
  if (name == nullptr)
    throw InvalidInput(fmt::format("{}: missing attribute name; expected the link's name", xml.where(e)));
  link.name = name;
  link.line = e.GetLineNum();
  if (const tinyxml2::XMLElement* inertial = e.FirstChildElement("inertial"))
    read_inertial(xml, *inertial, link);
  for (const char* element : {"collision", "visual"}) {
    for (const tinyxml2::XMLElement* g = e.FirstChildElement(element); g != nullptr;
         g = g->NextSiblingElement(element))
      read_link_shape(xml, *g, base_dir, read_pose, syntax, link);
    if (!link.geometry.empty()) break;
  }
  return link;
}

}  // namespace detail
}  // namespace poinsot::io
