// The SDF kinematic tree of robot_kinematics.hpp: the links' poses in their model (nested models composed;
// poses `relative_to` the model's links, joints and <frame>s), every <joint type><parent><child><pose><axis>
// <axis2>, <world><gravity>.
#include <algorithm>
#include <map>
#include <memory>
#include <numbers>
#include <string_view>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "robot_kinematics.hpp"
#include "robot_readers.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

std::string child_text(const XMLElement& e, const char* name) {
  const XMLElement* c = e.FirstChildElement(name);
  const char* t = c != nullptr ? c->GetText() : nullptr;
  return t != nullptr ? std::string(t) : std::string();
}

/// The <pose> child of `e` as written: the pose, and the frame it is relative to ("" when none is named).
struct WrittenPose {
  RigidPose pose;
  std::string relative_to;
};

WrittenPose written_pose(const XmlSource& xml, const XMLElement& e) {
  WrittenPose out;
  const XMLElement* p = e.FirstChildElement("pose");
  if (p == nullptr) return out;
  if (const char* rel = p->Attribute("relative_to")) out.relative_to = rel;
  if (p->GetText() == nullptr) return out;
  const char* format = p->Attribute("rotation_format");
  const bool quat = format != nullptr && std::string_view(format) == "quat_xyzw";
  const std::vector<double> v = xml.numbers_text(*p, quat ? 7 : 6);
  out.pose.p = Vec3(v[0], v[1], v[2]);
  if (quat) {
    out.pose.R = so3::rotation_from_quaternion(so3::quaternion_wxyz(v[6], v[3], v[4], v[5]));
  } else {
    const double unit = p->BoolAttribute("degrees", false) ? std::numbers::pi / 180.0 : 1.0;
    out.pose.R = rotation_from_rpy(unit * Vec3(v[3], v[4], v[5]), xml.where(*p) + " roll, pitch, yaw");
  }
  return out;
}

/// A <model>'s pose in its parent's frame; `relative_to` another frame is refused.
RigidPose model_pose_of(const XmlSource& xml, const XMLElement& model) {
  const WrittenPose w = written_pose(xml, model);
  if (!w.relative_to.empty() && w.relative_to != "__model__") {
    throw InvalidInput(
        fmt::format("{} relative_to=\"{}\": not supported for a model; expected a pose in its "
                    "parent's frame",
                    xml.where(*model.FirstChildElement("pose")), w.relative_to));
  }
  return w.pose;
}

/// The frames of one <model> (SDF 1.7): each link, joint and <frame> by name, and each one's pose in the
/// model's frame, following `relative_to` through the others. A pose without `relative_to` is in the frame
/// SDF implies: the model's for a link, the child link's for a joint, the `attached_to` frame's (else the
/// model's) for a <frame>; `__model__` names the model's frame.
class SdfModelFrames {
 public:
  SdfModelFrames(const XmlSource& xml, const XMLElement& model) : xml_(xml) {
    for (const XMLElement* e = model.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string_view n = e->Name();
      if (n != "link" && n != "joint" && n != "frame") continue;
      if (const char* name = e->Attribute("name")) by_name_.emplace(name, e);
    }
  }

  /// The pose of `e` (a link, joint or frame of this model) in the model's frame. Throws InvalidInput naming
  /// the <pose> for a `relative_to` that names no frame of the model, or a chain of them that comes back.
  RigidPose in_model(const XMLElement& e) const {
    std::vector<const XMLElement*> chain;
    return resolve(e, chain);
  }

