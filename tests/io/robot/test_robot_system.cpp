// Tests of robot_system.hpp: robot files (URDF, MJCF, SDF) as multibody systems. Oracles: the same double
// pendulum written by hand as a poinsot scenario (bit for bit), poses composed by hand from the files'
// numbers, initial velocities against finite differences of the poses, each joint kind's type and the
// conserved quantities of its run, closed loops held to round-off, bad files refused with one line.
#include "poinsot/io/robot/robot_system.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/scenario_file.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using multibody::JointType;
using multibody::kWorld;
using test::expect_has;
using test::max_abs_diff;
using test::message_of;

std::string robots(const std::string& name) {
  return std::string(POINSOT_TEST_DATA_DIR "/models/robots/") + name;
}

/// Joint types by name.
std::map<std::string, JointType> joint_types_of(const multibody::System& s) {
  std::map<std::string, JointType> m;
  for (const multibody::Joint& j : s.joints())
    m[j.name] = j.type;
  return m;
}

std::vector<std::string> body_names(const multibody::System& s) {
  std::vector<std::string> names;
  for (const multibody::Body& b : s.bodies())
    names.push_back(b.name);
  return names;
}

multibody::State run_rk4(const multibody::Scenario& sc, int steps, double* energy_error = nullptr,
                         double* gap = nullptr) {
  multibody::ProjectedRk4 rk4(sc.system, sc.dt);
  multibody::State s = sc.initial;
  const double e0 = multibody::total_energy(sc.system, s);
  double de = 0.0, g = 0.0;
  for (int k = 0; k < steps; ++k) {
    rk4.step(s);
    de = std::max(de, std::abs(multibody::total_energy(sc.system, s) - e0));
    g = std::max(g, multibody::constraint_violation(sc.system, s).joint_gap);
  }
  if (energy_error != nullptr) *energy_error = de;
  if (gap != nullptr) *gap = g;
  return s;
}

TEST(RobotSystem, DoublePendulumOfEachFormatIsTheHandWrittenScenarioBitForBit) {
  const multibody::Scenario ref = load_multibody_scenario(robots("pendulum2.toml"));
  for (const char* file : {"pendulum2.urdf", "pendulum2.xml", "pendulum2.sdf"}) {
    SCOPED_TRACE(file);
    const multibody::Scenario sc = load_robot_scenario(robots(file));
    ASSERT_EQ(sc.system.body_count(), 2);
    ASSERT_EQ(sc.system.joint_count(), 2);
    EXPECT_EQ(sc.system.gravity(), ref.system.gravity());
    for (int i = 0; i < 2; ++i) {
      const auto& a = sc.system.bodies()[static_cast<std::size_t>(i)];
      const auto& b = ref.system.bodies()[static_cast<std::size_t>(i)];
      EXPECT_EQ(a.name, b.name);
      EXPECT_EQ(a.mass, b.mass);
      EXPECT_EQ(a.poinsot, b.poinsot);
      const auto& ja = sc.system.joints()[static_cast<std::size_t>(i)];
      const auto& jb = ref.system.joints()[static_cast<std::size_t>(i)];
      EXPECT_EQ(ja.name, jb.name);
      EXPECT_EQ(ja.type, jb.type);
      EXPECT_EQ(ja.body_a, jb.body_a);
      EXPECT_EQ(ja.body_b, jb.body_b);
      EXPECT_EQ(ja.point_a, jb.point_a);
      EXPECT_EQ(ja.point_b, jb.point_b);
      for (int k = 0; k < 2; ++k) {
        EXPECT_EQ(ja.p_a[static_cast<std::size_t>(k)], jb.p_a[static_cast<std::size_t>(k)]);
        EXPECT_EQ(ja.u_b[static_cast<std::size_t>(k)], jb.u_b[static_cast<std::size_t>(k)]);
      }
    }
    // The joints' dampers (each file's, the scenario's `damping` keys), with the same zero.
    ASSERT_EQ(sc.system.joint_springs().size(), 2u);
    ASSERT_EQ(ref.system.joint_springs().size(), 2u);
    for (std::size_t k = 0; k < 2; ++k) {
      const multibody::JointSpring& a = sc.system.joint_springs()[k];
      const multibody::JointSpring& b = ref.system.joint_springs()[k];
      EXPECT_EQ(a.joint, b.joint);
      EXPECT_EQ(a.stiffness, b.stiffness);
      EXPECT_EQ(a.damping, b.damping);
      EXPECT_EQ(a.rest_position, b.rest_position);
      EXPECT_EQ(a.R_b_a_zero, b.R_b_a_zero);
    }
    // The same system from the same state: RATTLE's trajectories are the same bits.
    multibody::Rattle ra(sc.system, 1e-3), rb(ref.system, 1e-3);
    multibody::State sa = sc.initial, sb = ref.initial;
    for (int k = 0; k < 300; ++k) {
      ra.step(sa);
      rb.step(sb);
    }
    for (std::size_t i = 0; i < 2; ++i) {
      EXPECT_EQ(sa.bodies[i].x_space, sb.bodies[i].x_space);
      EXPECT_EQ(sa.bodies[i].R_space_body, sb.bodies[i].R_space_body);
      EXPECT_EQ(sa.bodies[i].omega_body, sb.bodies[i].omega_body);
    }
    EXPECT_GT(std::abs(sa.bodies[1].x_space.z()), 0.1);  // it fell
  }
}

