// Joint springs and dampers read from robot files (MJCF stiffness, damping, springref; URDF <dynamics
// damping>; SDF <axis><dynamics>) as multibody::JointSpring. Oracles: the files' numbers; the damped
// oscillator's closed form for a hinge and a slide of an MJCF file; the decay of a URDF wheel's spin,
// ω(t) = ω0 exp(−c t / I); what stays unmodelled listed.
#include <cmath>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "damped_oscillator.hpp"
#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::damped_oscillator;
using test::expect_has;

/// A wheel on a hinge about z and a cart on a slide along x, both to the world, in zero gravity. Angles in
/// degrees (MuJoCo's default): springref 30 is π/6 rad, as MuJoCo compiles it.
constexpr const char* kMjcf = R"(<mujoco model="springs">
  <option gravity="0 0 0"/>
  <worldbody>
    <body name="wheel">
      <joint name="spin" type="hinge" axis="0 0 1" stiffness="3" damping="0.2" springref="30"/>
      <inertial pos="0 0 0" mass="2" diaginertia="0.3 0.4 0.5"/>
    </body>
    <body name="cart" pos="1 0 0">
      <joint name="track" type="slide" axis="1 0 0" stiffness="5" damping="0.4" springref="-0.2"/>
      <inertial pos="0 0 0" mass="2" diaginertia="0.1 0.1 0.1"/>
    </body>
  </worldbody>
</mujoco>
)";

TEST(RobotJointSprings, MjcfHingeAndSlideAreTheDampedOscillators) {
  RobotSystemOptions o;
  o.positions["spin"] = {1.2};  // rad
  o.positions["track"] = {0.1};
  const multibody::Scenario sc = robot_scenario(read_robot_model(kMjcf, "springs.xml"), o);
  ASSERT_EQ(sc.system.joint_springs().size(), 2u);
  const multibody::JointSpring& spin = sc.system.joint_springs()[0];
  EXPECT_EQ(spin.stiffness, 3.0);
  EXPECT_EQ(spin.damping, 0.2);
  EXPECT_NEAR(spin.rest_position, std::numbers::pi / 6, 1e-16);
  const multibody::JointSpring& track = sc.system.joint_springs()[1];
  EXPECT_EQ(track.rest_position, -0.2);
  EXPECT_EQ(track.offset, 0.1);  // the slide starts at 0.1 m, where its points coincide
  for (const std::string& line : sc.not_modelled)
    EXPECT_EQ(line.find("spin"), std::string::npos) << line;

  multibody::ProjectedRk4 rk4(sc.system, 1e-3);
  multibody::State s = sc.initial;
  for (int n = 0; n < 2000; ++n)
    rk4.step(s);
  const Mat3& R = s.bodies[0].R_space_body;
  const double angle = std::atan2(R(1, 0), R(0, 0));
  const double w_spin = std::sqrt(3.0 / 0.5), z_spin = 0.2 / (2.0 * std::sqrt(3.0 * 0.5));
  const double w_track = std::sqrt(5.0 / 2.0), z_track = 0.4 / (2.0 * std::sqrt(5.0 * 2.0));
  // RK4 at ωh ≤ 2.5e-3 over 2 s: global errors ~ (ωh)⁴ ωT/100 of the amplitude, about 1e-12 for the wheel
  // (measured 7.4e-13 rad) and 1e-13 for the cart (measured 1.1e-14 m).
  EXPECT_NEAR(angle,
              std::numbers::pi / 6 + damped_oscillator(1.2 - std::numbers::pi / 6, w_spin, z_spin, s.time),
              5e-12);
  EXPECT_NEAR(s.bodies[1].x_space.x() - 1.0, -0.2 + damped_oscillator(0.3, w_track, z_track, s.time), 1e-12);
}

