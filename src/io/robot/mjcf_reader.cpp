// The MJCF (MuJoCo) reader of robot_model.hpp: every <body> under <worldbody>, its <inertial> and <geom>s,
// the geoms and mesh assets with their default classes (mjcf_defaults.hpp).
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>

#include "mjcf_defaults.hpp"
#include "mjcf_orientation.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "robot_readers.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

/// The orientation attributes MJCF allows besides quat; their meaning depends on <compiler angle eulerseq>.
constexpr const char* kOtherOrientations[] = {"axisangle", "euler", "xyaxes", "zaxis"};

/// The rotation of quaternion `q` (w x y z, normalised here) written by `e`; identity when absent.
Mat3 rotation_of_quat(const XmlSource& xml, const XMLElement& e,
                      const std::optional<std::vector<double>>& q) {
  if (!q) return Mat3::Identity();
  const double norm =
      std::sqrt((*q)[0] * (*q)[0] + (*q)[1] * (*q)[1] + (*q)[2] * (*q)[2] + (*q)[3] * (*q)[3]);
  if (!(norm > 0.0))
    throw InvalidInput(fmt::format("{} quat: zero quaternion; expected w x y z, not all 0", xml.where(e)));
  return so3::rotation_from_quaternion(so3::quaternion_wxyz((*q)[0], (*q)[1], (*q)[2], (*q)[3]));
}

void read_mjcf_inertial(const XmlSource& xml, const XMLElement& inertial, RobotLink& link) {
  link.has_inertial = true;
  for (const char* other : kOtherOrientations) {
    if (inertial.Attribute(other) != nullptr) {
      throw InvalidInput(
          fmt::format("{}: orientation given by {}; expected quat (w x y z)", xml.where(inertial), other));
    }
  }
  if (auto pos = xml.numbers_attribute(inertial, "pos", 3))
    link.com_link = Vec3((*pos)[0], (*pos)[1], (*pos)[2]);
  auto mass = xml.numbers_attribute(inertial, "mass", 1);
  if (!mass)
    throw InvalidInput(
        fmt::format("{}: missing attribute mass; expected the body's mass (kg)", xml.where(inertial)));
  link.mass = (*mass)[0];
  link.R_link_inertial = rotation_of_quat(xml, inertial, xml.numbers_attribute(inertial, "quat", 4));
  auto diag = xml.numbers_attribute(inertial, "diaginertia", 3);
  auto full = xml.numbers_attribute(inertial, "fullinertia", 6);
  if (diag.has_value() == full.has_value()) {
    throw InvalidInput(
        fmt::format("{}: expected exactly one of diaginertia (3 numbers) or fullinertia (6 numbers)",
                    xml.where(inertial)));
  }
  if (diag) {
    link.inertia_file = tensor_from_entries((*diag)[0], (*diag)[1], (*diag)[2], 0.0, 0.0, 0.0);
    link.layout = TensorLayout::mjcf_diag;
    set_spans(link, {xml.attribute_span(inertial, "diaginertia")});
  } else {
    const auto& f = *full;
    link.inertia_file = tensor_from_entries(f[0], f[1], f[2], f[3], f[4], f[5]);
    link.layout = TensorLayout::mjcf_full;
    set_spans(link, {xml.attribute_span(inertial, "fullinertia")});
  }
  finish_inertial(link);
}

/// A rotation whose z axis is the unit vector `z` (for fromto: the shapes are symmetric about z).
Mat3 frame_with_z(const Vec3& z) {
  const Vec3 helper = std::abs(z.x()) < 0.9 ? Vec3::UnitX() : Vec3::UnitY();
  const Vec3 x = helper.cross(z).normalized();
  Mat3 R;
  R.col(0) = x;
  R.col(1) = z.cross(x);
  R.col(2) = z;
  return R;
}

struct MeshAssets {
  std::map<std::string, std::pair<std::string, Vec3>> files;  // name -> (file reference, scale)
  std::string dir;                                            // folder of the mesh files
};

MeshAssets read_assets(const XmlSource& xml, const MjcfDefaults& defaults, const std::string& base_dir) {
  MeshAssets a;
  a.dir = base_dir;
  for (const XMLElement* c = xml.root()->FirstChildElement("compiler"); c != nullptr;
       c = c->NextSiblingElement("compiler")) {
    const char* dir = c->Attribute("meshdir");
    if (dir == nullptr) dir = c->Attribute("assetdir");
    if (dir != nullptr) {
      const std::filesystem::path p(dir);
      a.dir = p.is_absolute() ? p.string() : (std::filesystem::path(base_dir) / p).string();
    }
  }
  for (const XMLElement* asset = xml.root()->FirstChildElement("asset"); asset != nullptr;
       asset = asset->NextSiblingElement("asset")) {
    for (const XMLElement* m = asset->FirstChildElement("mesh"); m != nullptr;
         m = m->NextSiblingElement("mesh")) {
      const char* file = m->Attribute("file");
      if (file == nullptr) continue;
      const char* name = m->Attribute("name");
      const std::string key = name != nullptr ? name : std::filesystem::path(file).stem().string();
      const MjcfAttributes attributes(xml, *m,
                                      defaults.values(MjcfDefaults::class_of(*m, false), "mesh", *m));
      Vec3 scale = Vec3::Ones();
      if (auto s = attributes.numbers("scale", 3)) scale = Vec3((*s)[0], (*s)[1], (*s)[2]);
      a.files[key] = {file, scale};
    }
  }
  return a;
}