TEST(RobotSystem, NotModelledFeaturesAreListed) {
  const multibody::Scenario urdf = load_robot_scenario(robots("pendulum2.urdf"));
  ASSERT_EQ(urdf.not_modelled.size(), 1u);
  expect_has(urdf.not_modelled[0], {"<joint name=\"shoulder\">", "line 6", "limits"});
  const multibody::Scenario mjcf = load_robot_scenario(robots("pendulum2.xml"));
  std::string all;
  for (const std::string& line : mjcf.not_modelled)
    all += line + "\n";
  expect_has(all, {"contacts between the links' shapes (1 shapes)", "friction loss", "shoulder",
                   "<actuator> line 16"});
}

TEST(RobotSystem, UrdfJointKinds) {
  const multibody::Scenario sc = load_robot_scenario(robots("joints.urdf"));
  // The massless flange is a frame of the carriage; the drone floats (no joint).
  EXPECT_EQ(body_names(sc.system), (std::vector<std::string>{"base", "carriage", "arm", "hand", "drone"}));
  const auto types = joint_types_of(sc.system);
  EXPECT_EQ(types, (std::map<std::string, JointType>{{"base", JointType::weld},
                                                     {"rail", JointType::prismatic},
                                                     {"wrist", JointType::hinge},
                                                     {"hand_mount", JointType::weld}}));
  // The arm's frame composed by hand: rail origin (z 0.1, yaw 0.5), flange (z 0.05, roll π/2), wrist (y
  // 0.02).
  const Mat3 R_rail = so3::rotation_from_axis_angle(Vec3::UnitZ(), 0.5);
  const Mat3 R_flange = so3::rotation_from_axis_angle(Vec3::UnitX(), std::numbers::pi / 2);
  const Vec3 origin = Vec3(0, 0, 0.1) + R_rail * (Vec3(0, 0, 0.05) + R_flange * Vec3(0, 0.02, 0));
  const Mat3 R_arm = R_rail * R_flange;
  const Vec3 com_arm = origin + R_arm * Vec3(0.15, 0, 0);
  const multibody::BodyState& arm = sc.initial.bodies[2];
  POINSOT_EXPECT_MATRIX_NEAR(arm.R_space_body, R_arm, 1e-15);
  POINSOT_EXPECT_MATRIX_NEAR(arm.x_space, com_arm, 1e-15);
  // The wrist's axis (0, 0, 2) of the arm's frame, normalised, fixed in the carriage as R_flange z.
  const multibody::Joint& wrist = sc.system.joints()[2];
  EXPECT_EQ(wrist.body_b, 1);
  // Its point on the carriage: the flange origin plus R_flange (0, 0.02, 0), from the carriage's centre of
  // mass.
  POINSOT_EXPECT_MATRIX_NEAR(wrist.point_b,
                             Vec3(0, 0, 0.05) + R_flange * Vec3(0, 0.02, 0) - Vec3(0.01, 0, 0.02), 1e-16);
  POINSOT_EXPECT_MATRIX_NEAR(wrist.point_a, -Vec3(0.15, 0, 0), 1e-16);
  // Gravity (URDF gives none): the default; the run conserves energy and keeps the joints.
  EXPECT_EQ(sc.system.gravity(), Vec3(0, 0, -9.81));
  double de = 0.0, gap = 0.0;
  const multibody::State end = run_rk4(sc, 300, &de, &gap);
  EXPECT_LT(gap, 1e-12);
  EXPECT_LT(de, 1e-9);
  // The drone falls freely: z = 1 − g t²/2.
  EXPECT_NEAR(end.bodies[4].x_space.z(), 1.0 - 0.5 * 9.81 * 0.09, 1e-12);
}

