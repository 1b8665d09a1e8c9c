// Robot files that poinsot refuses: each is one line naming the file, the element and its line (URDF, MJCF
// and SDF; a missing parent, a loop, a zero axis, a massless moving link, an unsupported joint, an
// orientation whose rotation is not finite, an SDF pose relative to no frame or to a chain of frames that
// comes back).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::expect_has;
using test::message_of;

struct BadFile {
  const char* name;
  const char* text;
  std::vector<std::string> pieces;
};

class RobotSystemBadFile : public ::testing::TestWithParam<BadFile> {};

TEST_P(RobotSystemBadFile, IsRefusedWithOneLineNamingTheElementAndItsLine) {
  const BadFile& b = GetParam();
  const std::string message = message_of([&] { robot_scenario(read_robot_model(b.text, b.name)); });
  for (const std::string& piece : b.pieces)
    expect_has(message, {piece});
}

constexpr const char* kLink =
    "<inertial><mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" "
    "izz=\"1\"/></inertial>";

std::string urdf(const std::string& body) {
  return "<robot name=\"r\">\n<link name=\"a\">" + std::string(kLink) + "</link>\n<link name=\"b\">" + kLink +
         "</link>\n" + body + "</robot>\n";
}

const std::string kMissingParent =
    urdf("<joint name=\"j\" type=\"revolute\">\n<parent link=\"c\"/><child link=\"b\"/></joint>\n");
const std::string kTwoParents = urdf(
    "<joint name=\"j1\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
    "<joint name=\"j2\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/></joint>\n");
const std::string kCycle = urdf(
    "<joint name=\"j1\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
    "<joint name=\"j2\" type=\"revolute\"><parent link=\"b\"/><child link=\"a\"/></joint>\n");
const std::string kZeroAxis = urdf(
    "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>\n<axis xyz=\"0 0 "
    "0\"/></joint>\n");
const std::string kMassless =
    "<robot name=\"r\">\n<link name=\"a\"/>\n<link name=\"b\"/>\n"
    "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/></joint>\n</robot>\n";
const std::string kPlanar =
    urdf("<joint name=\"j\" type=\"planar\"><parent link=\"a\"/><child link=\"b\"/></joint>\n");
const std::string kMjcfZeroAxis =
    "<mujoco>\n<worldbody>\n<body name=\"b\">\n<joint name=\"j\" axis=\"0 0 0\"/>\n"
    "<geom type=\"sphere\" size=\"0.1\"/></body></worldbody></mujoco>\n";
const std::string kMjcfOffsetHinges =
    "<mujoco>\n<worldbody>\n<body name=\"foot\">\n<joint name=\"ankle_y\" pos=\"0 0 .08\" axis=\"0 1 0\"/>\n"
    "<joint name=\"ankle_x\" pos=\"0 0 .04\" axis=\"1 0 .5\"/>\n<joint name=\"ankle_z\" axis=\"0 0 1\"/>\n"
    "<geom type=\"sphere\" size=\"0.1\"/></body></worldbody></mujoco>\n";
const std::string kMjcfEquality =
    "<mujoco>\n<worldbody>\n<body name=\"b\">\n<joint name=\"j\"/><geom type=\"sphere\" size=\"0.1\"/></body>"
    "</worldbody>\n<equality>\n<joint joint1=\"j\"/>\n</equality></mujoco>\n";
const std::string kMjcfMassless =
    "<mujoco>\n<worldbody>\n<body name=\"b\">\n<joint name=\"j\"/></body></worldbody></mujoco>\n";
const std::string kSdfZeroAxis =
    "<sdf version=\"1.6\"><model name=\"m\">\n<link name=\"a\"/>\n"
    "<joint name=\"j\" type=\"revolute\"><parent>world</parent><child>a</child>\n"
    "<axis><xyz>0 0 0</xyz></axis></joint></model></sdf>\n";
const std::string kSdfMissingParent =
    "<sdf version=\"1.6\"><model name=\"m\">\n<link name=\"a\"/>\n"
    "<joint name=\"j\" type=\"revolute\"><parent>ghost</parent><child>a</child>\n"
    "<axis><xyz>0 0 1</xyz></axis></joint></model></sdf>\n";
const std::string kHugeInertialRpy =
    "<robot name=\"r\">\n<link name=\"a\">\n<inertial>\n<origin xyz=\"0 0 0\" rpy=\"1e300 0 0\"/>\n"
    "<mass value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" izz=\"1\"/>"
    "</inertial></link>\n</robot>\n";
const std::string kHugeJointRpy = urdf(
    "<joint name=\"j\" type=\"revolute\"><parent link=\"a\"/><child link=\"b\"/>\n<origin rpy=\"0 "
    "1e300 0\"/></joint>\n");
const std::string kSdfHugePose =
    "<sdf version=\"1.6\"><model name=\"m\">\n<link name=\"a\">\n<pose>0 0 0 0 0 1e300</pose></link>\n"
    "</model></sdf>\n";
const std::string kMjcfHugeEuler =
    "<mujoco>\n<worldbody>\n<body name=\"b\" euler=\"1e300 0 0\">\n<joint name=\"j\"/>"
    "<geom type=\"sphere\" size=\"0.1\"/></body></worldbody></mujoco>\n";
