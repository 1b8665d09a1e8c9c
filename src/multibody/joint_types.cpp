// The table of joint types (joint_types.hpp).
#include "poinsot/multibody/joint_types.hpp"

#include <array>

#include <fmt/format.h>

namespace poinsot::multibody {
namespace {

constexpr std::array<JointTypeInfo, 5> kJointTypes{{
    {JointType::ball, "ball", 3, JointAxes::none, false,
     "the points coincide; 3 rotational degrees of freedom (spherical joint)"},
    {JointType::hinge, "hinge", 5, JointAxes::parallel, false,
     "ball + axis_a parallel to axis_b; 1 rotational degree of freedom (revolute joint)"},
    {JointType::weld, "weld", 6, JointAxes::none, true, "ball + the relative rotation frozen; none free"},
    {JointType::universal, "universal", 4, JointAxes::crossed, false,
     "ball + axis_a perpendicular to axis_b; 2 rotational degrees of freedom (Cardan joint)"},
    {JointType::prismatic, "prismatic", 5, JointAxes::sliding, true,
     "the relative rotation frozen, point a on the line through point b along axis_a; 1 translational degree "
     "of freedom (slider)"},
}};

// The table is indexed by the enumerator.
constexpr bool indexed_by_type() {
  for (std::size_t k = 0; k < kJointTypes.size(); ++k)
    if (static_cast<std::size_t>(kJointTypes[k].type) != k) return false;
  return true;
}
static_assert(indexed_by_type(), "kJointTypes must list the JointType enumerators in order");

}  // namespace

std::span<const JointTypeInfo> joint_types() {
  return kJointTypes;
}

const JointTypeInfo& joint_type_info(JointType type) {
  return kJointTypes.at(static_cast<std::size_t>(type));
}

const JointTypeInfo* find_joint_type(std::string_view name) {
  for (const JointTypeInfo& info : kJointTypes)
    if (info.name == name) return &info;
  return nullptr;
}

std::string joint_type_names() {
  std::string out;
  for (std::size_t k = 0; k < kJointTypes.size(); ++k) {
    if (k > 0) out += k + 1 == kJointTypes.size() ? " or " : ", ";
    out += fmt::format("\"{}\"", kJointTypes[k].name);
  }
  return out;
}

}  // namespace poinsot::multibody
