// The MJCF kinematic tree of robot_kinematics.hpp: the <body> nesting with each body's pos and orientation,
// its <joint>s and <freejoint>, <equality><connect> and <weld>, <option gravity>; the joints' default
// classes (mjcf_defaults.hpp).
#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

#include "mjcf_defaults.hpp"
#include "mjcf_orientation.hpp"
#include "poinsot/core/error.hpp"
#include "robot_kinematics.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

Vec3 vec3_of(const std::vector<double>& v) {
  return Vec3(v[0], v[1], v[2]);
}

struct MjcfReader {
  const XmlSource& xml;
  const RobotModel& model;
  MjcfCompiler compiler;
  MjcfDefaults defaults;
  RobotTree tree;
  std::vector<const XMLElement*> body_elements;  // per link
  std::map<std::string, int, std::less<>> body_index;
  std::vector<std::string> limited, damped, rubbing, armatured;  // joint names, for the not-modelled lines

  MjcfReader(const XmlSource& x, const RobotModel& m)
      : xml(x), model(m), compiler(read_mjcf_compiler(x)), defaults(x) {}

  /// One <joint> of a body, with its class.
  RobotDof read_joint(const XMLElement& j, bool& free) {
    const MjcfAttributes a(xml, j, defaults.values(MjcfDefaults::class_of(j, true), "joint", j));
    const char* type_attr = a.get("type").text;
    const std::string type = type_attr != nullptr ? type_attr : "hinge";
    RobotDof d;
    const char* name = j.Attribute("name");
    d.name = name != nullptr ? name : fmt::format("joint_line{}", j.GetLineNum());
    d.line = j.GetLineNum();
    if (auto pos = a.numbers("pos", 3)) d.anchor_child = vec3_of(*pos);
    free = false;
    if (type == "hinge" || type == "slide") {
      d.kind = type == "hinge" ? RobotDof::Kind::hinge : RobotDof::Kind::slide;
      const Vec3 axis = a.numbers("axis", 3) ? vec3_of(*a.numbers("axis", 3)) : Vec3::UnitZ();
      d.axis_child = unit_axis_of(xml, j, "axis", axis);
    } else if (type == "ball") {
      d.kind = RobotDof::Kind::ball;
    } else if (type == "free") {
      free = true;
    } else {
      throw InvalidInput(fmt::format("{} {} type=\"{}\": expected hinge, slide, ball or free", xml.where(j),
                                     element_label(j), type));
    }
    const auto nonzero = [&](const char* key) {
      auto v = a.numbers(key, 1);
      return v && (*v)[0] != 0.0;
    };
    const char* lim = a.get("limited").text;
    if ((lim != nullptr && std::string_view(lim) == "true") ||
        (lim == nullptr && a.get("range").text != nullptr && !free))
      limited.push_back(d.name);
    if (type == "hinge" || type == "slide") {
      if (auto v = a.numbers("stiffness", 1)) d.stiffness = (*v)[0];
      if (auto v = a.numbers("damping", 1)) d.damping = (*v)[0];
      // ref and springref are in the compiler's angle unit for a hinge (as MuJoCo compiles qpos0 and
      // qpos_spring), m for a slide.
      const double unit = type == "hinge" ? compiler.angle_unit : 1.0;
      if (auto v = a.numbers("ref", 1)) d.reference = (*v)[0] * unit;
      if (auto v = a.numbers("springref", 1)) d.spring_reference = (*v)[0] * unit;
    } else if (nonzero("damping") || nonzero("stiffness")) {
      damped.push_back(d.name);
    }
    if (nonzero("frictionloss")) rubbing.push_back(d.name);
    if (nonzero("armature")) armatured.push_back(d.name);
    return d;
  }

