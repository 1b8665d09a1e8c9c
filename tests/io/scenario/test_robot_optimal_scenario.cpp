// Optimal-control scenarios on robot files (`[model] file = ...` with [optimal_control]): the URDF arm
// against the hand-written arm and the arm's closed-form kinematics, a floating base's target by its pose,
// and bad input as one located line.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "../../optimal/multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/scenario/multibody_optimal_scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

const std::string kOptimalExamples = std::string(POINSOT_SOURCE_DIR) + "/examples/optimal";
const std::string kRobotFiles = std::string(POINSOT_TEST_DATA_DIR) + "/models/robots";

/// The URDF arm's scenario with its [optimal_control] section replaced by `optimal_control`.
std::string urdf_arm(const std::string& optimal_control, const std::string& model = "") {
  return "[simulation]\ngravity = [0, -9.81, 0]\n[model]\nfile = \"two_link_arm.urdf\"\n" + model +
         "[optimal_control]\nfinal_time = 1.5\n"
         "actuators = [{ joint = \"shoulder\", torque_max = 50 }, { joint = \"elbow\", torque_max = 50 }]\n" +
         optimal_control;
}

void expect_bad(const std::string& text, const std::string& base_dir, const std::string& fragment) {
  const std::string message =
      test::message_of([&] { (void)parse_multibody_optimal_scenario(text, "s.toml", base_dir); });
  test::expect_has(message, {fragment});
  EXPECT_EQ(message.rfind("s.toml:", 0), 0u) << message;
}

void expect_near_state(const multibody::State& a, const multibody::State& b, double tolerance) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_LT((a.bodies[i].R_space_body - b.bodies[i].R_space_body).norm(), tolerance) << "body " << i;
    EXPECT_LT((a.bodies[i].x_space - b.bodies[i].x_space).norm(), tolerance) << "body " << i;
    EXPECT_LT((a.bodies[i].v_space - b.bodies[i].v_space).norm(), tolerance) << "body " << i;
    EXPECT_LT((a.bodies[i].omega_body - b.bodies[i].omega_body).norm(), tolerance) << "body " << i;
  }
}

TEST(RobotOptimalScenario, UrdfArmIsTheHandWrittenArm) {
  // The two example files describe one problem: the same bodies (masses and tensors from the URDF's 16-digit
  // numbers, against the reader's solid cylinder: round-off), the same joints, actuators and objective, and
  // states that are the arm's closed-form kinematics (the joints' angles composed from the file's rpy: a few
  // ulps).
  const MultibodyOptimalScenario hand =
      load_multibody_optimal_scenario(kOptimalExamples + "/two_link_arm.toml");
  const MultibodyOptimalScenario urdf =
      load_multibody_optimal_scenario(kOptimalExamples + "/two_link_arm_urdf.toml");
  const multibody::System& a = hand.problem.system;
  const multibody::System& b = urdf.problem.system;
  ASSERT_EQ(a.body_count(), b.body_count());
  for (std::size_t i = 0; i < a.bodies().size(); ++i) {
    EXPECT_EQ(a.bodies()[i].name, b.bodies()[i].name);
    EXPECT_EQ(a.bodies()[i].mass, b.bodies()[i].mass);
    EXPECT_LT((a.bodies()[i].inertia - b.bodies()[i].inertia).norm(), 1e-16) << "body " << i;
  }
  ASSERT_EQ(a.joint_count(), b.joint_count());
  for (std::size_t k = 0; k < a.joints().size(); ++k) {
    const multibody::Joint& ja = a.joints()[k];
    const multibody::Joint& jb = b.joints()[k];
    EXPECT_EQ(ja.name, jb.name);
    EXPECT_EQ(ja.type, jb.type);
    EXPECT_EQ(ja.body_a, jb.body_a);
    EXPECT_EQ(ja.body_b, jb.body_b);
    EXPECT_LT((ja.point_a - jb.point_a).norm(), 1e-15) << ja.name;
    EXPECT_LT((ja.point_b - jb.point_b).norm(), 1e-15) << ja.name;
    EXPECT_LT((ja.hinge_axis_a() - jb.hinge_axis_a()).norm(), 1e-15) << ja.name;
  }
  EXPECT_EQ(a.gravity(), b.gravity());
  ASSERT_EQ(urdf.problem.actuators.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_EQ(urdf.problem.actuators[k].kind, hand.problem.actuators[k].kind);
    EXPECT_EQ(urdf.problem.actuators[k].index, hand.problem.actuators[k].index);
    EXPECT_EQ(urdf.problem.actuators[k].torque_max, hand.problem.actuators[k].torque_max);
  }
  EXPECT_EQ(urdf.problem.objective, hand.problem.objective);
  EXPECT_EQ(urdf.problem.final_time, hand.problem.final_time);
  EXPECT_EQ(urdf.problem.intervals, hand.problem.intervals);
  EXPECT_EQ(urdf.options.coordinates, hand.options.coordinates);
  const double down = -0.5 * std::numbers::pi;
  expect_near_state(urdf.problem.initial_state, optimal::testing::two_link_state(down, 0.0), 1e-15);
  expect_near_state(urdf.problem.final_state, optimal::testing::two_link_state(down + 1.0, 0.5), 1e-15);
  // What the file states and the plan leaves out: the two joints' limits and the links' contacts.
  ASSERT_EQ(urdf.model.not_modelled.size(), 3u);
  EXPECT_NE(urdf.model.not_modelled[1].find("<joint name=\"shoulder\"> line 8: joint limits"),
            std::string::npos);
  EXPECT_TRUE(hand.model.not_modelled.empty());
}

