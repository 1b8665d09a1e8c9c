#include "poinsot/io/scenario/scenario.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

/// Expects every piece in the message (gmock is not linked into the layer tests).
using test::expect_has;

const char* kMinimal = R"(
[body]
principal_moments = [1.0, 2.0, 3.0]
[initial]
omega_body = [0.1, 2.0, 0.1]
[output]
t_end = 5
)";

/// The message of the InvalidInput that parsing `text` throws (fails the test when nothing is thrown).
std::string error_of(const std::string& text) {
  return test::message_of([&] { (void)parse_scenario(text, "s.toml"); }, text);
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

TEST(Scenario, MinimalFileGetsTheDocumentedDefaults) {
  const Scenario sc = parse_scenario(kMinimal);
  EXPECT_EQ(sc.body.principal_moments(), Vec3(1, 2, 3));
  EXPECT_EQ(sc.initial.omega_body, Vec3(0.1, 2.0, 0.1));
  EXPECT_EQ(sc.initial.R_space_body, Mat3::Identity());
  EXPECT_EQ(sc.torque_type, "none");
  EXPECT_TRUE(sc.torque->is_zero());
  EXPECT_EQ(sc.method, "dop853");
  EXPECT_EQ(sc.simulation.t_end, 5.0);  // a TOML integer is a number
  EXPECT_EQ(sc.simulation.sample_dt, 5.0 / 1000.0);
  EXPECT_TRUE(sc.out_dir.empty());
}

TEST(Scenario, FullFileIsReadKeyByKey) {
  const Scenario sc = parse_scenario(R"(
title = "a top"
[body]
inertia = [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 1.0]]
mass = 1.5
pivot_to_com = [0, 0, 0.1]
[initial]
omega_body = [0, 0, 50]
orientation = { axis_angle = { axis = [1, 0, 0], angle = 0.3 } }
[torque]
type = "gravity"
g = [0, 0, -9.8]
[integrator]
method = "rattle"
dt = 1e-4
max_step = 0.05
rtol = 1e-9
atol = 1e-11
[output]
t_end = 2.5
sample_dt = 0.01
dir = "out/top"
)");
  EXPECT_EQ(sc.title, "a top");
  EXPECT_TRUE(sc.body.has_pivot());
  EXPECT_EQ(sc.body.mass(), 1.5);
  EXPECT_EQ(sc.body.pivot_to_com(), Vec3(0, 0, 0.1));
  EXPECT_TRUE(sc.torque->is_gravity());
  EXPECT_EQ(sc.gravity_space, Vec3(0, 0, -9.8));
  EXPECT_EQ(sc.method, "rattle");
  EXPECT_EQ(sc.integrator.dt, 1e-4);
  EXPECT_EQ(sc.integrator.max_step, 0.05);
  EXPECT_EQ(sc.integrator.rtol, 1e-9);
  EXPECT_EQ(sc.integrator.atol, 1e-11);
  EXPECT_EQ(sc.simulation.t_end, 2.5);
  EXPECT_EQ(sc.simulation.sample_dt, 0.01);
  EXPECT_EQ(sc.out_dir, "out/top");
  // Oracle: the axis-angle rotation of the so3 layer.
  EXPECT_LE(test::max_abs_diff(sc.initial.R_space_body, so3::rotation_from_axis_angle(Vec3::UnitX(), 0.3)),
            4 * test::kEps);
}

TEST(Scenario, TheFourOrientationFormsOfOneRotationAgree) {
  // A rotation of 120° about (1, 1, 1)/√3 maps x → y → z → x: quaternion (1/2)(1, 1, 1, 1), matrix the cyclic
  // permutation, ZYX angles (90°, 0, 90°).
  const std::string base =
      replace(kMinimal, "omega_body = [0.1, 2.0, 0.1]", "omega_body = [0.1, 2.0, 0.1]\n@");
  const Mat3 expected = (Mat3() << 0, 0, 1, 1, 0, 0, 0, 1, 0).finished();
  for (const std::string orientation : {
           "orientation = { quaternion = [0.5, 0.5, 0.5, 0.5] }",
           "orientation = { quaternion = [2, 2, 2, 2] }",  // normalised
           "orientation = { matrix = [[0, 0, 1], [1, 0, 0], [0, 1, 0]] }",
           "orientation = { axis_angle = { axis = [1, 1, 1], angle = 120 }, degrees = true }",
           "orientation = { euler = { sequence = \"ZYX\", angles = [90, 0, 90] }, degrees = true }",
       }) {
    const Scenario sc = parse_scenario(replace(base, "@", orientation));
    // Degrees are converted with π/180 and go through sin/cos: a few ulps.
    EXPECT_LE(test::max_abs_diff(sc.initial.R_space_body, expected), 8 * test::kEps) << orientation;
  }
}

