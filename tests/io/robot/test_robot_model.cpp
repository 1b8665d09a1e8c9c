// Tests of robot_model.hpp: the three formats' conventions, each against a tensor rotated by hand (90°
// turns, where R J Rᵀ only permutes the diagonal, and one 45° turn that creates a product of inertia), and
// the one-line refusals of malformed files. Tolerances: a 90° rotation from radians or a quaternion of
// cos 45° is exact to a few ulps, so entries of order 1 agree to 1e-15.
#include "poinsot/io/robot/robot_model.hpp"

#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::expect_has;
using test::max_abs_diff;

constexpr double kTol = 1e-15;

std::string urdf_link(const std::string& origin, const std::string& inertia) {
  return "<robot name=\"r\"><link name=\"a\"><inertial>" + origin + "<mass value=\"1\"/><inertia " + inertia +
         "/></inertial></link></robot>";
}

const RobotLink& only_link(const RobotModel& m) {
  EXPECT_EQ(m.links.size(), 1u);
  return m.links.front();
}

std::string invalid_input(const std::string& text) {
  return test::message_of<InvalidInput>([&] { read_robot_model(text, "m.xml"); }, text);
}

TEST(RobotModel, UrdfYawTurnsInertialXToLinkY) {
  // R = R_z(π/2): inertial x → link y, so J_link = diag(Iyy, Ixx, Izz) of the file's.
  const RobotModel m =
      read_robot_model(urdf_link("<origin xyz=\"1 2 3\" rpy=\"0 0 1.5707963267948966\"/>",
                                 "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"3\""),
                       "r.urdf");
  EXPECT_EQ(m.format, RobotFormat::urdf);
  const RobotLink& l = only_link(m);
  EXPECT_TRUE(l.has_inertial);
  EXPECT_EQ(l.com_link, Vec3(1, 2, 3));
  EXPECT_LE(max_abs_diff(l.inertia_link, Mat3(Vec3(2, 1, 3).asDiagonal())), kTol);
}

TEST(RobotModel, UrdfRollPitchYawIsFixedAxisXThenYThenZ) {
  // rpy = (π/2, 0, π/2): R = R_z(π/2) R_x(π/2). R_x(π/2) takes x→x, y→z, z→−y; then R_z(π/2) takes x→y, z→z,
  // −y→x. So inertial x → link y, y → link z, z → link x: J_link = diag(Izz, Ixx, Iyy) = (3, 1, 2). The
  // other order, R_x R_z, would give inertial x → link z, i.e. (2, 3, 1).
  const RobotLink l =
      only_link(read_robot_model(urdf_link("<origin rpy=\"1.5707963267948966 0 1.5707963267948966\"/>",
                                           "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"3\""),
                                 "r.urdf"));
  EXPECT_LE(max_abs_diff(l.inertia_link, Mat3(Vec3(3, 1, 2).asDiagonal())), kTol);
}

TEST(RobotModel, UrdfProductsAreEntriesOfJ) {
  // diag(1, 2, 3) turned by 45° about z: J_xx = J_yy = (1 + 2)/2, J_xy = (1 − 2)/2 (R D Rᵀ by hand).
  const RobotLink l =
      only_link(read_robot_model(urdf_link("<origin rpy=\"0 0 0.78539816339744828\"/>",
                                           "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"2\" iyz=\"0\" izz=\"3\""),
                                 "r.urdf"));
  Mat3 expected;
  expected << 1.5, -0.5, 0, -0.5, 1.5, 0, 0, 0, 3;
  EXPECT_LE(max_abs_diff(l.inertia_link, expected), 4 * test::kEps);
  // And a product written in the file lands in J(0, 1) with its sign.
  const RobotLink p = only_link(read_robot_model(
      urdf_link("", "ixx=\"1\" ixy=\"-0.25\" ixz=\"0.125\" iyy=\"2\" iyz=\"0.5\" izz=\"3\""), "r"));
  EXPECT_EQ(p.inertia_link(0, 1), -0.25);
  EXPECT_EQ(p.inertia_link(1, 0), -0.25);
  EXPECT_EQ(p.inertia_link(0, 2), 0.125);
  EXPECT_EQ(p.inertia_link(1, 2), 0.5);
}