 private:
  RigidPose resolve(const XMLElement& e, std::vector<const XMLElement*>& chain) const {
    if (const auto it = cache_.find(&e); it != cache_.end()) return it->second;
    const XMLElement* pose = e.FirstChildElement("pose");
    if (std::find(chain.begin(), chain.end(), &e) != chain.end()) {
      throw InvalidInput(
          fmt::format("{} {}: its pose is relative to a chain of frames that comes back to it; "
                      "expected the chain to end at the model's frame",
                      xml_.where(e), element_label(e)));
    }
    chain.push_back(&e);
    const WrittenPose w = written_pose(xml_, e);
    std::string base = w.relative_to;
    if (base.empty() && std::string_view(e.Name()) == "joint") base = child_text(e, "child");
    if (base.empty() && std::string_view(e.Name()) == "frame" && e.Attribute("attached_to") != nullptr)
      base = e.Attribute("attached_to");
    RigidPose frame;  // the model's
    if (!base.empty() && base != "__model__") {
      const auto it = by_name_.find(base);
      if (it == by_name_.end()) {
        throw InvalidInput(fmt::format(
            "{} {}: relative_to=\"{}\": no link, joint or frame of that name in the model; expected one of "
            "them or __model__",
            xml_.where(pose != nullptr ? *pose : e), element_label(e), base));
      }
      frame = resolve(*it->second, chain);
    }
    chain.pop_back();
    const RigidPose out = frame * w.pose;
    cache_.emplace(&e, out);
    return out;
  }

  const XmlSource& xml_;
  std::map<std::string, const XMLElement*, std::less<>> by_name_;
  mutable std::map<const XMLElement*, RigidPose> cache_;
};

struct SdfReader {
  const XmlSource& xml;
  const RobotModel& model;
  RobotTree tree;
  std::size_t next_link = 0;
  /// Per link: its model element and its pose in space at the reference configuration.
  std::vector<const XMLElement*> link_model;
  std::vector<RigidPose> model_pose_of_link;                    ///< the pose of the link's model in space
  std::vector<std::pair<const XMLElement*, RigidPose>> joints;  // (element, its model's pose)
  std::map<const XMLElement*, std::unique_ptr<SdfModelFrames>> frames;  ///< per <model> element

  void read_model(const XMLElement& m, const RigidPose& parent_pose, bool is_static) {
    const RigidPose model_pose = parent_pose * model_pose_of(xml, m);
    const SdfModelFrames& model_frames =
        *frames.emplace(&m, std::make_unique<SdfModelFrames>(xml, m)).first->second;
    const bool static_model =
        is_static || child_text(m, "static") == "true" || child_text(m, "static") == "1";
    for (const XMLElement* e = m.FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
      const std::string_view n = e->Name();
      if (n == "link") {
        if (next_link >= model.links.size())
          throw InvalidInput(fmt::format("{}: more links than the model read", xml.where(*e)));
        const RigidPose link_pose = model_pose * model_frames.in_model(*e);
        tree.root_pose.push_back(link_pose);
        RobotJointSpec spec;  // until a joint names it as child: free, or fixed in a static model
        spec.kind = static_model ? RobotJointKind::fixed : RobotJointKind::free;
        spec.parent = -1;
        spec.child = static_cast<int>(next_link);
        spec.parent_child = link_pose;
        spec.name = model.links[next_link].name;
        spec.element = fmt::format("<link name=\"{}\">", spec.name);
        spec.line = e->GetLineNum();
        tree.joint_of_link.push_back(static_cast<int>(tree.joints.size()));
        tree.joints.push_back(std::move(spec));
        link_model.push_back(&m);
        model_pose_of_link.push_back(model_pose);
        ++next_link;
      } else if (n == "joint") {
        joints.emplace_back(e, model_pose);
      } else if (n == "model") {
        read_model(*e, model_pose, static_model);
      } else if (n == "include") {
        throw InvalidInput(
            fmt::format("{}: not supported; expected the whole model in one file", xml.where(*e)));
      }
    }
  }

  /// The link named `name` for a joint of model `m`: a link of m first, then any link of that name.
  int link_named(const XMLElement& joint, const XMLElement& m, const std::string& name,
                 const char* role) const {
    int found = -1;
    for (std::size_t k = 0; k < model.links.size(); ++k) {
      if (model.links[k].name != name) continue;
      if (link_model[k] == &m) return static_cast<int>(k);
      if (found < 0) found = static_cast<int>(k);
    }
    if (found < 0) {
      throw InvalidInput(fmt::format("{} {}: <{}>{}</{}>: no such link; expected a <link> of the model{}",
                                     xml.where(joint), element_label(joint), role, name, role,
                                     std::string_view(role) == "parent" ? " or world" : ""));
    }
    return found;
  }

