// SDF poses relative to other frames of the model (`<pose relative_to>`, `<frame attached_to>`): the system
// of tests/data/models/robots/relative_to.sdf equals that of the same model written with every pose in the
// frame SDF implies, its poses composed here by hand.
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <Eigen/Geometry>

#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

struct Pose {
  Mat3 R = Mat3::Identity();
  Vec3 p = Vec3::Zero();
  Pose operator*(const Pose& inner) const { return {R * inner.R, R * inner.p + p}; }
  Pose inverse() const { return {R.transpose(), -(R.transpose() * p)}; }
};

Pose at(double x, double y, double z, const Vec3& axis = Vec3::UnitZ(), double angle = 0.0) {
  return {Eigen::AngleAxisd(angle, axis).toRotationMatrix(), Vec3(x, y, z)};
}

/// `<pose rotation_format="quat_xyzw">` of a pose, to 17 digits.
std::string pose_element(const Pose& pose) {
  const Eigen::Quaterniond q(pose.R);
  return fmt::format(
      "<pose rotation_format=\"quat_xyzw\">{:.17g} {:.17g} {:.17g} {:.17g} {:.17g} {:.17g} "
      "{:.17g}</pose>",
      pose.p.x(), pose.p.y(), pose.p.z(), q.x(), q.y(), q.z(), q.w());
}

TEST(SdfFrames, RelativePosesAreTheComposedOnes) {
  // The poses of relative_to.sdf in the model's frame, composed from the file's numbers.
  const Pose base = at(0.0, 0.0, 1.0, Vec3::UnitZ(), 0.2);
  const Pose hip = base * at(0.1, 0.0, 0.0);
  const Pose arm = hip * at(0.0, 0.0, -0.2, Vec3::UnitY(), 0.3);
  const Pose tool_mount = arm * at(0.0, 0.0, -0.5, Vec3::UnitX(), 0.4);
  const Pose tool = tool_mount * at(0.0, 0.05, 0.0);
  const Pose wrist = at(0.1, 0.05, 0.4);
  // The same model with the links' poses in the model's frame and the joints' in their child's.
  const std::string inertial_base =
      "<inertial><mass>2</mass><inertia><ixx>0.02</ixx><iyy>0.03</iyy><izz>0.04</izz><ixy>0</ixy><ixz>0</ixz>"
      "<iyz>0</iyz></inertia></inertial>";
  const std::string inertial_arm =
      "<inertial><pose>0 0 -0.25 0 0 0</pose><mass>1</mass><inertia><ixx>0.021</ixx><iyy>0.021</iyy>"
      "<izz>0.0005</izz><ixy>0</ixy><ixz>0</ixz><iyz>0</iyz></inertia></inertial>";
  const std::string inertial_tool =
      "<inertial><mass>0.5</mass><inertia><ixx>0.001</ixx><iyy>0.002</iyy><izz>0.003</izz><ixy>0</ixy>"
      "<ixz>0</ixz><iyz>0</iyz></inertia></inertial>";
  const std::string plain = fmt::format(
      "<sdf version=\"1.6\"><model name=\"relative\">\n"
      "<link name=\"base\">{}{}</link>\n"
      "<joint name=\"hip\" type=\"revolute\">{}<parent>base</parent><child>arm</child>"
      "<axis><xyz>0 1 0</xyz></axis></joint>\n"
      "<link name=\"arm\">{}{}</link>\n"
      "<link name=\"tool\">{}{}</link>\n"
      "<joint name=\"wrist\" type=\"revolute\">{}<parent>arm</parent><child>tool</child>"
      "<axis><xyz>1 0 0</xyz></axis></joint>\n"
      "<joint name=\"anchor\" type=\"fixed\"><parent>world</parent><child>base</child></joint>\n"
      "</model></sdf>\n",
      pose_element(base), inertial_base, pose_element(arm.inverse() * hip), pose_element(arm), inertial_arm,
      pose_element(tool), inertial_tool, pose_element(tool.inverse() * wrist));
  const std::filesystem::path path = test::temp_path("plain.sdf");
  std::ofstream(path) << plain;

  const multibody::Scenario relative =
      load_robot_scenario(std::string(POINSOT_TEST_DATA_DIR) + "/models/robots/relative_to.sdf");
  const multibody::Scenario composed = load_robot_scenario(path.string());
  // Both read the same numbers; the composed file's quaternions of 17 digits carry the rotations to a few
  // ulps, which the poses and joint points inherit.
  const double tolerance = 2e-15;
  ASSERT_EQ(relative.system.body_count(), 3);
  ASSERT_EQ(composed.system.body_count(), 3);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(relative.system.bodies()[i].name, composed.system.bodies()[i].name);
    EXPECT_EQ(relative.system.bodies()[i].mass, composed.system.bodies()[i].mass);
    EXPECT_LT((relative.system.bodies()[i].inertia - composed.system.bodies()[i].inertia).norm(), tolerance);
    const auto& a = relative.initial.bodies[i];
    const auto& b = composed.initial.bodies[i];
    EXPECT_LT((a.R_space_body - b.R_space_body).norm(), tolerance) << i;
    EXPECT_LT((a.x_space - b.x_space).norm(), tolerance) << i;
  }
  ASSERT_EQ(relative.system.joint_count(), composed.system.joint_count());
  for (std::size_t k = 0; k < relative.system.joints().size(); ++k) {
    const multibody::Joint& a = relative.system.joints()[k];
    const multibody::Joint& b = composed.system.joints()[k];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.type, b.type);
    EXPECT_LT((a.point_a - b.point_a).norm(), tolerance) << a.name;
    EXPECT_LT((a.point_b - b.point_b).norm(), tolerance) << a.name;
    if (a.type == multibody::JointType::hinge) {
      EXPECT_LT((a.hinge_axis_a() - b.hinge_axis_a()).norm(), tolerance) << a.name;
      EXPECT_LT((a.u_b[0] - b.u_b[0]).norm(), tolerance) << a.name;
    }
  }
  // The check of the hand composition itself: the wrist's axis (x of the model, as the joint's pose is
  // relative to __model__ without rotation) in space, from the tool's body.
  const multibody::Joint& wrist_joint = relative.system.joints()[2];
  ASSERT_EQ(wrist_joint.name, "wrist");
  const Mat3 R_tool = relative.initial.bodies[2].R_space_body;
  EXPECT_LT((R_tool * wrist_joint.hinge_axis_a() - Vec3::UnitX()).norm(), tolerance);
}

}  // namespace
}  // namespace poinsot::io