TEST(RobotModel, MjcfDiagInertiaWithQuaternion) {
  // quat (cos 45°, 0, 0, sin 45°) = R_z(π/2): diag(1, 2, 3) → diag(2, 1, 3); pos is the centre of mass.
  const RobotModel m = read_robot_model(
      "<mujoco><worldbody><body name=\"b\"><inertial pos=\"0.1 0 0\" mass=\"2\" "
      "quat=\"0.7071067811865476 0 0 0.7071067811865476\" diaginertia=\"1 2 "
      "3\"/></body></worldbody></mujoco>",
      "m.xml");
  EXPECT_EQ(m.format, RobotFormat::mjcf);
  const RobotLink& l = only_link(m);
  EXPECT_EQ(l.mass, 2.0);
  EXPECT_EQ(l.com_link, Vec3(0.1, 0, 0));
  EXPECT_EQ(l.layout, TensorLayout::mjcf_diag);
  EXPECT_LE(max_abs_diff(l.inertia_link, Mat3(Vec3(2, 1, 3).asDiagonal())), 4 * test::kEps);
}

TEST(RobotModel, MjcfFullInertiaOrderIsM11M22M33M12M13M23) {
  const RobotModel m = read_robot_model(
      "<mujoco><worldbody><body><body name=\"inner\"><inertial mass=\"1\" fullinertia=\"4 5 6 0.1 0.2 0.3\"/>"
      "</body></body></worldbody></mujoco>",
      "m.xml");
  ASSERT_EQ(m.links.size(), 2u);  // nested bodies, outer first; the outer has no inertial element
  EXPECT_FALSE(m.links[0].has_inertial);
  const RobotLink& l = m.links[1];
  Mat3 expected;
  expected << 4, 0.1, 0.2, 0.1, 5, 0.3, 0.2, 0.3, 6;
  EXPECT_EQ(l.inertia_link, expected);
  EXPECT_EQ(l.name, "inner");
  EXPECT_EQ(l.layout, TensorLayout::mjcf_full);
}

TEST(RobotModel, SdfPoseRollPitchYawDegreesAndQuaternion) {
  const auto sdf = [](const std::string& pose) {
    return "<sdf version=\"1.9\"><model name=\"m\"><link name=\"l\"><inertial>" + pose +
           "<mass>3</mass><inertia><ixx>1</ixx><ixy>0</ixy><ixz>0</ixz><iyy>2</iyy><iyz>0</iyz><izz>3</izz>"
           "</inertia></inertial></link></model></sdf>";
  };
  const Mat3 turned = Vec3(2, 1, 3).asDiagonal();  // R_z(π/2), as for URDF
  const RobotLink a = only_link(read_robot_model(sdf("<pose>1 2 3 0 0 1.5707963267948966</pose>"), "m.sdf"));
  EXPECT_EQ(a.mass, 3.0);
  EXPECT_EQ(a.com_link, Vec3(1, 2, 3));
  EXPECT_LE(max_abs_diff(a.inertia_link, turned), kTol);
  const RobotLink b = only_link(read_robot_model(sdf("<pose degrees=\"true\">0 0 0 0 0 90</pose>"), "m.sdf"));
  EXPECT_LE(max_abs_diff(b.inertia_link, turned), kTol);
  const RobotLink c = only_link(read_robot_model(
      sdf("<pose rotation_format=\"quat_xyzw\">0 0 0 0 0 0.7071067811865476 0.7071067811865476</pose>"),
      "m.sdf"));
  EXPECT_LE(max_abs_diff(c.inertia_link, turned), 4 * test::kEps);
  // The roll-pitch-yaw order is URDF's: (π/2, 0, π/2) gives diag(Izz, Ixx, Iyy).
  const RobotLink d =
      only_link(read_robot_model(sdf("<pose>0 0 0 1.5707963267948966 0 1.5707963267948966</pose>"), "m.sdf"));
  EXPECT_LE(max_abs_diff(d.inertia_link, Mat3(Vec3(3, 1, 2).asDiagonal())), kTol);
}