void read_geom(const XmlSource& xml, const XMLElement& geom, const MjcfDefaults& defaults,
               const MjcfCompiler& compiler, const MeshAssets& assets, RobotLink& link) {
  LinkGeometry g;
  g.element = "geom";
  const MjcfAttributes attributes(xml, geom,
                                  defaults.values(MjcfDefaults::class_of(geom, true), "geom", geom));
  const char* type_attr = attributes.get("type").text;
  const std::string type = type_attr != nullptr ? type_attr : "sphere";
  if (auto density = attributes.numbers("density", 1)) g.density = (*density)[0];
  if (auto mass = attributes.numbers("mass", 1)) g.mass = (*mass)[0];
  if (type == "mesh") {
    const char* mesh = attributes.get("mesh").text;
    const auto it = mesh != nullptr ? assets.files.find(mesh) : assets.files.end();
    if (it == assets.files.end()) {
      link.notes.push_back(fmt::format("{}: mesh asset not found; skipped", xml.where(geom)));
      return;
    }
    g.shape.kind = "mesh";
    g.mesh_path = resolve_mesh_path(it->second.first, assets.dir);
    g.mesh_scale = it->second.second;
    if (g.mesh_path.empty()) {
      link.notes.push_back(
          fmt::format("{}: mesh file \"{}\" not found; skipped", xml.where(geom), it->second.first));
      return;
    }
    // MuJoCo moves a mesh to its centre of mass and principal axes before placing it; not reproduced.
    link.notes.push_back(
        fmt::format("{}: mesh placed in its file's own frame (MuJoCo re-centres meshes)", xml.where(geom)));
  } else if (type == "sphere" || type == "capsule" || type == "cylinder" || type == "box" ||
             type == "ellipsoid") {
    const char* size_attr = attributes.get("size").text;
    auto size = parse_numbers(size_attr != nullptr ? size_attr : "");
    const std::size_t needed = type == "sphere" ? 1 : (type == "capsule" || type == "cylinder") ? 2 : 3;
    auto fromto = attributes.numbers("fromto", 6);
    const std::size_t given = size ? size->size() : 0;
    if (given < (fromto ? 1 : needed)) {
      link.notes.push_back(fmt::format("{}: {} without size; skipped", xml.where(geom), type));
      return;
    }
    const auto& s = *size;
    g.shape.kind = type;
    if (type == "sphere") {
      g.shape.radius = s[0];
    } else if (type == "capsule" || type == "cylinder") {
      g.shape.radius = s[0];
      g.shape.length = fromto ? 0.0 : 2.0 * s[1];
    } else if (type == "box") {
      g.shape.size = 2.0 * Vec3(s[0], s[1], s[2]);
    } else {
      g.shape.size = Vec3(s[0], s[1], s[2]);
    }
    if (fromto) {
      if (type != "capsule" && type != "cylinder") {
        link.notes.push_back(fmt::format("{}: {} with fromto; skipped", xml.where(geom), type));
        return;
      }
      const Vec3 a((*fromto)[0], (*fromto)[1], (*fromto)[2]);
      const Vec3 b((*fromto)[3], (*fromto)[4], (*fromto)[5]);
      g.shape.length = (b - a).norm();
      if (!(g.shape.length > 0.0)) {
        link.notes.push_back(fmt::format("{}: fromto of zero length; skipped", xml.where(geom)));
        return;
      }
      g.position_link = (a + b) / 2.0;
      g.R_link_geometry = frame_with_z((b - a) / g.shape.length);
      link.geometry.push_back(std::move(g));
      return;
    }
  } else {
    return;  // plane, hfield, sdf: no volume of a link
  }
  if (auto pos = attributes.numbers("pos", 3)) g.position_link = Vec3((*pos)[0], (*pos)[1], (*pos)[2]);
  g.R_link_geometry = mjcf_orientation(xml, geom, compiler, [&](const char* name, std::size_t count) {
    return attributes.numbers(name, count);
  });
  link.geometry.push_back(std::move(g));
}

}  // namespace

void read_mjcf(const XmlSource& xml, const std::string& base_dir, RobotModel& model) {
  const MjcfDefaults defaults(xml);
  const MjcfCompiler compiler = read_mjcf_compiler(xml);
  const MeshAssets assets = read_assets(xml, defaults, base_dir);
  std::vector<const XMLElement*> stack;
  for (const XMLElement* w = xml.root()->FirstChildElement("worldbody"); w != nullptr;
       w = w->NextSiblingElement("worldbody"))
    stack.push_back(w);
  std::vector<const XMLElement*> bodies;
  while (!stack.empty()) {  // pre-order, file order
    const XMLElement* e = stack.back();
    stack.pop_back();
    if (std::string_view(e->Name()) == "body") bodies.push_back(e);
    std::vector<const XMLElement*> children;
    for (const XMLElement* c = e->FirstChildElement("body"); c != nullptr; c = c->NextSiblingElement("body"))
      children.push_back(c);
    for (auto it = children.rbegin(); it != children.rend(); ++it)
      stack.push_back(*it);
  }
  for (const XMLElement* e : bodies) {
    RobotLink link;
    const char* name = e->Attribute("name");
    link.name = name != nullptr ? name : fmt::format("(body at {})", xml.line_label(*e));
    link.line = e->GetLineNum();
    if (const XMLElement* inertial = e->FirstChildElement("inertial"))
      read_mjcf_inertial(xml, *inertial, link);
    for (const XMLElement* g = e->FirstChildElement("geom"); g != nullptr; g = g->NextSiblingElement("geom"))
      read_geom(xml, *g, defaults, compiler, assets, link);
    model.links.push_back(std::move(link));
  }
}

}  // namespace poinsot::io::detail
