// Multibody scenario files with an [optimal_control] section: the example read back against the closed-form
// kinematics of the arm, targets placed by their joints, and bad input as one located line.
#include "poinsot/io/scenario/multibody_optimal_scenario.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>
#include <string>

#include "../../optimal/multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::io {
namespace {

const std::string kArmScenario = std::string(POINSOT_SOURCE_DIR) + "/examples/optimal/two_link_arm.toml";

void expect_same_state(const multibody::State& a, const multibody::State& b) {
  ASSERT_EQ(a.bodies.size(), b.bodies.size());
  // The file gives the angles to 16 digits and the reader composes rotations and joint offsets: round-off.
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_LT((a.bodies[i].R_space_body - b.bodies[i].R_space_body).norm(), 1e-14) << "body " << i;
    EXPECT_LT((a.bodies[i].x_space - b.bodies[i].x_space).norm(), 1e-14) << "body " << i;
    EXPECT_LT(a.bodies[i].v_space.norm() + a.bodies[i].omega_body.norm(), 1e-14) << "body " << i;
  }
}

TEST(MultibodyOptimalScenario, ArmExampleIsTheTestProblem) {
  // The example is the arm of the optimal/ tests: the same initial state, and a target given by rotations
  // only whose positions the reader places through the joints: the closed-form forward kinematics of the arm.
  const MultibodyOptimalScenario sc = load_multibody_optimal_scenario(kArmScenario);
  const double down = -0.5 * std::numbers::pi;
  expect_same_state(sc.problem.initial_state, optimal::testing::two_link_state(down, 0.0));
  expect_same_state(sc.problem.final_state, optimal::testing::two_link_state(down + 1.0, 0.5));
  EXPECT_EQ(sc.name, "two_link_arm");
  EXPECT_EQ(sc.problem.final_time, 1.5);
  EXPECT_EQ(sc.problem.intervals, 64);
  EXPECT_EQ(sc.options.coordinates, optimal::MultibodyCoordinates::minimal);
  ASSERT_EQ(sc.problem.actuators.size(), 2u);
  EXPECT_EQ(sc.problem.actuators[1].kind, optimal::ActuatorKind::hinge_torque);
  EXPECT_EQ(sc.problem.actuators[1].index, 1);
  EXPECT_EQ(sc.problem.actuators[1].torque_max, 50.0);
  EXPECT_EQ(sc.problem.system.gravity(), Vec3(0.0, -9.81, 0.0));
}

/// A free sphere (no joint) turned by a body torque: its target needs center_of_mass.
std::string sphere(const std::string& optimal_control) {
  return "[[bodies]]\nname = \"ball\"\nmass = 2.0\nprincipal_moments = [1, 1, 1]\nposition = [1, 2, 3]\n"
         "[optimal_control]\nfinal_time = 2.0\n" +
         optimal_control;
}

TEST(MultibodyOptimalScenario, BodyTorqueOnAFreeBodyWithAGivenCentreOfMass) {
  const MultibodyOptimalScenario sc = parse_multibody_optimal_scenario(
      sphere("actuators = [{ body = \"ball\", torque_max = 3 }]\n"
             "[[optimal_control.final]]\nbody = \"ball\"\ncenter_of_mass = [1, 2, 3]\n"
             "quaternion = [0, 0, 0, 2]\n"),
      "<string>", "");
  EXPECT_EQ(sc.problem.actuators[0].kind, optimal::ActuatorKind::body_torque);
  EXPECT_EQ(optimal::control_count(sc.problem), 3);
  EXPECT_EQ(sc.problem.final_state.bodies[0].x_space, Vec3(1, 2, 3));
  // quaternion (0, 0, 0, 2) normalised: a half turn about z.
  EXPECT_LT(
      (sc.problem.final_state.bodies[0].R_space_body - Vec3(-1, -1, 1).asDiagonal().toDenseMatrix()).norm(),
      1e-15);
  EXPECT_EQ(sc.options.coordinates, optimal::MultibodyCoordinates::rotation_matrix);
  EXPECT_EQ(sc.problem.intervals, 20);
}

void expect_bad(const std::string& text, const std::string& fragment) {
  try {
    parse_multibody_optimal_scenario(text, "s.toml", "");
    ADD_FAILURE() << "expected InvalidInput containing " << fragment;
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_EQ(msg.rfind("s.toml:", 0), 0u) << msg;
  }
}

