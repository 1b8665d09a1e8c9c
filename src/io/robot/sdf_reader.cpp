// The SDF (Gazebo) reader of robot_model.hpp: every <link> of every <model> (nested models included), its
// <inertial> and its <collision>s (or <visual>s).
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "robot_readers.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

/// The <pose> child of `parent` (identity when absent): `x y z roll pitch yaw` (radians, or degrees with
/// degrees="true"), or `x y z qx qy qz qw` with rotation_format="quat_xyzw". Returns false (and notes it)
/// when the pose is relative to another frame than `own_frame` ("" accepts only the default).
bool read_pose(const XmlSource& xml, const XMLElement& parent, const std::string& own_frame, Mat3& R, Vec3& p,
               RobotLink& link) {
  R = Mat3::Identity();
  p = Vec3::Zero();
  const XMLElement* pose = parent.FirstChildElement("pose");
  if (pose == nullptr) return true;
  if (const char* rel = pose->Attribute("relative_to"); rel != nullptr && *rel != '\0' && own_frame != rel) {
    link.notes.push_back(
        fmt::format("{}: relative_to=\"{}\" not understood; skipped", xml.where(*pose), rel));
    return false;
  }
  const char* format = pose->Attribute("rotation_format");
  const bool quat = format != nullptr && std::string_view(format) == "quat_xyzw";
  if (format != nullptr && !quat && std::string_view(format) != "euler_rpy") {
    throw InvalidInput(
        fmt::format("{} rotation_format=\"{}\": expected euler_rpy or quat_xyzw", xml.where(*pose), format));
  }
  const char* text = pose->GetText();
  if (text == nullptr) return true;
  const std::vector<double> v = xml.numbers_text(*pose, quat ? 7 : 6);
  p = Vec3(v[0], v[1], v[2]);
  if (quat) {
    R = so3::rotation_from_quaternion(so3::quaternion_wxyz(v[6], v[3], v[4], v[5]));
  } else {
    const bool degrees = pose->BoolAttribute("degrees", false);
    const double unit = degrees ? std::numbers::pi / 180.0 : 1.0;
    R = rotation_from_rpy(unit * Vec3(v[3], v[4], v[5]), xml.where(*pose) + " roll, pitch, yaw");
  }
  return true;
}

void read_sdf_inertial(const XmlSource& xml, const XMLElement& inertial, RobotLink& link) {
  link.has_inertial = true;
  Mat3 R;
  if (!read_pose(xml, inertial, link.name, R, link.com_link, link)) {
    throw InvalidInput(fmt::format(
        "{}: <pose relative_to> another frame; expected a pose relative to the link", xml.where(inertial)));
  }
  link.R_link_inertial = R;
  link.mass = 1.0;  // SDF's default
  if (const XMLElement* mass = inertial.FirstChildElement("mass")) link.mass = xml.numbers_text(*mass, 1)[0];
  // SDF's defaults: ixx = iyy = izz = 1, products 0.
  static constexpr const char* names[6] = {"ixx", "ixy", "ixz", "iyy", "iyz", "izz"};
  double v[6] = {1.0, 0.0, 0.0, 1.0, 0.0, 1.0};
  std::vector<std::optional<TextSpan>> spans(6);
  if (const XMLElement* in = inertial.FirstChildElement("inertia")) {
    for (int k = 0; k < 6; ++k) {
      if (const XMLElement* e = in->FirstChildElement(names[k])) {
        v[k] = xml.numbers_text(*e, 1)[0];
        spans[static_cast<std::size_t>(k)] = xml.text_span(*e);
      }
    }
  }
  link.inertia_file = tensor_from_entries(v[0], v[3], v[5], v[1], v[2], v[4]);
  link.layout = TensorLayout::sdf_elements;
  set_spans(link, spans);
  finish_inertial(link);
}

double child_number(const XmlSource& xml, const XMLElement& shape, const char* name) {
  const XMLElement* e = shape.FirstChildElement(name);
  if (e == nullptr)
    throw InvalidInput(fmt::format("{}: no <{}>; expected its size (m)", xml.where(shape), name));
  return xml.numbers_text(*e, 1)[0];
}

Vec3 child_vector(const XmlSource& xml, const XMLElement& shape, const char* name) {
  const XMLElement* e = shape.FirstChildElement(name);
  if (e == nullptr)
    throw InvalidInput(fmt::format("{}: no <{}>; expected 3 numbers (m)", xml.where(shape), name));
  const std::vector<double> v = xml.numbers_text(*e, 3);
  return Vec3(v[0], v[1], v[2]);
}

std::string mesh_uri(const XmlSource& xml, const XMLElement& mesh) {
  const XMLElement* uri = mesh.FirstChildElement("uri");
  const char* file = uri != nullptr ? uri->GetText() : nullptr;
  if (file == nullptr)
    throw InvalidInput(fmt::format("{}: no <uri>; expected the mesh file", xml.where(mesh)));
  return file;
}

std::optional<Vec3> sdf_mesh_scale(const XmlSource& xml, const XMLElement& mesh) {
  if (mesh.FirstChildElement("scale") == nullptr) return std::nullopt;
  return child_vector(xml, mesh, "scale");
}

/// The pose of a <collision> or <visual> element: its <pose>, relative to the link.
bool read_geometry_pose(const XmlSource& xml, const XMLElement& holder, LinkGeometry& g, RobotLink& link) {
  return read_pose(xml, holder, link.name, g.R_link_geometry, g.position_link, link);
}

/// SDF writes a shape's fields as child elements: <box><size/></box>, <mesh><uri/><scale/></mesh>.
constexpr ShapeSyntax kSdfShapes{child_number, child_vector, mesh_uri, sdf_mesh_scale, true};

}  // namespace

void read_sdf(const XmlSource& xml, const std::string& base_dir, RobotModel& model) {
  // Every <link> whose parent is a <model>, in file order.
  std::vector<const XMLElement*> stack{xml.root()};
  std::vector<const XMLElement*> links;
  while (!stack.empty()) {
    const XMLElement* e = stack.back();
    stack.pop_back();
    if (std::string_view(e->Name()) == "link" && e->Parent() != nullptr &&
        e->Parent()->ToElement() != nullptr &&
        std::string_view(e->Parent()->ToElement()->Name()) == "model") {
      links.push_back(e);
      continue;
    }
    std::vector<const XMLElement*> children;
    for (const XMLElement* c = e->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
      children.push_back(c);
    for (auto it = children.rbegin(); it != children.rend(); ++it)
      stack.push_back(*it);
  }
  for (const XMLElement* e : links)
    model.links.push_back(
        read_link_element(xml, *e, base_dir, read_sdf_inertial, read_geometry_pose, kSdfShapes));
}

}  // namespace poinsot::io::detail