const std::string kSdfScrew =
    "<sdf version=\"1.6\"><model name=\"m\">\n<link name=\"a\"/>\n"
    "<joint name=\"j\" type=\"screw\"><parent>world</parent><child>a</child></joint></model></sdf>\n";

const std::string kSdfUnknownFrame =
    "<sdf version=\"1.7\"><model name=\"m\">\n<link name=\"a\">\n<pose relative_to=\"ghost\">0 0 1 0 0 "
    "0</pose></link>\n</model></sdf>\n";
const std::string kSdfFrameCycle =
    "<sdf version=\"1.7\"><model name=\"m\">\n<link name=\"a\"><pose relative_to=\"f\">0 0 1 0 0 "
    "0</pose></link>\n"
    "<frame name=\"f\" attached_to=\"a\"><pose>1 0 0 0 0 0</pose></frame>\n</model></sdf>\n";
const std::string kSdfModelRelative =
    "<sdf version=\"1.7\"><model name=\"m\">\n<pose relative_to=\"a\">0 0 1 0 0 0</pose>\n<link "
    "name=\"a\"/>\n</model></sdf>\n";

INSTANTIATE_TEST_SUITE_P(
    Files, RobotSystemBadFile,
    ::testing::Values(
        BadFile{
            "rpy.urdf",
            kHugeInertialRpy.c_str(),
            {"rpy.urdf:4: <origin> rpy: got (1e+300, 0, 0), expected angles (rad) whose rotation is finite"}},
        BadFile{
            "joint_rpy.urdf", kHugeJointRpy.c_str(), {"joint_rpy.urdf:5: <origin> rpy: got (0, 1e+300, 0)"}},
        BadFile{
            "pose.sdf", kSdfHugePose.c_str(), {"pose.sdf:3: <pose> roll, pitch, yaw: got (0, 0, 1e+300)"}},
        BadFile{"euler.xml",
                kMjcfHugeEuler.c_str(),
                {"euler.xml:3: <body>: its orientation is not a finite rotation"}},
        BadFile{"parent.urdf",
                kMissingParent.c_str(),
                {"parent.urdf:4: <joint> name=\"j\": <parent link=\"c\">: no such link"}},
        BadFile{"two.urdf",
                kTwoParents.c_str(),
                {"two.urdf:5: <joint> name=\"j2\": link \"b\" is already the child of <joint name=\"j1\"> "
                 "(line 4)",
                 "a kinematic loop"}},
        BadFile{
            "cycle.urdf", kCycle.c_str(), {"cycle.urdf:", "its parents lead back to link", "kinematic loop"}},
        BadFile{"axis.urdf",
                kZeroAxis.c_str(),
                {"axis.urdf:4: <joint> name=\"j\" <axis xyz>: zero length; expected a non-zero axis"}},
        BadFile{"massless.urdf",
                kMassless.c_str(),
                {"massless.urdf:3: <link name=\"b\">: mass 0 kg on a link that moves (<joint name=\"j\">)",
                 "expected a mass > 0"}},
        BadFile{"planar.urdf",
                kPlanar.c_str(),
                {"planar.urdf:4: <joint> name=\"j\" type=\"planar\": not supported"}},
        BadFile{"axis.xml", kMjcfZeroAxis.c_str(), {"axis.xml:4: <joint> name=\"j\" axis: zero length"}},
        BadFile{"offset.xml",
                kMjcfOffsetHinges.c_str(),
                {"offset.xml:4: <joint name=\"ankle_y\">",
                 "hinge \"ankle_y\" (line 4), hinge \"ankle_x\" (line 5), hinge \"ankle_z\" (line 6)",
                 "not supported together (their anchors differ)"}},
        BadFile{"equality.xml", kMjcfEquality.c_str(), {"equality.xml:6: <joint>: not supported"}},
        BadFile{"massless.xml", kMjcfMassless.c_str(), {"massless.xml:3: <body name=\"b\">: mass 0 kg"}},
        BadFile{
            "axis.sdf", kSdfZeroAxis.c_str(), {"axis.sdf:3: <joint> name=\"j\" <axis><xyz>: zero length"}},
        BadFile{"parent.sdf",
                kSdfMissingParent.c_str(),
                {"parent.sdf:3: <joint> name=\"j\": <parent>ghost</parent>: no such link"}},
        BadFile{"screw.sdf",
                kSdfScrew.c_str(),
                {"screw.sdf:3: <joint> name=\"j\" type=\"screw\": not supported"}},
        BadFile{"frame.sdf",
                kSdfUnknownFrame.c_str(),
                {"frame.sdf:3: <pose>", "relative_to=\"ghost\": no link, joint or frame of that name"}},
        BadFile{"cycle.sdf",
                kSdfFrameCycle.c_str(),
                {"cycle.sdf:2: <link>", "a chain of frames that comes back to it"}},
        BadFile{"model_pose.sdf",
                kSdfModelRelative.c_str(),
                {"model_pose.sdf:2: <pose> relative_to=\"a\": not supported for a model"}}));

}  // namespace
}  // namespace poinsot::io
