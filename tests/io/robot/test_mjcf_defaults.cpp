// Tests of the MJCF default classes (src/io/robot/mjcf_defaults.hpp) through read_robot_model: a model
// written with default classes — the top-level class, nested classes, body childclass inherited by nested
// bodies, a geom's own class over the childclass, the orientation taken whole from one level, mesh assets —
// is read into the same geometry as the same model expanded by hand (every attribute written on its geom or
// mesh). The two models give the same numbers to the reader, so the geometry must agree exactly (==).
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::expect_has;

const std::string kMeshDir = std::string(POINSOT_TEST_DATA_DIR) + "/inertia";

// The capsule of class main is turned by quat (0 0 0 1) = R_z(π); the class finger writes its orientation as
// euler (degrees, MuJoCo's default) unless its geom writes a quat of its own.
const char* const kWithDefaults = R"(<mujoco>
  <default>
    <geom type="capsule" size="0.05 0.2" quat="0 0 0 1"/>
    <mesh scale="2 2 2"/>
    <default class="arm">
      <geom type="box" size="0.1 0.2 0.3"/>
      <mesh scale="0.001 0.001 0.001"/>
      <default class="finger">
        <geom size="0.01 0.02 0.03" pos="0 0 0.5" euler="0 0 1"/>
      </default>
    </default>
    <default class="ball">
      <geom type="sphere" size="0.3" quat="1 0 0 0"/>
    </default>
  </default>
  <asset>
    <mesh name="big" file="cube_10cm.stl"/>
    <mesh name="small" class="arm" file="cube_10cm.stl"/>
  </asset>
  <worldbody>
    <body name="base">
      <geom/>
      <geom class="ball" pos="1 0 0"/>
      <geom type="mesh" mesh="big"/>
      <geom type="mesh" mesh="small" class="arm"/>
      <body name="arm1" childclass="arm">
        <geom/>
        <geom quat="0.5 0.5 0.5 0.5"/>
        <geom class="finger" quat="1 0 0 0"/>
        <geom class="finger"/>
        <body name="arm2">
          <geom size="0.5 0.5 0.5"/>
          <body name="tip" childclass="ball">
            <geom/>
            <geom class="main" pos="0 1 0"/>
            <geom class="arm" type="cylinder" size="0.2 0.4"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
)";

const char* const kExpanded = R"(<mujoco>
  <asset>
    <mesh name="big" file="cube_10cm.stl" scale="2 2 2"/>
    <mesh name="small" file="cube_10cm.stl" scale="0.001 0.001 0.001"/>
  </asset>
  <worldbody>
    <body name="base">
      <geom type="capsule" size="0.05 0.2" quat="0 0 0 1"/>
      <geom type="sphere" size="0.3" quat="1 0 0 0" pos="1 0 0"/>
      <geom type="mesh" mesh="big" quat="0 0 0 1"/>
      <geom type="mesh" mesh="small" quat="0 0 0 1"/>
      <body name="arm1">
        <geom type="box" size="0.1 0.2 0.3" quat="0 0 0 1"/>
        <geom type="box" size="0.1 0.2 0.3" quat="0.5 0.5 0.5 0.5"/>
        <geom type="box" size="0.01 0.02 0.03" pos="0 0 0.5" quat="1 0 0 0"/>
        <geom type="box" size="0.01 0.02 0.03" pos="0 0 0.5" euler="0 0 1"/>
        <body name="arm2">
          <geom type="box" size="0.5 0.5 0.5" quat="0 0 0 1"/>
          <body name="tip">
            <geom type="sphere" size="0.3" quat="1 0 0 0"/>
            <geom type="capsule" size="0.05 0.2" quat="0 0 0 1" pos="0 1 0"/>
            <geom type="cylinder" size="0.2 0.4" quat="0 0 0 1"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
</mujoco>
)";

void expect_same_geometry(const LinkGeometry& a, const LinkGeometry& b, const std::string& where) {
  SCOPED_TRACE(where);
  EXPECT_EQ(a.shape.kind, b.shape.kind);
  EXPECT_EQ(a.shape.radius, b.shape.radius);
  EXPECT_EQ(a.shape.length, b.shape.length);
  EXPECT_EQ(a.shape.size, b.shape.size);
  EXPECT_EQ(a.mesh_path, b.mesh_path);
  EXPECT_EQ(a.mesh_scale, b.mesh_scale);
  EXPECT_EQ(a.position_link, b.position_link);
  EXPECT_EQ(a.R_link_geometry, b.R_link_geometry);
}