TEST(RobotSystem, UrdfFloatingBaseAndInertiaFromGeometry) {
  RobotSystemOptions o;
  o.floating_base = true;
  o.inertia = RobotInertiaSource::geometry;
  o.gravity = Vec3::Zero();
  o.base_velocity = Vec3(0.1, 0.0, 0.0);
  o.base_omega_body = Vec3(0.0, 0.0, 0.5);
  const multibody::Scenario sc = load_robot_scenario(robots("joints.urdf"), o);
  EXPECT_EQ(joint_types_of(sc.system).count("base"), 0u);  // the root floats
  // The base's tensor: a 0.4 × 0.2 × 0.1 box of 4 kg.
  const Mat3 J = sc.system.bodies()[0].inertia;
  POINSOT_EXPECT_MATRIX_NEAR(
      J, Vec3(4.0 / 12 * 0.05, 4.0 / 12 * 0.17, 4.0 / 12 * 0.2).asDiagonal().toDenseMatrix(), 1e-15);
  // A free system in zero gravity: its momenta are conserved.
  const Vec3 p0 = multibody::linear_momentum(sc.system, sc.initial);
  const Vec3 L0 = multibody::angular_momentum(sc.system, sc.initial);
  // RATTLE conserves them to round-off.
  multibody::Rattle rattle(sc.system, 1e-3);
  multibody::State end = sc.initial;
  for (int k = 0; k < 200; ++k)
    rattle.step(end);
  POINSOT_EXPECT_MATRIX_NEAR(multibody::linear_momentum(sc.system, end), p0, 1e-12);
  POINSOT_EXPECT_MATRIX_NEAR(multibody::angular_momentum(sc.system, end), L0, 1e-10);
}

TEST(RobotSystem, UrdfMeshesAreDrawnAsTheFilesTriangles) {
  // valid_arm.urdf's hand is a 10 cm cube given as an STL mesh, its centre of mass at its link's origin: its
  // drawn surface is the mesh's triangles as read, unmoved; an unreadable mesh is not drawn.
  const std::string arm = std::string(POINSOT_TEST_DATA_DIR) + "/models/valid_arm.urdf";
  const multibody::Scenario sc = load_robot_scenario(arm);
  const int hand = sc.system.body_index("hand");
  ASSERT_GE(hand, 0);
  const auto& surface = sc.body_surfaces[static_cast<std::size_t>(hand)];
  ASSERT_NE(surface, nullptr);
  const inertia::TriangleMesh cube =
      inertia::load_mesh(std::string(POINSOT_TEST_DATA_DIR) + "/inertia/cube_10cm.stl");
  ASSERT_EQ(surface->vertices.size(), cube.vertices.size());
  ASSERT_EQ(surface->triangles.size(), cube.triangles.size());
  for (std::size_t k = 0; k < cube.vertices.size(); ++k)
    EXPECT_EQ(surface->vertices[k], cube.vertices[k]);
  std::ifstream in(arm);
  std::stringstream text;
  text << in.rdbuf();
  const multibody::Scenario missing =
      robot_scenario(read_robot_model(text.str(), "arm.urdf", "/nonexistent"));
  EXPECT_EQ(missing.body_surfaces[static_cast<std::size_t>(hand)], nullptr);
}

TEST(RobotSystem, MjcfMeshesAreDrawnInTheGeomFrameAsWritten) {
  // MuJoCo shows a mesh geom's vertices at the body's and the geom's frames as written, the file's vertices
  // scaled (it re-centres the mesh and moves the geom's frame back; docs/robot_models.md has the measurement
  // against MuJoCo). The drawn surface is about the body's centre of mass (<inertial pos>).
  const multibody::Scenario sc = load_robot_scenario(robots("mesh_geom.xml"));
  ASSERT_EQ(sc.system.body_count(), 1);
  const auto& surface = sc.body_surfaces[0];
  ASSERT_NE(surface, nullptr);
  const inertia::TriangleMesh raw =
      inertia::load_mesh(std::string(POINSOT_SOURCE_DIR) + "/examples/meshes/l_bracket.obj");
  ASSERT_EQ(surface->vertices.size(), raw.vertices.size());
  const Mat3 R_geom = Eigen::Quaterniond(0.8, -0.3, 0.2, 0.4).normalized().toRotationMatrix();
  for (std::size_t k = 0; k < raw.vertices.size(); ++k) {
    const Vec3 expected = R_geom * Vec3(1.5, 1.0, 0.8).cwiseProduct(raw.vertices[k]) +
                          Vec3(0.05, -0.02, 0.01) - Vec3(0.01, 0.02, -0.01);
    POINSOT_EXPECT_MATRIX_NEAR(surface->vertices[k], expected, 1e-15);
  }
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies[0].R_space_body,
                             Eigen::Quaterniond(0.9, 0.1, -0.2, 0.3).normalized().toRotationMatrix(), 1e-15);
}