TEST(MultibodyOptimalScenario, BadInputIsOneLocatedLine) {
  const std::string target = "[[optimal_control.final]]\nbody = \"ball\"\ncenter_of_mass = [1, 2, 3]\n";
  const std::string act = "actuators = [{ body = \"ball\", torque_max = 3 }]\n";
  expect_bad(sphere("actuators = []\n" + target), "[optimal_control] actuators: none given");
  expect_bad(sphere("actuators = [{ body = \"ball\", torque_max = 0 }]\n" + target),
             "[optimal_control.actuators[0]] torque_max: got 0 N·m");
  expect_bad(sphere("actuators = [{ joint = \"elbow\", torque_max = 1 }]\n" + target),
             "joint: got \"elbow\", expected the name of a hinge or ball joint");
  expect_bad(sphere("actuators = [{ joint = \"a\", body = \"ball\", torque_max = 1 }]\n" + target), "joint");
  expect_bad(sphere(act), "[optimal_control] final: missing");
  expect_bad(sphere(act + "[[optimal_control.final]]\nbody = \"ball\"\n"),
             "body \"ball\": no center_of_mass and no joint that places it");
  expect_bad(sphere(act + target + target), "\"ball\" is given twice");
  expect_bad(sphere("intervals = 1.5\n" + act + target),
             "intervals: got 1.5, expected an integer from 2 to 2000");
  expect_bad(sphere("objective = \"minimum_time\"\n" + act + target),
             "[optimal_control] final_time_bounds: missing");
  expect_bad(sphere("coordinates = \"joint\"\n" + act + target), "coordinates: got \"joint\"");
  expect_bad(sphere("speed = 1\n" + act + target), "unknown key \"speed\"");
  expect_bad("[[bodies]]\nname = \"ball\"\nmass = 2.0\nprincipal_moments = [1, 1, 1]\n",
             "[top level] optimal_control: missing; expected an [optimal_control] section");
  expect_bad("tilte = \"x\"\n" + sphere(act + target), "[top level] unknown key \"tilte\"");
  expect_bad(
      sphere("rate_bounds = [{ joint = \"ball\", rate_max = 1 }]\n" + act + target),
      "[optimal_control.rate_bounds[0]] joint: got \"ball\", expected the name of a hinge joint (the system "
      "has none)");
}

TEST(MultibodyOptimalScenario, ArmFileVariants) {
  // The arm's file with the forearm's target moved off the elbow (the last table of the file is its target):
  // optimal::validate's check, located at [optimal_control].
  std::ifstream in(kArmScenario);
  std::stringstream text;
  text << in.rdbuf();
  expect_bad(text.str() + "center_of_mass = [5, 5, 0]\n", "optimal control: final state:");
  const std::string no_time =
      std::regex_replace(text.str(), std::regex("final_time = 1.5"), "final_time = -1");
  expect_bad(no_time, "[optimal_control] final_time: got -1 s, expected a number > 0");
  const std::string with_rates =
      std::regex_replace(text.str(), std::regex("intervals = 64"),
                         "intervals = 64\nrate_bounds = [{ joint = \"elbow\", rate_max = R }]");
  expect_bad(std::regex_replace(with_rates, std::regex("rate_max = R"), "rate_max = 0"),
             "[optimal_control.rate_bounds[0]] rate_max: got 0 rad/s, expected a number > 0");
  expect_bad(std::regex_replace(std::regex_replace(with_rates, std::regex("rate_max = R"), "rate_max = 1"),
                                std::regex("joint = \"elbow\""), "joint = \"wrist\""),
             "joint: got \"wrist\", expected the name of a hinge or ball joint (\"shoulder\", \"elbow\")");
  const MultibodyOptimalScenario sc = parse_multibody_optimal_scenario(
      std::regex_replace(with_rates, std::regex("rate_max = R"), "rate_max = 2.5"), "s.toml", "");
  ASSERT_EQ(sc.problem.rate_bounds.size(), 1u);
  EXPECT_EQ(sc.problem.rate_bounds[0].joint, 1);
  EXPECT_EQ(sc.problem.rate_bounds[0].rate_max, 2.5);
}

}  // namespace
}  // namespace poinsot::io