  void read_body(const XMLElement& body, int parent) {
    const int index = static_cast<int>(body_elements.size());
    if (index >= static_cast<int>(model.links.size()))
      throw InvalidInput(fmt::format("{}: more bodies than the model read", xml.where(body)));
    body_elements.push_back(&body);
    tree.joint_of_link.push_back(-1);
    RigidPose pose;
    if (auto pos = xml.numbers_attribute(body, "pos", 3)) pose.p = vec3_of(*pos);
    pose.R = mjcf_orientation(xml, body, compiler);
    tree.root_pose.push_back(pose);
    if (const char* name = body.Attribute("name")) body_index.emplace(name, index);
    if (const XMLElement* c = body.FirstChildElement("composite"))
      throw InvalidInput(fmt::format("{}: not supported; expected bodies, joints and geoms", xml.where(*c)));

    RobotJointSpec spec;
    spec.child = index;
    spec.parent = parent;
    spec.parent_child = pose;
    spec.line = body.GetLineNum();
    const char* body_name = body.Attribute("name");
    spec.name = body_name != nullptr ? body_name : model.links[static_cast<std::size_t>(index)].name;
    spec.element = fmt::format("<body name=\"{}\">", spec.name);
    spec.kind = RobotJointKind::fixed;
    int free_count = 0;
    const XMLElement* free_element = nullptr;
    for (const XMLElement* j = body.FirstChildElement(); j != nullptr; j = j->NextSiblingElement()) {
      const std::string_view n = j->Name();
      if (n != "joint" && n != "freejoint") continue;
      bool free = n == "freejoint";
      RobotDof d;
      if (!free) d = read_joint(*j, free);
      if (free) {
        ++free_count;
        free_element = j;
        const char* jn = j->Attribute("name");
        spec.name = jn != nullptr ? jn : spec.name;
        continue;
      }
      if (spec.dofs.empty()) {
        spec.name = d.name;
        spec.element = fmt::format("<joint name=\"{}\">", d.name);
        spec.line = d.line;
      }
      spec.dofs.push_back(std::move(d));
    }
    if (free_count > 0) {
      if (free_count > 1 || !spec.dofs.empty() || parent >= 0) {
        throw InvalidInput(fmt::format(
            "{}: a free joint {}; expected it alone in a body of <worldbody>", xml.where(*free_element),
            parent >= 0 ? "in a body inside another body" : "with other joints in its body"));
      }
      spec.kind = RobotJointKind::free;
      spec.element =
          fmt::format("<freejoint> of <body name=\"{}\">", model.links[static_cast<std::size_t>(index)].name);
    } else if (!spec.dofs.empty()) {
      spec.kind = RobotJointKind::dofs;
    }
    tree.joint_of_link.back() = static_cast<int>(tree.joints.size());
    tree.joints.push_back(std::move(spec));
    for (const XMLElement* c = body.FirstChildElement("body"); c != nullptr;
         c = c->NextSiblingElement("body"))
      read_body(*c, index);
  }

  int named_body(const XMLElement& e, const char* attribute, bool world_allowed) const {
    const char* name = e.Attribute(attribute);
    if (name == nullptr) {
      if (world_allowed) return -1;
      throw InvalidInput(
          fmt::format("{}: missing attribute {}; expected the name of a body", xml.where(e), attribute));
    }
    if (world_allowed && std::string_view(name) == "world") return -1;
    const auto it = body_index.find(name);
    if (it == body_index.end()) {
      throw InvalidInput(fmt::format("{} {}=\"{}\": no such body; expected the name of a <body>",
                                     xml.where(e), attribute, name));
    }
    return it->second;
  }