TEST(MjcfDefaults, ModelWithClassesReadsAsTheModelExpandedByHand) {
  const RobotModel with = read_robot_model(kWithDefaults, "with.xml", kMeshDir);
  const RobotModel expanded = read_robot_model(kExpanded, "expanded.xml", kMeshDir);
  ASSERT_EQ(with.links.size(), 4u);
  ASSERT_EQ(expanded.links.size(), 4u);
  for (std::size_t i = 0; i < with.links.size(); ++i) {
    const RobotLink& a = with.links[i];
    const RobotLink& b = expanded.links[i];
    EXPECT_EQ(a.name, b.name);
    ASSERT_EQ(a.geometry.size(), b.geometry.size()) << a.name;
    for (std::size_t k = 0; k < a.geometry.size(); ++k)
      expect_same_geometry(a.geometry[k], b.geometry[k], a.name + " geom " + std::to_string(k));
    EXPECT_EQ(a.notes.size(), b.notes.size()) << a.name;
  }
  // Not vacuous: the classes did change the shapes (kinds of the first link, in file order).
  const RobotLink& base = with.links[0];
  ASSERT_EQ(base.geometry.size(), 4u);
  EXPECT_EQ(base.geometry[0].shape.kind, "capsule");
  EXPECT_EQ(base.geometry[0].shape.length, 0.4);  // MJCF half-length 0.2
  EXPECT_EQ(base.geometry[1].shape.kind, "sphere");
  EXPECT_EQ(base.geometry[2].mesh_scale, Vec3(2, 2, 2));
  EXPECT_EQ(base.geometry[3].mesh_scale, Vec3(0.001, 0.001, 0.001));
  // arm1: the geom's own quat wins over the class finger's euler; without one, the class's euler "0 0 1" is
  // a turn of 1° about z.
  const RobotLink& arm1 = with.links[1];
  ASSERT_EQ(arm1.geometry.size(), 4u);
  EXPECT_TRUE(arm1.notes.empty());
  EXPECT_EQ(arm1.geometry[2].shape.size, Vec3(0.02, 0.04, 0.06));
  EXPECT_EQ(arm1.geometry[2].R_link_geometry, Mat3::Identity());
  const double one_degree = std::numbers::pi / 180.0;
  Mat3 Rz;
  Rz << std::cos(one_degree), -std::sin(one_degree), 0, std::sin(one_degree), std::cos(one_degree), 0, 0, 0,
      1;
  POINSOT_EXPECT_MATRIX_NEAR(arm1.geometry[3].R_link_geometry, Rz, 1e-16);
  // tip: childclass ball, then class main and class arm over it.
  const RobotLink& tip = with.links[3];
  ASSERT_EQ(tip.geometry.size(), 3u);
  EXPECT_EQ(tip.geometry[0].shape.kind, "sphere");
  EXPECT_EQ(tip.geometry[1].shape.kind, "capsule");
  EXPECT_EQ(tip.geometry[2].shape.kind, "cylinder");
}

TEST(MjcfDefaults, InertialIsNotAffectedByDefaults) {
  // MuJoCo has no default values for <inertial>: a childclass changes only the geoms.
  const RobotModel m = read_robot_model(
      "<mujoco><default><default class=\"c\"><geom type=\"box\" size=\"1 1 1\"/></default></default>"
      "<worldbody><body childclass=\"c\"><inertial mass=\"2\" diaginertia=\"1 2 "
      "3\"/><geom/></body></worldbody>"
      "</mujoco>",
      "m.xml");
  ASSERT_EQ(m.links.size(), 1u);
  EXPECT_EQ(m.links[0].mass, 2.0);
  EXPECT_EQ(m.links[0].inertia_link, Mat3(Vec3(1, 2, 3).asDiagonal()));
  ASSERT_EQ(m.links[0].geometry.size(), 1u);
  EXPECT_EQ(m.links[0].geometry[0].shape.size, Vec3(2, 2, 2));
}

std::string mjcf_invalid_input(const std::string& text) {
  return test::message_of<InvalidInput>([&] { read_robot_model(text, "m.xml"); }, text);
}

TEST(MjcfDefaults, RefusalsNameTheElementAndTheClass) {
  expect_has(
      mjcf_invalid_input("<mujoco><worldbody><body><geom class=\"nope\"/></body></worldbody></mujoco>"),
      {"m.xml:1: <geom>", "class=\"nope\"", "no such default class"});
  expect_has(mjcf_invalid_input(
                 "<mujoco><worldbody><body childclass=\"nope\">\n<geom/></body></worldbody></mujoco>"),
             {"m.xml:2: <geom>", "class=\"nope\"", "no such default class"});
  expect_has(mjcf_invalid_input("<mujoco><asset><mesh class=\"x\" file=\"a.stl\"/></asset></mujoco>"),
             {"<mesh>", "class=\"x\""});
  expect_has(mjcf_invalid_input("<mujoco><default>\n<default><geom/></default></default></mujoco>"),
             {"m.xml:2: <default>", "nested <default> without class"});
  expect_has(mjcf_invalid_input(
                 "<mujoco><default><default class=\"a\"/>\n<default class=\"a\"/></default></mujoco>"),
             {"m.xml:2: <default>", "class=\"a\"", "defined twice"});
  expect_has(mjcf_invalid_input("<mujoco><default><default class=\"main\"/></default></mujoco>"),
             {"class=\"main\"", "defined twice"});
  // A malformed value given by a class is reported at the class's line.
  expect_has(mjcf_invalid_input("<mujoco><default>\n<geom pos=\"a b c\"/></default><worldbody><body><geom "
                                "type=\"sphere\" size=\"1\"/></body></worldbody></mujoco>"),
             {"m.xml:2: <geom>", "pos=\"a b c\"", "expected 3 finite numbers"});
}

}  // namespace
}  // namespace poinsot::io
