// The text, JSON and robot-model forms of a body's mass properties (see inertia_report.hpp).
#include "poinsot/io/robot/inertia_report.hpp"

#include <fmt/format.h>

#include "io/json_values.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::io {
namespace {

using detail::json;
using inertia::PrincipalAxes;

std::string full_precision_rows(const Mat3& m) {
  std::string s;
  for (int i = 0; i < 3; ++i)
    s += fmt::format("  [{:>24.17g} {:>24.17g} {:>24.17g}]\n", m(i, 0), m(i, 1), m(i, 2));
  return s;
}

/// The report's derived quantities: principal axes about the centre of mass and, with a reference point,
/// J about it and its principal axes.
struct DerivedAxes {
  PrincipalAxes axes;
  Mat3 K;
  std::optional<Mat3> J_ref;
  std::optional<PrincipalAxes> axes_ref;
};

DerivedAxes derive_axes(const InertiaReport& r) {
  if (r.about) {
    if (!r.about->allFinite()) {
      throw InvalidInput(
          fmt::format("inertia: --about {}; expected finite coordinates (m)", format_vector(*r.about)));
    }
    if (!r.mass) throw InvalidInput("inertia: --about needs the mass; expected --mass M (kg)");
  }
  DerivedAxes d{
      inertia::principal_axes(r.props.inertia_com, r.symmetry_tolerance), r.props.poinsot_com(), {}, {}};
  if (r.about) {
    d.J_ref = r.props.inertia_about(*r.about);
    d.axes_ref = inertia::principal_axes(*d.J_ref, r.symmetry_tolerance);
  }
  return d;
}

}  // namespace

std::string inertia_report_text(const InertiaReport& r) {
  const DerivedAxes d = derive_axes(r);
  std::string out;
  out += fmt::format("mass:                {}\n",
                     r.mass ? format_number(*r.mass) + " kg" : std::string("(not given)"));
  out += fmt::format("centre of mass:      {} m\n", format_vector(r.props.com));
  out +=
      "inertia J about the centre of mass (kg·m², input frame):\n" + full_precision_rows(r.props.inertia_com);
  if (d.J_ref) {
    out += fmt::format("inertia J about {} m (kg·m², input frame):\n", format_vector(*r.about)) +
           full_precision_rows(*d.J_ref);
    out += fmt::format("  its principal moments: {} kg·m² (ascending)\n", format_vector(d.axes_ref->moments));
    out += "  its principal axes (columns):\n" + full_precision_rows(d.axes_ref->axes);
  }
  out += "Poinsot tensor K = tr(J)/2·I − J about the centre of mass (kg·m²):\n" + full_precision_rows(d.K);
  out += fmt::format("principal moments:   {} kg·m² (ascending)\n", format_vector(d.axes.moments));
  out += "principal axes (columns, a proper rotation):\n" + full_precision_rows(d.axes.axes);
  out += fmt::format("symmetry:            {} (relative tolerance {})\n", inertia::to_string(d.axes.symmetry),
                     format_number(r.symmetry_tolerance));
  out += fmt::format("valid:               {}\n", r.valid ? "yes" : "no");
  if (r.repair_distance)
    out += fmt::format("repair distance:     {} kg·m² (Frobenius)\n", format_number(*r.repair_distance));
  out += "diagnostics:        ";
  if (r.diagnostics.empty()) out += " none\n";
  for (std::size_t i = 0; i < r.diagnostics.size(); ++i)
    out += (i ? "; " : " ") + r.diagnostics[i];
  if (!r.diagnostics.empty()) out += "\n";
  return out;
}

std::string inertia_report_json(const InertiaReport& r) {
  const DerivedAxes d = derive_axes(r);
  json j;
  j["mass"] = r.mass ? json(*r.mass) : json(nullptr);
  j["center_of_mass"] = detail::vec(r.props.com);
  j["inertia_com"] = detail::mat(r.props.inertia_com);
  if (d.J_ref) {
    j["about"] = detail::vec(*r.about);
    j["inertia_ref"] = detail::mat(*d.J_ref);
    j["principal_moments_ref"] = detail::vec(d.axes_ref->moments);
    j["principal_axes_ref"] = detail::mat(d.axes_ref->axes);
  }
  j["poinsot_com"] = detail::mat(d.K);
  j["principal_moments"] = detail::vec(d.axes.moments);
  j["principal_axes"] = detail::mat(d.axes.axes);
  j["symmetry"] = inertia::to_string(d.axes.symmetry);
  j["symmetry_tolerance"] = r.symmetry_tolerance;
  j["valid"] = r.valid;
  j["diagnostics"] = r.diagnostics;
  if (r.repair_distance) j["repair_distance"] = *r.repair_distance;
  return j.dump() + "\n";
}

RobotFormat robot_format_named(std::string_view name, std::string_view what) {
  for (const RobotFormat f : {RobotFormat::urdf, RobotFormat::mjcf, RobotFormat::sdf})
    if (name == to_string(f)) return f;
  throw InvalidInput(fmt::format("{} \"{}\"; expected urdf, mjcf or sdf", what, name));
}

std::string inertial_element(RobotFormat format, double mass, const inertia::MassProperties& p) {
  const Mat3& J = p.inertia_com;
  const Vec3& c = p.com;
  const auto num = [](double x) { return format_number(x); };
  switch (format) {
    case RobotFormat::urdf:
      return fmt::format(
          "<inertial>\n  <origin xyz=\"{} {} {}\" rpy=\"0 0 0\"/>\n  <mass value=\"{}\"/>\n"
          "  <inertia ixx=\"{}\" ixy=\"{}\" ixz=\"{}\" iyy=\"{}\" iyz=\"{}\" izz=\"{}\"/>\n</inertial>\n",
          num(c.x()), num(c.y()), num(c.z()), num(mass), num(J(0, 0)), num(J(0, 1)), num(J(0, 2)),
          num(J(1, 1)), num(J(1, 2)), num(J(2, 2)));
    case RobotFormat::mjcf:
      return fmt::format("<inertial pos=\"{} {} {}\" mass=\"{}\" fullinertia=\"{} {} {} {} {} {}\"/>\n",
                         num(c.x()), num(c.y()), num(c.z()), num(mass), num(J(0, 0)), num(J(1, 1)),
                         num(J(2, 2)), num(J(0, 1)), num(J(0, 2)), num(J(1, 2)));
    case RobotFormat::sdf:
      break;
  }
  return fmt::format(
      "<inertial>\n  <pose>{} {} {} 0 0 0</pose>\n  <mass>{}</mass>\n  <inertia>\n    <ixx>{}</ixx>\n"
      "    <ixy>{}</ixy>\n    <ixz>{}</ixz>\n    <iyy>{}</iyy>\n    <iyz>{}</iyz>\n    <izz>{}</izz>\n"
      "  </inertia>\n</inertial>\n",
      num(c.x()), num(c.y()), num(c.z()), num(mass), num(J(0, 0)), num(J(0, 1)), num(J(0, 2)), num(J(1, 1)),
      num(J(1, 2)), num(J(2, 2)));
}

}  // namespace poinsot::io
