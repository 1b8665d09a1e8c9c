// Scenario files: parsing, defaults, error messages, the example files, and the run driver's outputs.
#include "poinsot/multibody/scenario.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

const std::string kExamples = std::string(POINSOT_SOURCE_DIR) + "/examples/multibody/";

std::string error_of(const std::string& text) {
  try {
    parse_scenario(text, "t.toml");
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "";
}

TEST(Scenario, ParsesBodiesJointsAndDefaults) {
  const Scenario sc = parse_scenario(R"(
[simulation]
dt = 2e-3
duration = 0.5
gravity = [0, 0, -9.81]
[[bodies]]
name = "a"
mass = 2
inertia = [0.1, 0.2, 0.25]
position = [1, 0, 0]
[[bodies]]
name = "b"
mass = 1
shape = { type = "box", size = [0.2, 0.4, 0.6] }
position = [1, 1, 0]
velocity = [0, 0, 5]
[[joints]]
type = "ball"
body_a = "a"
point_a = [0, 0.5, 0]
body_b = "b"
[[joints]]
type = "hinge"
body_a = "a"
point_a = [-1, 0, 0]
axis_a = [0, 0, 1]
)",
                                     "t.toml");
  EXPECT_EQ(sc.system.body_count(), 2);
  EXPECT_EQ(sc.system.joint_count(), 2);
  EXPECT_DOUBLE_EQ(sc.dt, 2e-3);
  // K of the box: m/12 diag(a², b², c²); K of "a" from J: tr(J)/2 − J.
  EXPECT_NEAR(sc.system.bodies()[1].poinsot(2, 2), 0.36 / 12, 1e-15);
  EXPECT_NEAR(sc.system.bodies()[0].poinsot(0, 0), 0.175, 1e-15);
  // point_b defaulted to where point_a is at t = 0, in b's frame: (1, 0.5, 0) − (1, 1, 0).
  EXPECT_LT((sc.system.joints()[0].point_b - Vec3(0, -0.5, 0)).norm(), 1e-15);
  check_consistent(sc.system, sc.initial);
  // The initial velocities were projected onto the joints: ġ = 0.
  EXPECT_LT(constraint_violation(sc.system, sc.initial).joint_velocity, 1e-14);
  EXPECT_GT(sc.initial.bodies[1].v_space.norm(), 0.1);  // but not zeroed: b may still move about the joints
}

TEST(Scenario, ErrorsNameTheFileTheEntryAndTheField) {
  EXPECT_EQ(error_of("[[bodies]]\nname = \"a\"\nmass = -1\ninertia = [1, 1, 1]\n"),
            "scenario t.toml: bodies[0].mass: -1 kg must be > 0");
  EXPECT_NE(error_of("[[bodies]]\nmass = 1\n").find("bodies[0].inertia: give exactly one of"),
            std::string::npos);
  EXPECT_NE(
      error_of("[[bodies]]\nname = \"a\"\nmass = 1\ninertia = [1, 1, 1]\n[[joints]]\ntype = \"slider\"\n"
               "body_a = \"a\"\n")
          .find("joints[0].type: 'slider' is not a joint type"),
      std::string::npos);
  EXPECT_NE(error_of("[[bodies]]\nname = \"a\"\nmass = 1\ninertia = [1, 1, 1]\n[[joints]]\ntype = \"ball\"\n"
                     "body_a = \"nobody\"\n")
                .find("joints[0].body_a: no body named 'nobody'"),
            std::string::npos);
  EXPECT_NE(error_of("[[bodies]]\nname = \"a\"\nmass = 1\ninertia = [1, 1, 5]\n").find("bodies[0]"),
            std::string::npos);  // J violates the triangle inequality: K not positive semi-definite
  EXPECT_NE(error_of("x = [1,\n").find("scenario t.toml: line"), std::string::npos);
  EXPECT_NE(error_of("[simulation]\ndt = 1e-3\n").find("bodies: missing"), std::string::npos);
  EXPECT_THROW(load_scenario("/nonexistent/file.toml"), InvalidInput);
}

TEST(Scenario, EveryExampleLoadsAndRuns) {
  int count = 0;
  for (const auto& entry : std::filesystem::directory_iterator(kExamples)) {
    if (entry.path().extension() != ".toml") continue;
    ++count;
    SCOPED_TRACE(entry.path().string());
    EXPECT_TRUE(is_multibody_scenario(entry.path().string()));
    Scenario sc = load_scenario(entry.path().string());
    sc.duration = 50 * sc.dt;  // a smoke run; the physics is tested elsewhere
    const RunSummary s = run_scenario(sc, nullptr, "");
    EXPECT_EQ(s.steps, 50);
    EXPECT_LT(s.max_joint_gap, 1e-12);
    EXPECT_LT(s.max_joint_angle, 1e-12);
    if (sc.system.torques().empty()) {  // a constant couple does work and has no potential
      EXPECT_LT(s.max_energy_error, 1e-4 * std::max(1.0, std::abs(s.energy_initial)));
    }
  }
  EXPECT_EQ(count, 5);
}

}  // namespace
}  // namespace poinsot::multibody