TEST(RobotSystem, MjcfJointKinds) {
  const multibody::Scenario sc = load_robot_scenario(robots("joints.xml"));
  EXPECT_EQ(body_names(sc.system), (std::vector<std::string>{"post", "crank", "slider", "bob", "gimbal",
                                                             "hip", "foot", "heel", "puck"}));
  EXPECT_EQ(joint_types_of(sc.system),
            (std::map<std::string, JointType>{{"post", JointType::weld},
                                              {"crank_hinge", JointType::hinge},
                                              {"slide_x", JointType::prismatic},
                                              {"bob_ball", JointType::ball},
                                              {"gimbal_z+gimbal_x", JointType::universal},
                                              {"hip_x+hip_z+hip_y", JointType::ball},
                                              {"foot", JointType::weld},
                                              {"heel_y+heel_x", JointType::universal}}));
  // The heel's hinges: y through (0, 0, 0.04), then x + z/2 through the origin (heel frame). The second axis
  // is 0.04 m · (e₂ × e₁)·(−z) = 0.04/√1.25 m from the first, on the side of −(e₂ × e₁).
  for (const multibody::Joint& j : sc.system.joints()) {
    if (j.name == "heel_y+heel_x") {
      EXPECT_NEAR(j.axis_offset, -0.04 / std::sqrt(1.25), 1e-15);
    } else {
      EXPECT_EQ(j.axis_offset, 0.0) << j.name;
    }
  }
  // Inertia from the geoms at 1000 kg/m³: the post is a 0.1 m cube, the bob a sphere of radius 0.03 plus a
  // cylinder of 0.05 kg.
  EXPECT_NEAR(sc.system.bodies()[0].mass, 1.0, 1e-15);
  EXPECT_NEAR(sc.system.bodies()[3].mass, 1000.0 * 4.0 / 3.0 * std::numbers::pi * 0.027e-3 + 0.05, 1e-15);
  // The crank's frame: post (z 1) then y 0.1 and euler 30° (degrees, rotating x y z: a turn about z).
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies[1].R_space_body,
                             so3::rotation_from_axis_angle(Vec3::UnitZ(), std::numbers::pi / 6), 1e-15);
  std::string all;
  for (const std::string& line : sc.not_modelled)
    all += line + "\n";
  // The crank's spring is modelled, and so is the damper of gimbal_x, the second of the two hinges merged
  // into a universal joint: it turns about the child's axis (coordinate a).
  expect_has(all, {"<joint> friction loss: 10 joint(s)"});
  EXPECT_EQ(all.find("crank_hinge\""), std::string::npos) << all;
  EXPECT_EQ(all.find("gimbal_x\""), std::string::npos) << all;
  ASSERT_EQ(sc.system.joint_springs().size(), 3u);
  const auto& springs = sc.system.joint_springs();
  EXPECT_EQ(sc.system.joints()[static_cast<std::size_t>(springs[0].joint)].name, "crank_hinge");
  EXPECT_EQ(springs[0].stiffness, 2.0);
  EXPECT_EQ(sc.system.joints()[static_cast<std::size_t>(springs[1].joint)].name, "gimbal_z+gimbal_x");
  EXPECT_EQ(springs[1].coordinate, multibody::JointSpring::Coordinate::a);
  EXPECT_EQ(springs[1].stiffness, 0.0);
  EXPECT_EQ(springs[1].damping, 0.3);
  EXPECT_EQ(sc.system.joints()[static_cast<std::size_t>(springs[2].joint)].name, "heel_y+heel_x");
  EXPECT_EQ(springs[2].coordinate, multibody::JointSpring::Coordinate::b);
  EXPECT_EQ(springs[2].stiffness, 2.0);
  double de = 0.0, gap = 0.0;
  run_rk4(sc, 300, &de, &gap);
  EXPECT_LT(gap, 1e-12);
  EXPECT_LT(de, 1e-8);
  // The drawn surfaces (view.html): every body's geoms about its centre of mass; the post's cube of half-size
  // 0.05 m, the crank's capsule from its pin (x = 0, less the 0.02 m cap) to x = 0.22 m in its frame.
  ASSERT_EQ(sc.body_surfaces.size(), 9u);
  for (const auto& surface : sc.body_surfaces)
    EXPECT_NE(surface, nullptr);
  double post = 0.0;
  for (const Vec3& v : sc.body_surfaces[0]->vertices)
    post = std::max(post, v.cwiseAbs().maxCoeff());
  EXPECT_NEAR(post, 0.05, 1e-15);
  const multibody::BodyState& crank = sc.initial.bodies[1];
  const Vec3 pin_to_com = crank.R_space_body.transpose() * (crank.x_space - Vec3(0, 0.1, 1));
  double lo = 1.0, hi = -1.0;
  for (const Vec3& v : sc.body_surfaces[1]->vertices) {
    lo = std::min(lo, v.x() + pin_to_com.x());
    hi = std::max(hi, v.x() + pin_to_com.x());
  }
  EXPECT_NEAR(lo, -0.02, 1e-12);
  EXPECT_NEAR(hi, 0.22, 1e-12);
}