// Two hinges of one body about one point become a universal joint whose two angles keep their springs: the
// first hinge's on the angle about the parent's axis (coordinate b), the second's about the child's (a), each
// resting at springref − ref (degrees in the file). At the file's pose both angles are 0, so the springs hold
// Σ ½ k (springref − ref)² beside gravity's −Σ m g·x. (Their motion against MuJoCo's:
// bench/peers/robot_files_mujoco.cpp, "universal springs".)
TEST(RobotJointSprings, MjcfHingesMergedIntoAUniversalJointKeepTheirSprings) {
  const multibody::Scenario sc =
      load_robot_scenario(std::string(POINSOT_TEST_DATA_DIR) + "/models/robots/universal_springs.xml");
  const auto& springs = sc.system.joint_springs();
  ASSERT_EQ(springs.size(), 4u);
  using Coordinate = multibody::JointSpring::Coordinate;
  const double deg = std::numbers::pi / 180.0;
  const struct {
    const char* joint;
    Coordinate coordinate;
    double k, c, rest;
  } expected[] = {{"pin_y+pin_x", Coordinate::b, 4.0, 0.2, 20 * deg},
                  {"pin_y+pin_x", Coordinate::a, 2.5, 0.1, -10 * deg},
                  {"knee_z+knee_x", Coordinate::b, 1.0, 0.05, 5 * deg},
                  {"knee_z+knee_x", Coordinate::a, 3.0, 0.05, (-20 - 15) * deg}};
  double spring_energy = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    const multibody::JointSpring& s = springs[i];
    EXPECT_EQ(sc.system.joints()[static_cast<std::size_t>(s.joint)].name, expected[i].joint) << i;
    EXPECT_EQ(sc.system.joints()[static_cast<std::size_t>(s.joint)].type, multibody::JointType::universal);
    EXPECT_EQ(s.coordinate, expected[i].coordinate) << i;
    EXPECT_EQ(s.stiffness, expected[i].k) << i;
    EXPECT_EQ(s.damping, expected[i].c) << i;
    EXPECT_NEAR(s.rest_position, expected[i].rest, 1e-15) << i;
    spring_energy += 0.5 * expected[i].k * expected[i].rest * expected[i].rest;
  }
  double gravity_energy = 0.0;
  for (std::size_t i = 0; i < sc.system.bodies().size(); ++i)
    gravity_energy -= sc.system.bodies()[i].mass * sc.system.gravity().dot(sc.initial.bodies[i].x_space);
  EXPECT_NEAR(multibody::potential_energy(sc.system, sc.initial.bodies) - gravity_energy, spring_energy,
              1e-14);
  for (const std::string& line : sc.not_modelled)
    EXPECT_EQ(line.find("spring"), std::string::npos) << line;
}

TEST(RobotJointSprings, MjcfRefIsTheCoordinateOfTheFilesPose) {
  // As MuJoCo's qpos0: a hinge with ref = 30° is at 30° in the file's pose; springref is in the same
  // coordinates. A slide with ref = 0.5 m likewise.
  constexpr const char* mjcf = R"(<mujoco model="ref">
  <option gravity="0 0 0"/>
  <worldbody>
    <body name="arm">
      <joint name="j" type="hinge" axis="0 0 1" ref="30" stiffness="2" springref="50"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.1"/>
    </body>
    <body name="cart" pos="1 0 0">
      <joint name="s" type="slide" axis="1 0 0" ref="0.5" stiffness="1" springref="0.4"/>
      <inertial pos="0 0 0" mass="1" diaginertia="0.1 0.1 0.1"/>
    </body>
  </worldbody>
</mujoco>
)";
  const RobotModel model = read_robot_model(mjcf, "ref.xml");
  const multibody::Scenario at_ref = robot_scenario(model);
  EXPECT_EQ(at_ref.initial.bodies[0].R_space_body, Mat3::Identity());
  EXPECT_EQ(at_ref.initial.bodies[1].x_space, Vec3(1, 0, 0));
  ASSERT_EQ(at_ref.system.joint_springs().size(), 2u);
  EXPECT_NEAR(at_ref.system.joint_springs()[0].rest_position, 20.0 * std::numbers::pi / 180, 1e-16);
  EXPECT_NEAR(at_ref.system.joint_springs()[1].rest_position, -0.1, 1e-16);
  EXPECT_EQ(at_ref.system.joint_springs()[1].offset, 0.0);
  RobotSystemOptions o;
  o.positions["j"] = {std::numbers::pi / 6 + 0.2};
  o.positions["s"] = {0.7};
  const multibody::Scenario moved = robot_scenario(model, o);
  POINSOT_EXPECT_MATRIX_NEAR(moved.initial.bodies[0].R_space_body,
                             Eigen::AngleAxisd(0.2, Vec3::UnitZ()).toRotationMatrix(), 1e-15);
  EXPECT_NEAR(moved.initial.bodies[1].x_space.x(), 1.2, 1e-15);
  EXPECT_NEAR(moved.system.joint_springs()[1].offset, 0.2, 1e-15);
  // The spring energy at these positions: ½ k (q − springref)² for each, in the file's coordinates.
  const double expected = 0.5 * 2.0 * std::pow(std::numbers::pi / 6 + 0.2 - 5 * std::numbers::pi / 18, 2) +
                          0.5 * 1.0 * std::pow(0.7 - 0.4, 2);
  EXPECT_NEAR(multibody::potential_energy(moved.system, moved.initial.bodies), expected, 1e-15);
}