TEST(Scenario, OmegaSpaceIsTakenToTheBodyFrame) {
  const Scenario sc = parse_scenario(R"(
[body]
principal_moments = [1, 2, 3]
[initial]
omega_space = [0, 0, 3]
orientation = { axis_angle = { axis = [1, 0, 0], angle = 1.5707963267948966 } }
[output]
t_end = 1
)");
  // Rotation by 90° about x maps body y to space z: Ω = 3 e_z in space is ω = 3 e_y in the body.
  EXPECT_LE(test::max_abs_diff(sc.initial.omega_body, Vec3(0, 3, 0)), 8 * test::kEps);
  EXPECT_LE(test::max_abs_diff(sc.initial.omega_space(), Vec3(0, 0, 3)), 8 * test::kEps);
}

TEST(Scenario, PivotAsAPointIsTheVectorToTheCentreOfMass) {
  const Scenario sc =
      parse_scenario(replace(kMinimal, "principal_moments = [1.0, 2.0, 3.0]",
                             "principal_moments = [1.0, 2.0, 3.0]\nmass = 2\npivot = [0, 0, -0.5]"));
  EXPECT_EQ(sc.body.pivot_to_com(), Vec3(0, 0, 0.5));
  // Parallel-axis theorem: J about the pivot = J + m(|d|² I − d d^T).
  EXPECT_EQ(sc.body.inertia().diagonal(), Vec3(1.5, 2.5, 3.0));
}

TEST(Scenario, SyntaxErrorGivesLineAndColumn) {
  const std::string m = error_of("[body]\nprincipal_moments = [1, 2, 3\n[initial]\n");
  expect_has(m, {"s.toml:", "TOML syntax error"});
  EXPECT_EQ(m.rfind("s.toml:3:1: ", 0), 0u) << m;  // the unclosed array is noticed at the next table
}

TEST(Scenario, UnknownKeyIsNamedWithTheValidOnes) {
  const std::string m = error_of(replace(kMinimal, "principal_moments", "principal_moment"));
  expect_has(m, {"s.toml:3:1:", "[body] unknown key \"principal_moment\"",
                 "valid keys: principal_moments, inertia, poinsot, shape, mesh, composite, mass"});
  expect_has(error_of(std::string(kMinimal) + "[integrater]\nmethod = \"rk4\"\n"),
             {"unknown key \"integrater\"", "integrator"});
}

TEST(Scenario, InertiaMustBeGivenExactlyOnce) {
  expect_has(error_of(replace(kMinimal, "principal_moments = [1.0, 2.0, 3.0]", "")),
             {"[body] the inertia", "missing", "exactly one of"});
  expect_has(error_of(replace(kMinimal, "principal_moments = [1.0, 2.0, 3.0]",
                              "principal_moments = [1.0, 2.0, 3.0]\ninertia = [[1,0,0],[0,2,0],[0,0,3]]")),
             {"s.toml:4:", "given 2 times (principal_moments and inertia)"});
  expect_has(error_of(replace(kMinimal, "omega_body", "omega_space = [1, 0, 0]\nomega_body")),
             {"[initial] the angular velocity is given 2 times"});
  expect_has(error_of(replace(kMinimal, "t_end = 5", "sample_dt = 1")),
             {"[output] t_end: missing", "s.toml:"});
  expect_has(error_of("[body]\nprincipal_moments = [1, 2, 3]\n[output]\nt_end = 1\n"),
             {"[initial] section is missing"});
}

TEST(Scenario, WrongTypesAreNamed) {
  expect_has(error_of(replace(kMinimal, "t_end = 5", "t_end = \"5 s\"")),
             {"[output] t_end: got \"5 s\", expected a number"});
  expect_has(error_of(replace(kMinimal, "[0.1, 2.0, 0.1]", "[0.1, 2.0]")),
             {"[initial] omega_body: got [0.1, 2], expected an array of 3 numbers"});
  expect_has(error_of(replace(kMinimal, "[body]", "body = 3\n[bodyx]")), {"unknown key \"bodyx\""});
  expect_has(error_of("body = 3\n" + replace(kMinimal, "[body]\nprincipal_moments = [1.0, 2.0, 3.0]\n", "")),
             {"[top level] body: got 3, expected a table"});
}