TEST(RobotSystem, SdfJointKinds) {
  const multibody::Scenario sc = load_robot_scenario(robots("joints.sdf"));
  EXPECT_EQ(body_names(sc.system),
            (std::vector<std::string>{"tower", "arm", "slide", "pendant", "cardan", "cap", "satellite"}));
  EXPECT_EQ(joint_types_of(sc.system), (std::map<std::string, JointType>{{"base_fix", JointType::weld},
                                                                         {"shoulder", JointType::hinge},
                                                                         {"rail", JointType::prismatic},
                                                                         {"pivot", JointType::ball},
                                                                         {"cross", JointType::universal},
                                                                         {"cap_fix", JointType::weld}}));
  EXPECT_EQ(sc.system.gravity(), Vec3(0, 0, -9.8));
  // The model's pose (z 1, yaw 0.2) composed with the slide's (x 0.4, pitch 0.3).
  const Mat3 R_model = so3::rotation_from_axis_angle(Vec3::UnitZ(), 0.2);
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies[2].R_space_body,
                             R_model * so3::rotation_from_axis_angle(Vec3::UnitY(), 0.3), 1e-15);
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies[2].x_space, Vec3(0, 0, 1) + R_model * Vec3(0.4, 0, 0), 1e-15);
  // The ball's point on the pendant: the joint's pose (z 0.2 in the pendant's frame) from its centre of mass.
  EXPECT_EQ(sc.system.joints()[3].point_a, Vec3(0, 0, 0.25));
  double de = 0.0, gap = 0.0;
  const multibody::State end = run_rk4(sc, 300, &de, &gap);
  EXPECT_LT(gap, 1e-12);
  EXPECT_LT(de, 1e-9);
  EXPECT_NEAR(end.bodies[6].x_space.z(), 1.0 - 0.5 * 9.8 * 0.09, 1e-12);  // the free satellite falls
}

TEST(RobotSystem, MjcfOrientationsAreMuJoCos) {
  // Each geom turns its z axis onto space x, written five ways; the angles in degrees (MuJoCo's default).
  const std::string text =
      "<mujoco><worldbody><body name=\"b\" euler=\"90 90 0\">\n"
      "<geom type=\"capsule\" size=\"0.01 0.1\" zaxis=\"2 0 0\"/>\n"
      "<geom type=\"capsule\" size=\"0.01 0.1\" euler=\"0 90 0\"/>\n"
      "<geom type=\"capsule\" size=\"0.01 0.1\" axisangle=\"0 1 0 90\"/>\n"
      "<geom type=\"capsule\" size=\"0.01 0.1\" xyaxes=\"0 0 -1 0 1 0\"/>\n"
      "<geom type=\"capsule\" size=\"0.01 0.1\" quat=\"1 0 1 0\"/>\n"
      "<joint type=\"ball\"/></body></worldbody></mujoco>\n";
  const RobotModel model = read_robot_model(text, "o.xml");
  ASSERT_EQ(model.links[0].geometry.size(), 5u);
  for (const LinkGeometry& g : model.links[0].geometry)
    POINSOT_EXPECT_MATRIX_NEAR(g.R_link_geometry * Vec3::UnitZ(), Vec3::UnitX(), 1e-15);
  // The body's euler "90 90 0" about axes that rotate with the frame (eulerseq "xyz"): R = R_x(90°) R_y(90°);
  // about fixed axes ("XYZ"): R = R_y(90°) R_x(90°).
  const Mat3 Rx = so3::rotation_from_axis_angle(Vec3::UnitX(), std::numbers::pi / 2);
  const Mat3 Ry = so3::rotation_from_axis_angle(Vec3::UnitY(), std::numbers::pi / 2);
  POINSOT_EXPECT_MATRIX_NEAR(robot_scenario(model).initial.bodies[0].R_space_body, Rx * Ry, 1e-15);
  std::string fixed = text;
  fixed.replace(fixed.find("<worldbody>"), 0, "<compiler eulerseq=\"XYZ\"/>");
  POINSOT_EXPECT_MATRIX_NEAR(robot_scenario(read_robot_model(fixed, "o.xml")).initial.bodies[0].R_space_body,
                             Ry * Rx, 1e-15);
  std::string radians = text;
  radians.replace(radians.find("<worldbody>"), 0, "<compiler angle=\"radian\"/>");
  radians.replace(radians.find("euler=\"0 90 0\""), 14, "euler=\"0 1.5707963267948966 0\"");
  POINSOT_EXPECT_MATRIX_NEAR(read_robot_model(radians, "o.xml").links[0].geometry[1].R_link_geometry,
                             model.links[0].geometry[1].R_link_geometry, 1e-16);
  expect_has(message_of([&] {
               std::string mixed = text;
               mixed.replace(mixed.find("<worldbody>"), 0, "<compiler eulerseq=\"xYz\"/>");
               read_robot_model(mixed, "o.xml");
             }),
             {"o.xml:3: <geom> euler: <compiler eulerseq=\"xYz\">: expected three of x, y, z"});
}