  void read_equalities() {
    for (const XMLElement* eq = xml.root()->FirstChildElement("equality"); eq != nullptr;
         eq = eq->NextSiblingElement("equality")) {
      for (const XMLElement* e = eq->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
        const std::string_view kind = e->Name();
        if (kind != "connect" && kind != "weld") {
          throw InvalidInput(fmt::format(
              "{}: not supported; expected <connect> or <weld> (loop-closing joints)", xml.where(*e)));
        }
        if (const char* active = e->Attribute("active");
            active != nullptr && std::string_view(active) == "false") {
          tree.not_modelled.push_back(
              fmt::format("<{}> {}: inactive (active=\"false\"), left out", kind, xml.line_label(*e)));
          continue;
        }
        RobotLoopSpec loop;
        loop.weld = kind == "weld";
        loop.line = e->GetLineNum();
        const char* name = e->Attribute("name");
        loop.name = name != nullptr ? name : fmt::format("{}_line{}", kind, loop.line);
        loop.element = fmt::format("<{} {}>", kind, element_label(*e));
        loop.body1 = named_body(*e, "body1", false);
        loop.body2 = named_body(*e, "body2", true);
        if (auto anchor = xml.numbers_attribute(*e, "anchor", 3)) {
          loop.anchor1 = vec3_of(*anchor);
        } else if (!loop.weld) {
          throw InvalidInput(fmt::format(
              "{}: missing attribute anchor; expected 3 numbers (m, body1's frame)", xml.where(*e)));
        }
        if (e->Attribute("relpose") != nullptr || e->Attribute("torquescale") != nullptr) {
          throw InvalidInput(
              fmt::format("{}: relpose and torquescale are not supported; expected the relative "
                          "pose of the file's configuration",
                          xml.where(*e)));
        }
        tree.loops.push_back(std::move(loop));
      }
    }
  }

  void list(std::vector<std::string>& names, const char* what) {
    if (names.empty()) return;
    std::string shown;
    for (std::size_t k = 0; k < names.size() && k < 4; ++k)
      shown += (k > 0 ? ", " : "") + names[k];
    if (names.size() > 4) shown += ", ...";
    tree.not_modelled.push_back(fmt::format("<joint> {}: {} joint(s) ({})", what, names.size(), shown));
  }
};

}  // namespace

RobotTree read_mjcf_tree(const XmlSource& xml, const RobotModel& model) {
  MjcfReader r(xml, model);
  for (const XMLElement* w = xml.root()->FirstChildElement("worldbody"); w != nullptr;
       w = w->NextSiblingElement("worldbody")) {
    for (const XMLElement* c = w->FirstChildElement(); c != nullptr; c = c->NextSiblingElement()) {
      const std::string_view n = c->Name();
      if (n == "body") r.read_body(*c, -1);
      if (n == "composite" || n == "flexcomp")
        throw InvalidInput(
            fmt::format("{}: not supported; expected bodies, joints and geoms", xml.where(*c)));
    }
  }
  if (r.body_elements.size() != model.links.size())
    throw InvalidInput(fmt::format("{}: the bodies do not match the model's links", xml.where(*xml.root())));
  r.read_equalities();
  for (const XMLElement* o = xml.root()->FirstChildElement("option"); o != nullptr;
       o = o->NextSiblingElement("option")) {
    if (auto g = xml.numbers_attribute(*o, "gravity", 3)) {
      r.tree.has_gravity = true;
      r.tree.gravity = vec3_of(*g);
    }
  }
  if (!r.tree.has_gravity) r.tree.has_gravity = true;  // MuJoCo's default, (0, 0, −9.81)
  r.list(r.limited, "limits");
  r.list(r.damped, "damping and stiffness of a ball or free joint");
  r.list(r.rubbing, "friction loss");
  r.list(r.armatured, "armature");
  for (const char* other : {"actuator", "tendon", "contact"}) {
    if (const XMLElement* t = xml.root()->FirstChildElement(other);
        t != nullptr && t->FirstChildElement() != nullptr)
      r.tree.not_modelled.push_back(fmt::format("<{}> {}: {}", other, xml.line_label(*t),
                                                std::string_view(other) == "actuator" ? "actuators"
                                                : std::string_view(other) == "tendon"
                                                    ? "tendons"
                                                    : "contact pairs and exclusions"));
  }
  const bool geoms_always = r.compiler.inertiafromgeom == "true";
  const bool geoms_never = r.compiler.inertiafromgeom == "false";
  r.tree.inertia_from_geoms.resize(model.links.size());
  for (std::size_t k = 0; k < model.links.size(); ++k)
    r.tree.inertia_from_geoms[k] = geoms_always || (!geoms_never && !model.links[k].has_inertial);
  return std::move(r.tree);
}

}  // namespace poinsot::io::detail
