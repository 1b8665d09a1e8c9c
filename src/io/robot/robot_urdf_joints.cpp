// The URDF kinematic tree of robot_kinematics.hpp: every <joint type parent child origin axis>.
#include <map>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "robot_kinematics.hpp"
#include "robot_readers.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

/// The link named by <parent link=...> or <child link=...> of a joint.
int linked(const XmlSource& xml, const XMLElement& joint, const char* role,
           const std::map<std::string, int, std::less<>>& index) {
  const XMLElement* e = joint.FirstChildElement(role);
  const char* name = e != nullptr ? e->Attribute("link") : nullptr;
  if (name == nullptr) {
    throw InvalidInput(fmt::format("{} {}: no <{} link=\"...\"/>; expected the {} link's name",
                                   xml.where(joint), element_label(joint), role, role));
  }
  const auto it = index.find(name);
  if (it == index.end()) {
    throw InvalidInput(fmt::format("{} {}: <{} link=\"{}\">: no such link; expected one of the <link>s",
                                   xml.where(joint), element_label(joint), role, name));
  }
  return it->second;
}

}  // namespace

std::string element_label(const tinyxml2::XMLElement& e) {
  const char* name = e.Attribute("name");
  return name != nullptr ? fmt::format("name=\"{}\"", name) : std::string("(unnamed)");
}

Vec3 unit_axis_of(const XmlSource& xml, const tinyxml2::XMLElement& e, const char* what, const Vec3& v) {
  const double n = v.norm();
  if (!(n > 0.0)) {
    throw InvalidInput(
        fmt::format("{} {} {}: zero length; expected a non-zero axis", xml.where(e), element_label(e), what));
  }
  return v / n;
}

RobotTree read_urdf_tree(const XmlSource& xml, const RobotModel& model) {
  RobotTree tree;
  const std::size_t n = model.links.size();
  tree.joint_of_link.assign(n, -1);
  tree.root_pose.assign(n, RigidPose{});
  std::map<std::string, int, std::less<>> index;
  for (std::size_t k = 0; k < n; ++k)
    index.emplace(model.links[k].name, static_cast<int>(k));
  for (const XMLElement* e = xml.root()->FirstChildElement("joint"); e != nullptr;
       e = e->NextSiblingElement("joint")) {
    RobotJointSpec j;
    const char* name = e->Attribute("name");
    if (name == nullptr)
      throw InvalidInput(fmt::format("{}: missing attribute name; expected the joint's name", xml.where(*e)));
    j.name = name;
    j.element = fmt::format("<joint name=\"{}\">", name);
    j.line = e->GetLineNum();
    j.parent = linked(xml, *e, "parent", index);
    j.child = linked(xml, *e, "child", index);
    const int previous = tree.joint_of_link[static_cast<std::size_t>(j.child)];
    if (previous >= 0 || j.child == j.parent) {
      throw InvalidInput(fmt::format(
          "{} {}: link \"{}\" is already the child of <joint name=\"{}\"> (line {}): a kinematic loop; "
          "expected a tree (each link the child of one joint)",
          xml.where(*e), element_label(*e), model.links[static_cast<std::size_t>(j.child)].name,
          previous >= 0 ? tree.joints[static_cast<std::size_t>(previous)].name : j.name,
          previous >= 0 ? tree.joints[static_cast<std::size_t>(previous)].line : j.line));
    }
    if (const XMLElement* origin = e->FirstChildElement("origin")) {
      if (auto xyz = xml.numbers_attribute(*origin, "xyz", 3))
        j.parent_child.p = Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]);
      if (auto rpy = xml.numbers_attribute(*origin, "rpy", 3))
        j.parent_child.R =
            rotation_from_rpy(Vec3((*rpy)[0], (*rpy)[1], (*rpy)[2]), xml.where(*origin) + " rpy");
    }
    const char* type_attr = e->Attribute("type");
    const std::string type = type_attr != nullptr ? type_attr : "";
    // URDF's axis is in the joint frame, which is the child's frame; default (1, 0, 0).
    Vec3 axis = Vec3::UnitX();
    if (const XMLElement* a = e->FirstChildElement("axis")) {
      if (auto xyz = xml.numbers_attribute(*a, "xyz", 3)) axis = Vec3((*xyz)[0], (*xyz)[1], (*xyz)[2]);
    }
    if (type == "revolute" || type == "continuous" || type == "prismatic") {
      RobotDof d;
      d.kind = type == "prismatic" ? RobotDof::Kind::slide : RobotDof::Kind::hinge;
      d.name = j.name;
      d.line = j.line;
      d.axis_child = unit_axis_of(xml, *e, "<axis xyz>", axis);
      j.kind = RobotJointKind::dofs;
      j.dofs.push_back(d);
      if (type != "continuous" && e->FirstChildElement("limit") != nullptr)
        tree.not_modelled.push_back(fmt::format("{} line {}: joint limits", j.element, j.line));
    } else if (type == "fixed") {
      j.kind = RobotJointKind::fixed;
    } else if (type == "floating") {
      j.kind = RobotJointKind::free;
    } else {
      throw InvalidInput(
          fmt::format("{} {} type=\"{}\": not supported; expected revolute, continuous, "
                      "prismatic, fixed or floating",
                      xml.where(*e), element_label(*e), type));
    }
    if (const XMLElement* dyn = e->FirstChildElement("dynamics")) {
      // <dynamics damping> of a revolute or prismatic joint is a joint damper (N·m·s/rad or N·s/m); its
      // Coulomb friction is not modelled.
      if (auto damping = xml.numbers_attribute(*dyn, "damping", 1); damping && !j.dofs.empty())
        j.dofs.front().damping = (*damping)[0];
      if (auto friction = xml.numbers_attribute(*dyn, "friction", 1); friction && (*friction)[0] != 0.0)
        tree.not_modelled.push_back(
            fmt::format("{} line {}: <dynamics friction> (joint friction)", j.element, j.line));
    }
    if (e->FirstChildElement("mimic") != nullptr)
      tree.not_modelled.push_back(fmt::format("{} line {}: <mimic> (joint coupling)", j.element, j.line));
    tree.joint_of_link[static_cast<std::size_t>(j.child)] = static_cast<int>(tree.joints.size());
    tree.joints.push_back(std::move(j));
  }
  for (const char* other : {"transmission", "gazebo"}) {
    if (const XMLElement* t = xml.root()->FirstChildElement(other)) {
      tree.not_modelled.push_back(fmt::format("<{}> line {}: {}", other, t->GetLineNum(),
                                              std::string_view(other) == "transmission"
                                                  ? "transmissions and actuators"
                                                  : "simulator extensions"));
    }
  }
  return tree;
}

}  // namespace poinsot::io::detail