  /// The unit axis of <axis> or <axis2> of a joint, in the child link's frame.
  Vec3 axis_of(const XMLElement& joint, const char* which, const RigidPose& child_joint,
               const RigidPose& model_pose, const RigidPose& child_pose) const {
    const XMLElement* a = joint.FirstChildElement(which);
    const XMLElement* xyz = a != nullptr ? a->FirstChildElement("xyz") : nullptr;
    if (xyz == nullptr) {
      throw InvalidInput(fmt::format("{} {}: no <{}><xyz>; expected the joint's axis", xml.where(joint),
                                     element_label(joint), which));
    }
    const std::vector<double> v = xml.numbers_text(*xyz, 3);
    const Vec3 axis =
        unit_axis_of(xml, joint, fmt::format("<{}><xyz>", which).c_str(), Vec3(v[0], v[1], v[2]));
    const char* in = xyz->Attribute("expressed_in");
    const bool model_frame = (in != nullptr && std::string_view(in) == "__model__") ||
                             child_text(*a, "use_parent_model_frame") == "true" ||
                             child_text(*a, "use_parent_model_frame") == "1";
    if (in != nullptr && !model_frame) {
      throw InvalidInput(
          fmt::format("{} expressed_in=\"{}\": not supported; expected __model__ or the joint "
                      "frame (no attribute)",
                      xml.where(*xyz), in));
    }
    if (model_frame) return child_pose.R.transpose() * (model_pose.R * axis);
    return child_joint.R * axis;
  }

