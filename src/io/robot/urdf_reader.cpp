// The URDF reader of robot_model.hpp: <robot><link name><inertial>, <collision>, <visual>.
#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "robot_readers.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

/// Pose of an <origin xyz rpy/> child of `parent` (identity when absent).
void read_origin(const XmlSource& xml, const XMLElement& parent, Mat3& R, Vec3& p) {
  R = Mat3::Identity();
  p = Vec3::Zero();
  const XMLElement* origin = parent.FirstChildElement("origin");
  if (origin == nullptr) return;
  if (auto xyz = xml.numbers_attribute(*origin, "xyz", 3)) p = Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]);
  if (auto rpy = xml.numbers_attribute(*origin, "rpy", 3))
    R = rotation_from_rpy(Vec3((*rpy)[0], (*rpy)[1], (*rpy)[2]), xml.where(*origin) + " rpy");
}

double required_number(const XmlSource& xml, const XMLElement& e, const char* attribute) {
  auto v = xml.numbers_attribute(e, attribute, 1);
  if (!v)
    throw InvalidInput(fmt::format("{}: missing attribute {}; expected a number", xml.where(e), attribute));
  return (*v)[0];
}

void read_urdf_inertial(const XmlSource& xml, const XMLElement& inertial, RobotLink& link) {
  link.has_inertial = true;
  Mat3 R;
  read_origin(xml, inertial, R, link.com_link);
  link.R_link_inertial = R;
  const XMLElement* mass = inertial.FirstChildElement("mass");
  if (mass == nullptr)
    throw InvalidInput(
        fmt::format("{}: no <mass value/>; expected the link's mass (kg)", xml.where(inertial)));
  link.mass = required_number(xml, *mass, "value");
  const XMLElement* in = inertial.FirstChildElement("inertia");
  if (in == nullptr) {
    throw InvalidInput(fmt::format("{}: no <inertia ixx ixy ixz iyy iyz izz/>; expected the tensor (kg·m²)",
                                   xml.where(inertial)));
  }
  static constexpr const char* names[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  double v[6];
  std::vector<std::optional<TextSpan>> spans;
  for (int k = 0; k < 6; ++k) {
    v[k] = required_number(xml, *in, names[k]);
    spans.push_back(xml.attribute_span(*in, names[k]));
  }
  link.inertia_file = tensor_from_entries(v[0], v[3], v[5], v[1], v[2], v[4]);
  link.layout = TensorLayout::urdf_attributes;
  set_spans(link, spans);
  finish_inertial(link);
}

/// The pose of a <collision> or <visual> element: its <origin> (always read).
bool read_geometry_origin(const XmlSource& xml, const XMLElement& holder, LinkGeometry& g, RobotLink&) {
  read_origin(xml, holder, g.R_link_geometry, g.position_link);
  return true;
}

Vec3 required_lengths(const XmlSource& xml, const XMLElement& shape, const char* attribute) {
  auto v = xml.numbers_attribute(shape, attribute, 3);
  if (!v) {
    throw InvalidInput(
        fmt::format("{}: missing attribute {}; expected 3 numbers (m)", xml.where(shape), attribute));
  }
  return Vec3((*v)[0], (*v)[1], (*v)[2]);
}

std::string mesh_filename(const XmlSource& xml, const XMLElement& mesh) {
  const char* file = mesh.Attribute("filename");
  if (file == nullptr) {
    throw InvalidInput(
        fmt::format("{}: missing attribute filename; expected the mesh file", xml.where(mesh)));
  }
  return file;
}

std::optional<Vec3> urdf_mesh_scale(const XmlSource& xml, const XMLElement& mesh) {
  if (auto scale = xml.numbers_attribute(mesh, "scale", 3))
    return Vec3((*scale)[0], (*scale)[1], (*scale)[2]);
  return std::nullopt;
}

/// URDF writes a shape's fields as attributes: <box size/>, <cylinder radius length/>, <mesh filename
/// scale/>.
constexpr ShapeSyntax kUrdfShapes{required_number, required_lengths, mesh_filename, urdf_mesh_scale, false};

}  // namespace

void read_urdf(const XmlSource& xml, const std::string& base_dir, RobotModel& model) {
  for (const XMLElement* e = xml.root()->FirstChildElement("link"); e != nullptr;
       e = e->NextSiblingElement("link")) {
    model.links.push_back(
        read_link_element(xml, *e, base_dir, read_urdf_inertial, read_geometry_origin, kUrdfShapes));
  }
}

}  // namespace poinsot::io::detail