TEST(RobotOptimalScenario, TargetVelocitiesByJointName) {
  // final_velocities gives the joints' rates at T: the arm's closed-form velocities.
  const MultibodyOptimalScenario sc =
      parse_multibody_optimal_scenario(urdf_arm("final_positions = { shoulder = 1.0, elbow = 0.5 }\n"
                                                "final_velocities = { shoulder = 0.25, elbow = -0.75 }\n"),
                                       "s.toml", kOptimalExamples);
  const double down = -0.5 * std::numbers::pi;
  expect_near_state(sc.problem.final_state, optimal::testing::two_link_state(down + 1.0, 0.5, 0.25, -0.75),
                    1e-15);
}

TEST(RobotOptimalScenario, FloatingBaseTargetByItsPose) {
  // A free base with one hinged arm (MJCF): final_base places the base, final_positions turns the arm.
  const std::filesystem::path dir = test::temp_path("robot_optimal");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "probe.xml") << R"(<mujoco><worldbody>
  <body name="base"><freejoint/><geom type="box" size="0.2 0.2 0.2" mass="8"/>
    <body name="arm" pos="0.2 0 0"><joint name="hinge" type="hinge" axis="0 0 1"/>
      <geom type="box" size="0.5 0.05 0.05" pos="0.5 0 0" mass="1"/></body>
  </body></worldbody></mujoco>)";
  // The system floats: its centre of mass stays where it starts (the base's box of 8 kg at the origin, the
  // arm's 1 kg at x = 0.7 m), so the base's target position is where that holds.
  const Mat3 R_base = Eigen::AngleAxisd(0.3, Vec3::UnitY()).toRotationMatrix();
  const Mat3 R_arm = R_base * Eigen::AngleAxisd(0.4, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 arm_from_base = R_base * Vec3(0.2, 0.0, 0.0) + R_arm * Vec3(0.5, 0.0, 0.0);
  const Vec3 position = Vec3(0.7, 0.0, 0.0) / 9.0 - arm_from_base / 9.0;
  const MultibodyOptimalScenario sc = parse_multibody_optimal_scenario(
      fmt::format(
          "[simulation]\ngravity = [0, 0, 0]\n[model]\nfile = \"probe.xml\"\n[optimal_control]\n"
          "final_time = 2\n"
          "actuators = [{{ joint = \"hinge\", torque_max = 1 }}, {{ body = \"base\", torque_max = 1 }}]\n"
          "final_positions = {{ hinge = 0.4 }}\n"
          "final_base = {{ position = [{:.17g}, {:.17g}, {:.17g}], rotation = {{ axis = [0, 1, 0], "
          "angle = 0.3 }} }}\n",
          position.x(), position.y(), position.z()),
      "s.toml", dir.string());
  const auto& base = sc.problem.final_state.bodies[0];
  const auto& arm = sc.problem.final_state.bodies[1];
  EXPECT_LT((base.R_space_body - R_base).norm(), 1e-15);
  EXPECT_LT((base.x_space - position).norm(), 1e-15);
  EXPECT_LT((arm.R_space_body - R_arm).norm(), 1e-15);
  EXPECT_LT((arm.x_space - (position + arm_from_base)).norm(), 1e-15);
}