TEST(Scenario, RangesAreChecked) {
  expect_has(error_of(replace(kMinimal, "t_end = 5", "t_end = -1")),
             {"[output] t_end: got -1 s, expected a number > 0"});
  expect_has(error_of(replace(kMinimal, "t_end = 5", "t_end = 5\nsample_dt = 0")),
             {"[output] sample_dt: got 0 s, expected a number > 0"});
  expect_has(error_of(std::string(kMinimal) + "[integrator]\ndt = 0.0\n"),
             {"[integrator] dt: got 0 s, expected a number > 0"});
  expect_has(error_of(std::string(kMinimal) + "[integrator]\ndt = -1e-3\n"), {"got -0.001 s"});
  expect_has(error_of(std::string(kMinimal) + "[integrator]\nmax_step = 0\n"),
             {"[integrator] max_step: got 0 s, expected a number > 0"});
  expect_has(error_of(std::string(kMinimal) + "[integrator]\nmax_step = 1e-12\n"),
             {"t_end / max_step = 5e+12 steps"});
  EXPECT_EQ(parse_scenario(kMinimal, "t.toml").integrator.max_step,
            std::numeric_limits<double>::infinity());  // by default the tolerances alone set the steps
  expect_has(error_of(replace(kMinimal, "[0.1, 2.0, 0.1]", "[0.1, nan, 0.1]")),
             {"[initial] omega_body: got [0.1, nan, 0.1], expected finite numbers"});
  expect_has(error_of(replace(kMinimal, "t_end = 5", "t_end = inf")),
             {"[output] t_end: got inf, expected a finite number"});
}

TEST(Scenario, InvalidInertiaCarriesTheInertiaLayersMessage) {
  const std::string m = error_of(replace(kMinimal, "[1.0, 2.0, 3.0]", "[1.0, 1.0, 5.0]"));
  expect_has(m, {"s.toml:3:", "[body] principal_moments:", "triangle inequality"});
}

TEST(Scenario, ExactRefusesATorque) {
  const std::string top =
      replace(kMinimal, "principal_moments = [1.0, 2.0, 3.0]",
              "principal_moments = [1.0, 2.0, 3.0]\nmass = 1\npivot_to_com = [0, 0, 0.1]");
  expect_has(error_of(top + "[torque]\ntype = \"gravity\"\n[integrator]\nmethod = \"exact\"\n"),
             {"[integrator] method: got \"exact\"", "torque-free", "\"gravity\""});
  expect_has(error_of(std::string(kMinimal) + "[torque]\ntype = \"body\"\nvalue = [0, 0, 1]\n[integrator]\n"
                                              "method = \"exact\"\n"),
             {"[torque] type is \"body\""});
  EXPECT_NO_THROW(parse_scenario(std::string(kMinimal) + "[integrator]\nmethod = \"exact\"\n"));
}

TEST(Scenario, TorqueKeysMatchTheirType) {
  expect_has(error_of(std::string(kMinimal) + "[torque]\ntype = \"gravity\"\n"),
             {"needs a body held at a pivot"});
  expect_has(error_of(std::string(kMinimal) + "[torque]\ntype = \"body\"\n"), {"[torque] value: missing"});
  expect_has(error_of(std::string(kMinimal) + "[torque]\ntype = \"wind\"\n"),
             {"got \"wind\", expected one of none, gravity, body, space"});
  const Scenario sc =
      parse_scenario(std::string(kMinimal) + "[torque]\ntype = \"space\"\nvalue = [0, 0, 0.5]\n");
  EXPECT_EQ(sc.torque->torque_body(0.0, Mat3::Identity(), Vec3::Zero()), Vec3(0, 0, 0.5));
}

TEST(Scenario, MethodNamesAreChecked) {
  std::string text = kMinimal;
  text += "[integrator]\nmethod = \"euler\"\n";
  expect_has(error_of(text), {"got \"euler\", expected one of exact, rk4, dopri5, dop853, dlm, rattle"});
}

TEST(Scenario, OverridesAreValidatedLikeTheFile) {
  Scenario sc = parse_scenario(kMinimal);
  ScenarioOverrides o;
  o.method = "rk4";
  o.dt = 2e-3;
  o.t_end = 7.0;
  o.out_dir = "x";
  apply_overrides(sc, o);
  EXPECT_EQ(sc.method, "rk4");
  EXPECT_EQ(sc.integrator.dt, 2e-3);
  EXPECT_EQ(sc.simulation.t_end, 7.0);
  EXPECT_EQ(sc.out_dir, "x");
  ScenarioOverrides bad;
  bad.dt = -1.0;
  EXPECT_THROW(apply_overrides(sc, bad), InvalidInput);
  ScenarioOverrides nan_t;
  nan_t.t_end = std::nan("");
  EXPECT_THROW(apply_overrides(sc, nan_t), InvalidInput);
}

TEST(Scenario, MissingFileIsNamed) {
  POINSOT_EXPECT_THROWS_MESSAGE((void)load_scenario("/nonexistent/poinsot/s.toml"), InvalidInput,
                                "cannot read \"/nonexistent/poinsot/s.toml\"");
}

TEST(Scenario, LoadNamesTheScenarioAfterItsFile) {
  const Scenario sc = load_scenario(std::string(POINSOT_SOURCE_DIR) + "/examples/tennis_racket.toml");
  EXPECT_EQ(sc.name, "tennis_racket");
  // Brody's measured moments (kg·m²).
  EXPECT_EQ(sc.body.principal_moments(), Vec3(0.00121, 0.01638, 0.01748));
}

}  // namespace
}  // namespace poinsot::io