/// The scenario at joint coordinates `q` (and velocities `v`), MJCF joints.xml.
multibody::Scenario joints_at(const std::map<std::string, std::vector<double>>& q,
                              const std::map<std::string, std::vector<double>>& v = {},
                              std::optional<Vec3> base_velocity = std::nullopt,
                              std::optional<Vec3> base_omega = std::nullopt) {
  RobotSystemOptions o;
  o.positions = q;
  o.velocities = v;
  o.base_velocity = base_velocity;
  o.base_omega_body = base_omega;
  return load_robot_scenario(robots("joints.xml"), o);
}

TEST(RobotSystem, InitialVelocitiesAreTheDerivativesOfThePoses) {
  // Positions and rates of every joint; the ball's rate ω is in the child's frame, so its quaternion moves
  // as q(t) = q0 ⊗ exp(ω t / 2).
  const Quat q0 = Quat(0.9, 0.1, -0.3, 0.2).normalized();
  const Vec3 w_ball(0.7, -0.4, 1.1);
  std::map<std::string, std::vector<double>> rates = {
      {"crank_hinge", {0.8}}, {"slide_x", {-0.3}},  {"bob_ball", {w_ball.x(), w_ball.y(), w_ball.z()}},
      {"gimbal_z", {0.5}},    {"gimbal_x", {-1.2}}, {"hip_x", {0.3}},
      {"hip_z", {0.9}},       {"hip_y", {-0.6}},    {"heel_y", {1.3}},
      {"heel_x", {-0.7}}};
  const std::map<std::string, double> angles = {{"crank_hinge", 0.4}, {"slide_x", 0.05}, {"gimbal_z", 0.3},
                                                {"gimbal_x", -0.2},   {"hip_x", 0.25},   {"hip_z", -0.4},
                                                {"hip_y", 0.6},       {"heel_y", -0.5},  {"heel_x", 0.35}};
  const auto at = [&](double t) {
    std::map<std::string, std::vector<double>> q;
    for (const auto& [name, a] : angles)
      q[name] = {a + t * rates.at(name)[0]};
    const double wn = w_ball.norm();
    const Quat dq(std::cos(wn * t / 2), 0, 0, 0);
    const Vec3 im = std::sin(wn * t / 2) * w_ball / wn;
    const Quat qt = q0 * Quat(dq.w(), im.x(), im.y(), im.z());
    q["bob_ball"] = {qt.w(), qt.x(), qt.y(), qt.z()};
    return q;
  };
  const Vec3 puck_v(0.2, -0.1, 0.3), puck_w(1.0, 2.0, -0.5);
  const multibody::Scenario sc = joints_at(at(0.0), rates, puck_v, puck_w);
  const double h = 1e-6;
  const multibody::Scenario plus = joints_at(at(h)), minus = joints_at(at(-h));
  for (std::size_t i = 0; i + 1 < sc.initial.bodies.size(); ++i) {  // the puck's pose does not move here
    SCOPED_TRACE(sc.system.bodies()[i].name);
    const auto& s = sc.initial.bodies[i];
    const Vec3 v_fd = (plus.initial.bodies[i].x_space - minus.initial.bodies[i].x_space) / (2 * h);
    const Mat3 Rdot = (plus.initial.bodies[i].R_space_body - minus.initial.bodies[i].R_space_body) / (2 * h);
    const Mat3 W = s.R_space_body.transpose() * Rdot;
    // Central differences: O(h²) ~ 1e-12 of the second derivatives, plus round-off ε/h ~ 2e-10.
    POINSOT_EXPECT_MATRIX_NEAR(s.v_space, v_fd, 1e-8);
    POINSOT_EXPECT_MATRIX_NEAR(s.omega_body, Vec3(W(2, 1), W(0, 2), W(1, 0)), 1e-8);
  }
  // The free puck: its origin's velocity and body rate as given (its frame's origin is its centre of mass).
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies.back().v_space, puck_v, 1e-15);
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies.back().omega_body, puck_w, 1e-15);
}