  void read_joint(const XMLElement& e, const RigidPose& model_pose) {
    const char* name_attr = e.Attribute("name");
    const std::string name = name_attr != nullptr ? name_attr : fmt::format("joint_line{}", e.GetLineNum());
    const char* type_attr = e.Attribute("type");
    const std::string type = type_attr != nullptr ? type_attr : "";
    const XMLElement& m = *e.Parent()->ToElement();
    const std::string parent_name = child_text(e, "parent");
    const std::string child_name = child_text(e, "child");
    if (child_name.empty()) {
      throw InvalidInput(
          fmt::format("{} {}: no <child>; expected the child link's name", xml.where(e), element_label(e)));
    }
    if (parent_name.empty()) {
      throw InvalidInput(fmt::format("{} {}: no <parent>; expected the parent link's name or world",
                                     xml.where(e), element_label(e)));
    }
    const int child = link_named(e, m, child_name, "child");
    const int parent = parent_name == "world" ? -1 : link_named(e, m, parent_name, "parent");
    RobotJointSpec& spec =
        tree.joints[static_cast<std::size_t>(tree.joint_of_link[static_cast<std::size_t>(child)])];
    if (spec.element.starts_with("<joint")) {
      throw InvalidInput(
          fmt::format("{} {}: link \"{}\" is already the child of {} (line {}); expected each link "
                      "the child of one joint",
                      xml.where(e), element_label(e), child_name, spec.element, spec.line));
    }
    spec.name = name;
    spec.element = fmt::format("<joint name=\"{}\">", name);
    spec.line = e.GetLineNum();
    spec.parent = parent;
    const RigidPose child_pose = tree.root_pose[static_cast<std::size_t>(child)];
    const RigidPose parent_pose = parent < 0 ? RigidPose{} : tree.root_pose[static_cast<std::size_t>(parent)];
    spec.parent_child = parent_pose.inverse() * child_pose;
    // The joint's frame in the child's: its pose as written, or through the model's frames when it names one.
    const WrittenPose written = written_pose(xml, e);
    const RigidPose child_joint = written.relative_to.empty()
                                      ? written.pose
                                      : child_pose.inverse() * (model_pose * frames.at(&m)->in_model(e));
    const auto dof = [&](RobotDof::Kind kind, const char* which) {
      RobotDof d;
      d.kind = kind;
      d.name = name;
      d.line = spec.line;
      d.anchor_child = child_joint.p;
      if (kind != RobotDof::Kind::ball) d.axis_child = axis_of(e, which, child_joint, model_pose, child_pose);
      return d;
    };
    spec.dofs.clear();
    if (type == "revolute" || type == "continuous") {
      spec.dofs.push_back(dof(RobotDof::Kind::hinge, "axis"));
    } else if (type == "prismatic") {
      spec.dofs.push_back(dof(RobotDof::Kind::slide, "axis"));
    } else if (type == "ball") {
      spec.dofs.push_back(dof(RobotDof::Kind::ball, "axis"));
    } else if (type == "universal") {
      spec.dofs.push_back(dof(RobotDof::Kind::hinge, "axis"));
      spec.dofs.push_back(dof(RobotDof::Kind::hinge, "axis2"));
    } else if (type != "fixed") {
      throw InvalidInput(
          fmt::format("{} {} type=\"{}\": not supported; expected revolute, continuous, "
                      "prismatic, ball, universal or fixed",
                      xml.where(e), element_label(e), type));
    }
    spec.kind = spec.dofs.empty() ? RobotJointKind::fixed : RobotJointKind::dofs;
    for (const char* which : {"axis", "axis2"}) {
      const XMLElement* a = e.FirstChildElement(which);
      if (a == nullptr) continue;
      if (a->FirstChildElement("limit") != nullptr)
        tree.not_modelled.push_back(
            fmt::format("{} line {}: <{}><limit> (joint limits)", spec.element, spec.line, which));
      const XMLElement* dyn = a->FirstChildElement("dynamics");
      if (dyn == nullptr) continue;
      // <dynamics> of the axis: its damper and spring act on that axis's coordinate; friction is not
      // modelled.
      const std::size_t k = std::string_view(which) == "axis" ? 0 : 1;
      if (k < spec.dofs.size() && spec.dofs[k].kind != RobotDof::Kind::ball) {
        RobotDof& d = spec.dofs[k];
        const auto value = [&](const char* key, double& out) {
          if (const XMLElement* v = dyn->FirstChildElement(key)) out = xml.numbers_text(*v, 1)[0];
        };
        value("damping", d.damping);
        value("spring_stiffness", d.stiffness);
        value("spring_reference", d.spring_reference);
      }
      if (const XMLElement* f = dyn->FirstChildElement("friction");
          f != nullptr && xml.numbers_text(*f, 1)[0] != 0.0)
        tree.not_modelled.push_back(fmt::format("{} line {}: <{}><dynamics><friction> (joint friction)",
                                                spec.element, spec.line, which));
    }
  }
};

}  // namespace

RobotTree read_sdf_tree(const XmlSource& xml, const RobotModel& model) {
  SdfReader r{xml, model, {}, 0, {}, {}, {}, {}};
  // Models under <sdf> and under its <world>s, in file order.
  for (const XMLElement* e = xml.root()->FirstChildElement(); e != nullptr; e = e->NextSiblingElement()) {
    const std::string_view n = e->Name();
    if (n == "model") r.read_model(*e, RigidPose{}, false);
    if (n == "world") {
      if (const XMLElement* g = e->FirstChildElement("gravity")) {
        const std::vector<double> v = xml.numbers_text(*g, 3);
        r.tree.has_gravity = true;
        r.tree.gravity = Vec3(v[0], v[1], v[2]);
      }
      for (const XMLElement* m = e->FirstChildElement("model"); m != nullptr;
           m = m->NextSiblingElement("model"))
        r.read_model(*m, RigidPose{}, false);
    }
  }
  if (r.next_link != model.links.size())
    throw InvalidInput(fmt::format("{}: the links do not match the model's", xml.where(*xml.root())));
  for (const auto& [e, pose] : r.joints)
    r.read_joint(*e, pose);
  return std::move(r.tree);
}

}  // namespace poinsot::io::detail