TEST(RobotOptimalScenario, BadInputIsOneLocatedLine) {
  const std::string target = "final_positions = { shoulder = 1.0, elbow = 0.5 }\n";
  expect_bad(urdf_arm("final_positions = { knee = 1.0 }\n"), kOptimalExamples,
             "[optimal_control] final_positions: final_positions.knee: no moving joint of that name");
  expect_bad(urdf_arm("final_positions = { elbow = [1, 2] }\n"), kOptimalExamples, "final_positions.elbow:");
  expect_bad(
      urdf_arm("final_velocities = { elbow = \"fast\" }\n"), kOptimalExamples,
      "[optimal_control] final_velocities.elbow: got \"fast\", expected a number or an array of numbers");
  expect_bad(urdf_arm(""), kOptimalExamples, "[optimal_control] final: missing; expected final_positions");
  expect_bad(urdf_arm(target + "[[optimal_control.final]]\nbody = \"upper\"\n"), kOptimalExamples,
             "[optimal_control] final: given with final_positions");
  expect_bad(urdf_arm(target + "final_base = { position = [0, 0, 1] }\n"), kOptimalExamples,
             "[optimal_control] final_base: the model has 0 floating bases");
  expect_bad(urdf_arm(target + "final_base = { speed = 1 }\n"), kOptimalExamples,
             "[optimal_control.final_base] unknown key \"speed\"");
  expect_bad(
      "[[bodies]]\nname = \"ball\"\nmass = 2.0\nprincipal_moments = [1, 1, 1]\n[optimal_control]\n"
      "final_time = 2.0\nactuators = [{ body = \"ball\", torque_max = 3 }]\nfinal_positions = { a = 1 }\n",
      kOptimalExamples, "[optimal_control] final_positions: given without a [model] robot file");
  // The double pendulum's files give its joints dampers, which the transcriptions do not handle.
  const std::string pendulum =
      "[model]\nfile = \"pendulum2.urdf\"\n{}[optimal_control]\nfinal_time = 1\n"
      "actuators = [{ joint = \"shoulder\", torque_max = 5 }]\nfinal_positions = { shoulder = 0.5 }\n";
  const auto with = [&](const std::string& model) {
    return std::string(pendulum).replace(pendulum.find("{}"), 2, model);
  };
  expect_bad(with(""), kRobotFiles,
             "[model] joint_springs: the file gives joint 'shoulder' a spring or damper, which the optimal "
             "control transcriptions do not handle; expected joint_springs = false");
  const MultibodyOptimalScenario sc =
      parse_multibody_optimal_scenario(with("joint_springs = false\n"), "s.toml", kRobotFiles);
  EXPECT_TRUE(sc.problem.system.joint_springs().empty());
  bool listed = false;
  for (const std::string& line : sc.model.not_modelled)
    listed = listed || line.find("(left out: joint_springs = false)") != std::string::npos;
  EXPECT_TRUE(listed);
}

}  // namespace
}  // namespace poinsot::io
