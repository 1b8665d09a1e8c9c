#pragma once
/// @file model_check.hpp
/// `poinsot inertia check`: for each link of a robot model (robot_model.hpp), the inertia layer's verdict
/// (validity.hpp: which inequality fails and by how much, and the nearest valid tensor) and plausibility
/// warnings against the link's own geometry.
///
/// The geometry's mass properties at the link's mass: the shapes (and closed meshes) of the link, each of
/// uniform density, the mass shared in proportion to their volumes (overlaps are counted twice), combined
/// about their joint centre of mass (mass_properties.hpp, combine). From it:
///  * implied density ρ = m / V outside [density_min, density_max] (default 50 to 25 000 kg/m³: from foam
///    to above tungsten, 19 300 kg/m³);
///  * the tensor more than `ratio_limit` (default 10) times larger or smaller than the geometry's, compared
///    by the trace tr J (a rotation invariant: a units mistake, mm² for m², shows as 10⁶, a wrong mass
///    distribution as a large factor);
///  * the centre of mass outside the bounding box of the geometry (in the link frame, with a margin of 1e-9
///    of the box diagonal);
///  * a mass that is zero or negative (then the geometry checks are skipped).
/// Every warning is one line.
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/validity.hpp"
#include "poinsot/io/robot/robot_model.hpp"

namespace poinsot::io {

struct ModelCheckOptions {
  double density_min = 50.0;     ///< kg/m³
  double density_max = 25000.0;  ///< kg/m³
  double ratio_limit = 10.0;     ///< tr J vs tr J_geometry
  double validity_tolerance = inertia::kDefaultValidityTolerance;
  /// Resource limits of the meshes read for the geometry (see inertia/mesh_io.hpp).
  std::size_t max_mesh_bytes = std::size_t{256} << 20;
  std::size_t max_mesh_triangles = std::size_t{5'000'000};
};

/// The geometry of a link at the link's mass.
struct GeometryInertia {
  double volume = 0.0;            ///< m³
  inertia::MassProperties props;  ///< at the link's mass, link frame
  Vec3 box_min = Vec3::Zero();    ///< bounding box in the link frame (m)
  Vec3 box_max = Vec3::Zero();
  std::string source;  ///< "collision", "visual" or "geom"
};

struct LinkCheck {
  std::string name;
  int line = 0;      ///< line of the link (body) element in its file
  std::string file;  ///< the included file that holds it (MJCF <include>); "" for the model's own
  bool has_inertial = false;
  double mass = 0.0;                 ///< kg
  Vec3 com_link = Vec3::Zero();      ///< m
  Mat3 inertia_link = Mat3::Zero();  ///< about the centre of mass, link frame (kg·m²)
  inertia::PrincipalAxes principal;  ///< of inertia_link
  inertia::InertiaCheck validity;
  std::optional<inertia::InertiaRepair> repair;  ///< nearest valid tensor (link frame) when invalid
  std::optional<GeometryInertia> geometry;
  std::optional<double> implied_density;  ///< kg/m³
  std::optional<double> trace_ratio;      ///< tr J / tr J_geometry
  std::vector<std::string> warnings;      ///< one line each
  std::vector<std::string> notes;         ///< what the reader or the geometry skipped
};

struct ModelCheck {
  RobotFormat format = RobotFormat::urdf;
  std::string source;
  ModelCheckOptions options;
  std::vector<LinkCheck> links;
  std::size_t invalid = 0;   ///< links whose tensor is not physical
  std::size_t warnings = 0;  ///< warnings over all links
};

/// Checks every link of `model`. Throws InvalidInput for options out of range (density_min <= 0,
/// density_max < density_min, ratio_limit <= 1, non-finite values), and for a model with no link.
ModelCheck check_model(const RobotModel& model, const ModelCheckOptions& options = {});

/// The geometry of `link` at mass `mass` (> 0), or nothing when it has no usable shape; what could not be
/// used is appended to `notes`.
std::optional<GeometryInertia> geometry_inertia(const RobotLink& link, double mass,
                                                const ModelCheckOptions& options,
                                                std::vector<std::string>& notes);

/// The report as one JSON object (the one serialisation shared by the command line and Python): keys
/// format, source, options, invalid, warnings, links[] with name, line (file: the included file that holds
/// it, only then), has_inertial, mass, center_of_mass, inertia_com (link frame), principal_moments,
/// principal_axes, valid, condition, amount, message, repair {inertia, moments_before, moments_after,
/// distance} or null, geometry {source, volume, mass, center_of_mass, inertia_com, box_min, box_max} or null,
/// implied_density, trace_ratio, warnings, notes. Bytes of names that are not UTF-8 are replaced by U+FFFD; a
/// non-finite number is written as null.
std::string model_check_json(const ModelCheck& check);

/// The report as text for a terminal (one block per link).
std::string model_check_text(const ModelCheck& check);

}  // namespace poinsot::io