TEST(RobotJointSprings, UrdfDampingSlowsAWheelExponentially) {
  // A URDF gives damping only (and friction, which is listed): a wheel spinning about z at 4 rad/s in zero
  // gravity slows as ω0 exp(−c t / I_zz).
  constexpr const char* urdf = R"(<robot name="wheel">
  <link name="world"/>
  <joint name="axle" type="continuous">
    <parent link="world"/><child link="wheel"/>
    <axis xyz="0 0 1"/>
    <dynamics damping="0.05" friction="0.01"/>
  </joint>
  <link name="wheel">
    <inertial><mass value="1"/><inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.2"/></inertial>
  </link>
</robot>
)";
  RobotSystemOptions o;
  o.gravity = Vec3::Zero();
  o.velocities["axle"] = {4.0};
  const multibody::Scenario sc = robot_scenario(read_robot_model(urdf, "wheel.urdf"), o);
  ASSERT_EQ(sc.system.joint_springs().size(), 1u);
  EXPECT_EQ(sc.system.joint_springs()[0].damping, 0.05);
  EXPECT_EQ(sc.system.joint_springs()[0].stiffness, 0.0);
  std::string all;
  for (const std::string& line : sc.not_modelled)
    all += line + "\n";
  expect_has(all, {"<joint name=\"axle\">", "friction"});
  multibody::ProjectedRk4 rk4(sc.system, 1e-3);
  multibody::State s = sc.initial;
  for (int n = 0; n < 1000; ++n)
    rk4.step(s);
  // RK4 on ω̇ = −(c/I) ω at (c/I) h = 2.5e-4: relative error ~ (ch/I)⁴ t c/I / 120, below 1e-15.
  EXPECT_NEAR(s.bodies[0].omega_body.z(), 4.0 * std::exp(-0.05 * s.time / 0.2), 1e-12);
}

TEST(RobotJointSprings, SdfAxisDynamicsAndWhatStaysUnmodelled) {
  constexpr const char* sdf = R"(<sdf version="1.7">
  <model name="m">
    <link name="arm"><inertial><mass>1</mass><inertia><ixx>0.1</ixx><iyy>0.1</iyy><izz>0.1</izz></inertia></inertial></link>
    <joint name="pivot" type="revolute">
      <parent>world</parent><child>arm</child>
      <axis><xyz>0 1 0</xyz><dynamics><damping>0.3</damping><friction>0.1</friction><spring_reference>0.25</spring_reference><spring_stiffness>7</spring_stiffness></dynamics></axis>
    </joint>
  </model>
</sdf>
)";
  const multibody::Scenario sc = robot_scenario(read_robot_model(sdf, "m.sdf"));
  ASSERT_EQ(sc.system.joint_springs().size(), 1u);
  const multibody::JointSpring& s = sc.system.joint_springs()[0];
  EXPECT_EQ(s.stiffness, 7.0);
  EXPECT_EQ(s.damping, 0.3);
  EXPECT_EQ(s.rest_position, 0.25);
  std::string all;
  for (const std::string& line : sc.not_modelled)
    all += line + "\n";
  expect_has(all, {"<axis><dynamics><friction>"});

  // Left out on request: listed instead.
  RobotSystemOptions off;
  off.joint_springs = false;
  const multibody::Scenario without = robot_scenario(read_robot_model(sdf, "m.sdf"), off);
  EXPECT_TRUE(without.system.joint_springs().empty());
  all.clear();
  for (const std::string& line : without.not_modelled)
    all += line + "\n";
  expect_has(all, {"the spring and damper of \"pivot\" (left out: joint_springs = false)"});
}

}  // namespace
}  // namespace poinsot::io
