#pragma once
/// @file body_file.hpp
/// Composite bodies described in a TOML file: parts (shapes or meshes) placed with a pose, minus voids.
///
/// Format (SI units: m, kg, kg/m³; kg/m² for plates and thin shells, kg/m for rods):
///
///     [[part]]                       # a solid part; repeat for more
///     shape = "box"                  # point, rod, plate, box, sphere, cylinder, cone, ellipsoid, capsule,
///     torus size = [0.3, 0.1, 0.02]        # fields as in ShapeSpec (shapes.hpp): size, radius, length,
///     height,
///                                    # inner_radius, major_radius, minor_radius, hollow
///     mass = 0.4                     # or density = 2700
///     position = [0.0, 0.0, 0.1]     # where the part's origin lies in the body frame (m); default 0
///     quaternion = [1, 0, 0, 0]      # orientation, w x y z; or axis_angle = [x, y, z, angle],
///                                    # or euler = [a1, a2, a3] with euler_sequence = "ZYX"; degrees = true
///
///     [[part]]
///     mesh = "bracket.stl"           # relative to the TOML file's folder
///     density = 7800                 # or mass; shell = 0.002 (a thickness, m) for a surface mesh;
///     flip_inward = false            # flip an inward mesh instead of rejecting it
///
///     [[void]]                       # removed material (a hole): same fields, with the density or mass of
///     shape = "cylinder"             # the material that is not there
///     radius = 0.01
///     length = 0.02
///     density = 2700
///
/// A shape's origin is its centre of mass with its axis along z (shapes.hpp); a mesh's origin is that of its
/// file. The composite is the sum of the parts minus the voids (mass_properties.hpp), in the body frame.

#include <string>
#include <vector>

#include "poinsot/inertia/mass_properties.hpp"

namespace poinsot::inertia {

/// The composite and what was found on the way.
struct BodyFileResult {
  MassProperties body;                   ///< in the body frame
  std::vector<std::string> diagnostics;  ///< per part, e.g. "part 2 (mesh a.stl): shells: 2"
  std::size_t parts = 0;
  std::size_t voids = 0;
};

/// Reads and evaluates a body file. Throws InvalidInput for an unreadable file, a TOML syntax error (with its
/// line), an unknown key or shape, a missing or doubled mass/density, bad sizes, or a composite whose mass is
/// not positive; each message names the part ("part 2", "void 1") and the field.
BodyFileResult load_body_file(const std::string& path);

/// The same from TOML text; mesh paths are relative to `base_dir`.
BodyFileResult parse_body(const std::string& toml_text, const std::string& base_dir = ".");

}  // namespace poinsot::inertia
