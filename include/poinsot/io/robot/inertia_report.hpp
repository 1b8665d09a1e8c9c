#pragma once
/// @file inertia_report.hpp
/// The one serialisation of a body's mass properties, for `poinsot inertia` and Python: a text table, one
/// JSON object, or the inertial element of a robot model (URDF, MJCF, SDF).
///
/// Every form gives the centre of mass (m) and the inertia tensor J about it (kg·m²) in the input frame, the
/// Poinsot tensor K = tr(J)/2·I − J, the principal moments (ascending) and axes (columns of a proper
/// rotation) and the symmetry class at the stated relative tolerance; with a reference point, J about it and
/// its principal moments and axes (parallel-axis theorem, inertia/mass_properties.hpp).
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/io/robot/robot_model.hpp"

namespace poinsot::io {

/// A body's mass properties and what was found about them.
struct InertiaReport {
  std::optional<double> mass;  ///< kg; absent for a tensor given without a mass
  inertia::MassProperties props;
  std::vector<std::string> diagnostics;  ///< the validity checks' findings, one line each
  bool valid = true;
  std::optional<double> repair_distance;  ///< kg·m² (Frobenius), when the tensor was repaired
  std::optional<Vec3> about;              ///< a reference point (m, input frame), which needs the mass
  double symmetry_tolerance = inertia::kDefaultSymmetryTolerance;  ///< relative, for the symmetry class
};

/// The table printed by `poinsot inertia` (full precision, units on every line). Throws InvalidInput for a
/// non-finite reference point, or a reference point without the mass.
std::string inertia_report_text(const InertiaReport& report);

/// One JSON object (SI units, one line): mass, center_of_mass, inertia_com, [about, inertia_ref,
/// principal_moments_ref, principal_axes_ref], poinsot_com, principal_moments, principal_axes, symmetry,
/// symmetry_tolerance, valid, diagnostics, [repair_distance]; matrices row by row. Throws as
/// inertia_report_text.
std::string inertia_report_json(const InertiaReport& report);

/// The format named "urdf", "mjcf" or "sdf". Throws InvalidInput `WHAT "NAME"; expected urdf, mjcf or sdf`
/// otherwise (`what` names the source of the value, e.g. "inertia: --format").
RobotFormat robot_format_named(std::string_view name, std::string_view what);

/// The inertial element of a link in `format` for a body of `mass` kg: the tensor about the centre of mass,
/// in a frame at the centre of mass with the axes of the input frame, products of inertia with their sign as
/// entries of J (J_xy = −∫ρxy): URDF `<inertial>` (origin, mass, inertia ixx … izz), MJCF `<inertial pos mass
/// fullinertia="M11 M22 M33 M12 M13 M23">`, SDF `<inertial>` (pose, mass, inertia elements). Numbers are
/// written with the shortest form that reads back to the same double.
std::string inertial_element(RobotFormat format, double mass, const inertia::MassProperties& props);

}  // namespace poinsot::io