TEST(RobotSystem, MjcfLoopsAreClosedByConnectAndWeld) {
  RobotSystemOptions o;
  o.velocities = {{"crank_pin", {2.0}}};  // projected onto the loop
  const multibody::Scenario sc = load_robot_scenario(robots("loop.xml"), o);
  const auto types = joint_types_of(sc.system);
  EXPECT_EQ(types.at("close"), JointType::ball);
  EXPECT_EQ(types.at("glue"), JointType::weld);
  // The coupler's anchor meets the rocker 0.1 m off its pin along y... in the rocker's frame (0.1, 0, 0.1).
  const multibody::Joint& close = sc.system.joints()[3];
  EXPECT_EQ(close.body_b, 2);
  POINSOT_EXPECT_MATRIX_NEAR(close.point_b, Vec3(0.1, 0, 0.1) - Vec3(0, 0, 0.05), 1e-16);
  // The energy error of the projected RK4 over 0.5 s is of fourth order (measured 2.6e-7 J at dt = 1e-3,
  // 1.7e-8 J at 5e-4, with a kinetic energy of up to 1.06 J); the loop's gaps stay at round-off.
  double de = 0.0, gap = 0.0, de_half = 0.0, gap_half = 0.0;
  const multibody::State end = run_rk4(sc, 500, &de, &gap);
  multibody::Scenario half = sc;
  half.dt = sc.dt / 2;
  run_rk4(half, 1000, &de_half, &gap_half);
  EXPECT_LT(std::max(gap, gap_half), 1e-13);
  EXPECT_LT(de, 1e-6);
  EXPECT_NEAR(de / de_half, 16.0, 3.0);
  // The crank turned, and the plate stayed glued to it: their relative rotation is the initial one.
  const Mat3 rel0 = sc.initial.bodies[0].R_space_body.transpose() * sc.initial.bodies[3].R_space_body;
  const Mat3 rel = end.bodies[0].R_space_body.transpose() * end.bodies[3].R_space_body;
  POINSOT_EXPECT_MATRIX_NEAR(rel, rel0, 1e-12);
  EXPECT_GT((end.bodies[0].R_space_body - sc.initial.bodies[0].R_space_body).norm(), 1e-3);
}

TEST(RobotSystem, ScenarioFileNamesARobotFile) {
  const AnyScenario any = load_any_scenario(robots("pendulum2_model.toml"));
  const auto& sc = std::get<multibody::Scenario>(any);
  RobotSystemOptions o;
  o.positions = {{"shoulder", {0.3}}};
  o.velocities = {{"elbow", {1.5}}};
  o.gravity = Vec3(0, 0, -1.62);
  const multibody::Scenario direct = load_robot_scenario(robots("pendulum2.urdf"), o);
  EXPECT_EQ(sc.dt, 5e-4);
  EXPECT_EQ(sc.duration, 0.5);
  EXPECT_EQ(sc.system.gravity(), direct.system.gravity());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(sc.initial.bodies[i].x_space, direct.initial.bodies[i].x_space);
    EXPECT_EQ(sc.initial.bodies[i].R_space_body, direct.initial.bodies[i].R_space_body);
    EXPECT_EQ(sc.initial.bodies[i].omega_body, direct.initial.bodies[i].omega_body);
  }
  // The shoulder turned by 0.3 rad about y: the upper rod's centre of mass at 0.25 (cos 0.3, 0, −sin 0.3).
  POINSOT_EXPECT_MATRIX_NEAR(sc.initial.bodies[0].x_space, 0.25 * Vec3(std::cos(0.3), 0, -std::sin(0.3)),
                             1e-16);
  // `poinsot run arm.urdf` reads the file itself with the defaults.
  const AnyScenario file = load_any_scenario(robots("pendulum2.urdf"));
  EXPECT_EQ(std::get<multibody::Scenario>(file).system.body_count(), 2);
}

TEST(RobotSystem, ScenarioKeysAreChecked) {
  const std::string dir = robots("");
  const auto parse = [&](const std::string& text) { return parse_any_scenario(text, "s.toml", dir); };
  expect_has(message_of([&] { parse("[model]\nfile = \"pendulum2.urdf\"\npositions = { knee = 1.0 }\n"); }),
             {"s.toml:3:", "[model] positions", "positions.knee: no moving joint of that name",
              "\"elbow\", \"shoulder\""});
  expect_has(
      message_of([&] { parse("[model]\nfile = \"pendulum2.urdf\"\nvelocities = { elbow = [1, 2] }\n"); }),
      {"s.toml:3:", "velocities.elbow: got 2 value(s), expected a number (rad/s) for a hinge joint"});
  expect_has(message_of([&] { parse("[model]\nfile = \"pendulum2.urdf\"\ninertia = \"cad\"\n"); }),
             {"s.toml:3:", "[model] inertia: got \"cad\", expected \"file\" or \"geometry\""});
  expect_has(message_of([&] { parse("[model]\nfile = \"missing.urdf\"\n"); }),
             {"s.toml:2:", "[model] file", "missing.urdf"});
  expect_has(
      message_of([&] { parse("[model]\nfile = \"pendulum2.urdf\"\n[model.base]\nposition = [0, 0, 1]\n"); }),
      {"[model] base", "0 floating bases; expected exactly one"});
  expect_has(message_of([&] { parse("[model]\nfile = \"pendulum2.urdf\"\ncolour = 1\n"); }), {"colour"});
}

