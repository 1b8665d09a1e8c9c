// geometry_inertia of model_check.hpp: the mass properties and bounding box of a link's shapes and meshes.
#include <limits>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/io/robot/model_check.hpp"

namespace poinsot::io {
namespace {

/// Half-extents of a shape about its own origin, in its own frame (m).
Vec3 half_extents(const inertia::ShapeSpec& s) {
  if (s.kind == "box") return s.size / 2.0;
  if (s.kind == "sphere") return Vec3::Constant(s.radius);
  if (s.kind == "cylinder") return Vec3(s.radius, s.radius, s.length / 2.0);
  if (s.kind == "capsule") return Vec3(s.radius, s.radius, s.length / 2.0 + s.radius);
  return s.size;  // ellipsoid: the semi-axes
}

struct Part {
  inertia::MassProperties props;  // at unit density: mass = volume (m³), link frame
  Vec3 box_min;
  Vec3 box_max;
};

std::optional<Part> shape_part(const LinkGeometry& g) {
  Part part;
  part.props = inertia::shape_with_density(g.shape, 1.0).placed(g.R_link_geometry, g.position_link);
  const Vec3 h = g.R_link_geometry.cwiseAbs() * half_extents(g.shape);
  part.box_min = g.position_link - h;
  part.box_max = g.position_link + h;
  return part;
}

std::optional<Part> mesh_part(const LinkGeometry& g, const ModelCheckOptions& options) {
  inertia::MeshLimits limits;
  limits.max_file_bytes = options.max_mesh_bytes;
  limits.max_triangles = options.max_mesh_triangles;
  inertia::TriangleMesh mesh = inertia::load_mesh(g.mesh_path, limits);
  for (Vec3& v : mesh.vertices)
    v = g.mesh_scale.cwiseProduct(v);
  if (g.mesh_scale.prod() < 0.0) inertia::flip_orientation(mesh);  // a reflection reverses the winding
  Part part;
  part.props = inertia::mesh_mass_properties(mesh, 1.0).placed(g.R_link_geometry, g.position_link);
  part.box_min = Vec3::Constant(std::numeric_limits<double>::infinity());
  part.box_max = -part.box_min;
  for (const Vec3& v : mesh.vertices) {
    const Vec3 x = g.R_link_geometry * v + g.position_link;
    part.box_min = part.box_min.cwiseMin(x);
    part.box_max = part.box_max.cwiseMax(x);
  }
  return part;
}

}  // namespace

std::optional<GeometryInertia> geometry_inertia(const RobotLink& link, double mass,
                                                const ModelCheckOptions& options,
                                                std::vector<std::string>& notes) {
  std::vector<Part> parts;
  for (const LinkGeometry& g : link.geometry) {
    try {
      parts.push_back(*(g.shape.kind == "mesh" ? mesh_part(g, options) : shape_part(g)));
    } catch (const InvalidInput& e) {
      notes.push_back(fmt::format("{} {} skipped: {}", g.element, g.shape.kind, e.what()));
    }
  }
  if (parts.empty()) return std::nullopt;
  GeometryInertia out;
  out.source = link.geometry.front().element;
  inertia::MassProperties unit = parts.front().props;
  out.box_min = parts.front().box_min;
  out.box_max = parts.front().box_max;
  for (std::size_t k = 1; k < parts.size(); ++k) {
    unit = inertia::combine(unit, parts[k].props);
    out.box_min = out.box_min.cwiseMin(parts[k].box_min);
    out.box_max = out.box_max.cwiseMax(parts[k].box_max);
  }
  out.volume = unit.mass;
  // Uniform density ρ = m / V: mass and tensor scale by ρ, the centre of mass stays.
  const double rho = mass / out.volume;
  out.props = unit;
  out.props.mass = mass;
  out.props.inertia_com = rho * unit.inertia_com;
  return out;
}

}  // namespace poinsot::io
