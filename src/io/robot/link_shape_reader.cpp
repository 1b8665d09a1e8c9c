// The <collision>/<visual> shape reader shared by the URDF and SDF readers (robot_readers.hpp): the kinds of
// shape and what each needs are the same in both formats; only how a field is written differs (ShapeSyntax).
#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "robot_readers.hpp"

namespace poinsot::io::detail {

void read_link_shape(const XmlSource& xml, const tinyxml2::XMLElement& holder, const std::string& base_dir,
                     GeometryPoseReader read_pose, const ShapeSyntax& syntax, RobotLink& link) {
  LinkGeometry g;
  g.element = holder.Name();
  if (!read_pose(xml, holder, g, link)) return;
  const tinyxml2::XMLElement* geometry = holder.FirstChildElement("geometry");
  const tinyxml2::XMLElement* shape = geometry != nullptr ? geometry->FirstChildElement() : nullptr;
  if (shape == nullptr) {
    link.notes.push_back(fmt::format("{}: no <geometry> shape; skipped", xml.where(holder)));
    return;
  }
  const std::string kind = shape->Name();
  if (kind == "box") {
    g.shape.kind = "box";
    g.shape.size = syntax.lengths(xml, *shape, "size");
  } else if (kind == "sphere") {
    g.shape.kind = "sphere";
    g.shape.radius = syntax.length(xml, *shape, "radius");
  } else if (kind == "cylinder" || kind == "capsule") {
    g.shape.kind = kind;
    g.shape.radius = syntax.length(xml, *shape, "radius");
    g.shape.length = syntax.length(xml, *shape, "length");
  } else if (kind == "ellipsoid" && syntax.has_ellipsoid) {
    g.shape.kind = "ellipsoid";
    g.shape.size = syntax.lengths(xml, *shape, "radii");
  } else if (kind == "mesh") {
    g.shape.kind = "mesh";
    const std::string file = syntax.mesh_uri(xml, *shape);
    g.mesh_path = resolve_mesh_path(file, base_dir);
    if (g.mesh_path.empty()) {
      link.notes.push_back(fmt::format("{}: mesh \"{}\" not found; skipped", xml.where(*shape), file));
      return;
    }
    if (auto scale = syntax.mesh_scale(xml, *shape)) g.mesh_scale = *scale;
  } else {
    link.notes.push_back(fmt::format("{}: geometry <{}> not understood; skipped", xml.where(*shape), kind));
    return;
  }
  link.geometry.push_back(std::move(g));
}

}  // namespace poinsot::io::detail