TEST(RobotModel, GeometryIsReadWithItsPose) {
  const RobotLink l = only_link(read_robot_model(
      "<robot name=\"r\"><link name=\"a\"><collision><origin xyz=\"0 0 1\" rpy=\"0 1.5707963267948966 0\"/>"
      "<geometry><cylinder radius=\"0.1\" length=\"2\"/></geometry></collision>"
      "<visual><geometry><sphere radius=\"9\"/></geometry></visual></link></robot>",
      "r.urdf"));
  EXPECT_FALSE(l.has_inertial);
  ASSERT_EQ(l.geometry.size(), 1u);  // the visual shape stands in only without collision shapes
  EXPECT_EQ(l.geometry[0].shape.kind, "cylinder");
  EXPECT_EQ(l.geometry[0].position_link, Vec3(0, 0, 1));
  EXPECT_LE(max_abs_diff(l.geometry[0].R_link_geometry * Vec3::UnitZ(), Vec3(1, 0, 0)), kTol);
  // MJCF sizes are half-sizes; fromto gives the axis and the length.
  const RobotLink m = only_link(
      read_robot_model("<mujoco><worldbody><body><geom type=\"box\" size=\"1 2 3\"/><geom type=\"capsule\" "
                       "fromto=\"0 0 0 0 2 0\" size=\"0.5\"/></body></worldbody></mujoco>",
                       "m.xml"));
  ASSERT_EQ(m.geometry.size(), 2u);
  EXPECT_EQ(m.geometry[0].shape.size, Vec3(2, 4, 6));
  EXPECT_EQ(m.geometry[1].shape.length, 2.0);
  EXPECT_EQ(m.geometry[1].position_link, Vec3(0, 1, 0));
  EXPECT_LE(max_abs_diff(m.geometry[1].R_link_geometry * Vec3::UnitZ(), Vec3(0, 1, 0)), kTol);
}

TEST(RobotModel, RefusalsAreOneLineNamingTheElement) {
  expect_has(invalid_input("<robot><link name=\"a\">"), {"m.xml:1:", "XML error"});
  expect_has(invalid_input("<html/>"), {"<html>", "expected <robot> (URDF), <mujoco> (MJCF) or <sdf>"});
  expect_has(invalid_input(urdf_link("", "ixx=\"abc\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"")),
             {"<inertia>", "ixx=\"abc\"", "expected 1 finite number"});
  expect_has(invalid_input(urdf_link("", "ixx=\"nan\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"")),
             {"ixx=\"nan\"", "finite"});
  expect_has(invalid_input(urdf_link("", "ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\"")),
             {"missing attribute izz"});
  expect_has(invalid_input("<robot><link name=\"a\"><inertial><inertia/></inertial></link></robot>"),
             {"<inertial>", "no <mass value/>"});
  expect_has(
      invalid_input("<mujoco><worldbody><body><inertial mass=\"1\" euler=\"0 0 1\" diaginertia=\"1 1 1\"/>"
                    "</body></worldbody></mujoco>"),
      {"<inertial>", "euler", "expected quat"});
  expect_has(invalid_input("<mujoco><worldbody><body><inertial mass=\"1\"/></body></worldbody></mujoco>"),
             {"exactly one of diaginertia", "fullinertia"});
  expect_has(invalid_input("<mujoco><worldbody><body><inertial mass=\"1\" quat=\"0 0 0 0\" diaginertia=\"1 1 "
                           "1\"/></body></worldbody></mujoco>"),
             {"quat", "zero quaternion"});
}

TEST(RobotModel, FileSizeLimitIsCheckedBeforeReading) {
  const std::string path = std::string(POINSOT_TEST_DATA_DIR) + "/models/valid_arm.urdf";
  POINSOT_EXPECT_THROWS_MESSAGE(load_robot_model(path, 100), InvalidInput, "valid_arm.urdf",
                                "the limit is 100 bytes", "--max-file-bytes");
  EXPECT_EQ(load_robot_model(path).links.size(), 5u);
}

}  // namespace
}  // namespace poinsot::io