TEST(RobotSystem, MujocoSampleModelsRunOrAreRefusedWithOneLine) {
  const std::filesystem::path root = "/usr/share/mujoco/model";
  if (!std::filesystem::is_directory(root)) GTEST_SKIP() << "MuJoCo's sample models are not installed";
  int ran = 0, refused = 0;
  for (const auto& dir : std::filesystem::directory_iterator(root)) {
    if (!dir.is_directory()) continue;
    for (const auto& f : std::filesystem::directory_iterator(dir.path())) {
      if (f.path().extension() != ".xml") continue;
      SCOPED_TRACE(f.path().string());
      try {
        const multibody::Scenario sc = load_robot_scenario(f.path().string());
        multibody::Rattle rattle(sc.system, 1e-3);
        multibody::State s = sc.initial;
        for (int k = 0; k < 100; ++k)
          rattle.step(s);
        EXPECT_LT(multibody::constraint_violation(sc.system, s).joint_gap, 1e-10);
        ++ran;
      } catch (const InvalidInput& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos);
        expect_has(message, {f.path().string() + ":", "<"});
        ++refused;
      }
    }
  }
  EXPECT_GE(ran, 2);  // arm26 and slider_crank at least
  EXPECT_GE(refused, 1);
}

TEST(RobotSystem, MujocoHumanoidIsUniversalBallAndHingeJoints) {
  std::ifstream in("/usr/share/mujoco/model/humanoid/humanoid.xml");
  if (!in) GTEST_SKIP() << "MuJoCo's sample models are not installed";
  std::stringstream text;
  text << in.rdbuf();
  const std::string xml = text.str();
  RobotSystemOptions o;
  o.gravity = Vec3::Zero();
  o.base_omega_body = Vec3(0.3, -0.2, 0.5);
  o.velocities = {{"right_knee", {2.0}},
                  {"left_shoulder1", {-1.5}},
                  {"abdomen_y", {1.0}},
                  {"right_ankle_y", {3.0}},
                  {"left_ankle_x", {-2.5}}};
  o.positions = {{"right_ankle_y", {0.4}}, {"right_ankle_x", {-0.3}}};
  const multibody::Scenario sc = robot_scenario(read_robot_model(xml, "humanoid.xml"), o);
  EXPECT_EQ(sc.system.body_count(), 16);
  std::map<JointType, int> count;
  for (const multibody::Joint& j : sc.system.joints())
    ++count[j.type];
  // Abdomen z+y, both ankles, both shoulders: universal; the hips' three hinges: balls; knees, elbows and
  // abdomen x: hinges; the head and the hands (no joints): welds. 6 (free torso) + 5·2 + 2·3 + 5·1 = 27
  // degrees of freedom, MuJoCo's count. Each ankle's two hinges turn about points 4 cm apart along z: axes
  // (0, 1, 0) and (1, 0, 0.5) at 0.04/√1.25 m from each other.
  EXPECT_EQ(count[JointType::universal], 5);
  for (const multibody::Joint& j : sc.system.joints()) {
    const bool ankle = j.name.find("ankle") != std::string::npos;
    EXPECT_NEAR(std::abs(j.axis_offset), ankle ? 0.04 / std::sqrt(1.25) : 0.0, 1e-15) << j.name;
  }
  EXPECT_EQ(count[JointType::ball], 2);
  EXPECT_EQ(count[JointType::hinge], 5);
  EXPECT_EQ(count[JointType::weld], 3);
  // Every hinge's spring and damper is modelled: on a hinge, on a universal joint's angles (abdomen z+y,
  // ankles, shoulders) and on the three hinge angles of the hips' ball joints.
  EXPECT_EQ(sc.system.joint_springs().size(), 21u);
  for (const std::string& line : sc.not_modelled)
    EXPECT_EQ(line.find("springs"), std::string::npos) << line;
  // The poses that the two hinges in series give (robot_kinematics.hpp) hold the joints of the model.
  EXPECT_LT(multibody::constraint_violation(sc.system, sc.initial).joint_gap, 1e-15);
  // A free system: RATTLE conserves its momenta to round-off.
  multibody::Rattle rattle(sc.system, 1e-3);
  multibody::State s = sc.initial;
  const Vec3 p0 = multibody::linear_momentum(sc.system, s), L0 = multibody::angular_momentum(sc.system, s);
  for (int k = 0; k < 500; ++k)
    rattle.step(s);
  POINSOT_EXPECT_MATRIX_NEAR(multibody::linear_momentum(sc.system, s), p0, 1e-12);
  POINSOT_EXPECT_MATRIX_NEAR(multibody::angular_momentum(sc.system, s), L0, 1e-11);
  EXPECT_GT(L0.norm(), 0.1);
}

}  // namespace
}  // namespace poinsot::io
