// [body] shape and [body] mesh of scenario files (src/io/scenario/scenario_body.cpp), through parse_scenario.
#include <gtest/gtest.h>

#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/body_file.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

std::string scenario_with_body(const std::string& body) {
  return "[body]\n" + body + "\n[initial]\nomega_body = [1, 2, 3]\n[output]\nt_end = 1\n";
}

std::string body_error_of(const std::string& text) {
  return test::message_of([&] { (void)parse_scenario(text, "b.toml", POINSOT_SOURCE_DIR "/examples"); },
                          text);
}

using test::expect_has;

TEST(ScenarioBody, BoxShapeIsTheInertiaLayersBox) {
  const Scenario sc =
      parse_scenario(scenario_with_body("shape = { type = \"box\", size = [0.3, 0.1, 0.02], mass = 0.4 }"));
  const inertia::MassProperties box = inertia::box(0.4, Vec3(0.3, 0.1, 0.02));
  EXPECT_EQ(sc.body.inertia_com(), box.inertia_com);
  // Density: the same box from 0.4 kg / (0.3·0.1·0.02 m³); one rounding in the density, one in the product.
  const Scenario sd = parse_scenario(
      scenario_with_body("shape = { type = \"box\", size = [0.3, 0.1, 0.02], density = 666.6666666666667 }"));
  EXPECT_LE(test::max_abs_diff(sd.body.inertia_com(), box.inertia_com),
            8 * test::kEps * box.inertia_com.norm());
}

TEST(ScenarioBody, LecturesSquarePlateAboutItsCorner) {
  // The lecture: a square plate of side a and mass m about a corner has principal moments (1/12, 7/12, 2/3) m
  // a², with axes along the two diagonals and the normal.
  const double a = 0.5, m = 2.0;
  const Scenario sc = parse_scenario(scenario_with_body(
      "shape = { type = \"plate\", size = [0.5, 0.5], mass = 2.0 }\npivot = [-0.25, -0.25, 0]"));
  const Vec3 expected = Vec3(1.0 / 12.0, 7.0 / 12.0, 2.0 / 3.0) * m * a * a;
  // Eigen-decomposition of a 3×3 to a few ulps of the trace (inertia layer).
  EXPECT_LE(test::max_abs_diff(sc.body.principal_moments(), expected), 16 * test::kEps * expected.sum());
  const Vec3 diagonal = sc.body.principal_axes().col(0);
  EXPECT_NEAR(std::abs(diagonal.dot(Vec3(1, 1, 0).normalized())), 1.0, 1e-14);
  EXPECT_EQ(sc.body.pivot_to_com(), Vec3(0.25, 0.25, 0.0));
}

TEST(ScenarioBody, MeshBracketIsTwoBoxes) {
  // examples/meshes/l_bracket.obj: an L of 0.12 × 0.03 and 0.03 × 0.05 m arms, 0.02 m thick, in aluminium.
  const double rho = 2700.0;
  const Scenario sc =
      parse_scenario(scenario_with_body("mesh = { file = \"meshes/l_bracket.obj\", density = 2700.0 }"),
                     "b.toml", POINSOT_SOURCE_DIR "/examples");
  const double va = 0.12 * 0.03 * 0.02, vb = 0.03 * 0.05 * 0.02;
  const auto a =
      inertia::box(rho * va, Vec3(0.12, 0.03, 0.02)).placed(Mat3::Identity(), Vec3(0.06, 0.015, 0.01));
  const auto b =
      inertia::box(rho * vb, Vec3(0.03, 0.05, 0.02)).placed(Mat3::Identity(), Vec3(0.015, 0.055, 0.01));
  const auto both = inertia::combine(a, b);
  // assimp stores vertices in single precision: 0.03 m is off by up to 6e-8 relative, and J (5th power of
  // lengths times density) by a few times that. 1e-6 relative leaves a margin over that float round-off.
  EXPECT_LE(test::max_abs_diff(sc.body.inertia_com(), both.inertia_com), 1e-6 * both.inertia_com.norm());
  EXPECT_NE(sc.body_description.find("l_bracket.obj"), std::string::npos);
}

TEST(ScenarioBody, ShapeMistakesAreNamed) {
  expect_has(body_error_of(scenario_with_body("shape = { type = \"blob\", mass = 1 }")),
             {"[body.shape] type: got \"blob\"", "expected one of point, rod, plate, box"});
  expect_has(body_error_of(scenario_with_body("shape = { type = \"sphere\", size = [1, 1, 1], mass = 1 }")),
             {"key \"size\" does not apply to a sphere", "valid keys: type, mass, density, radius"});
  expect_has(body_error_of(scenario_with_body("shape = { type = \"box\", mass = 1 }")),
             {"[body.shape] size: missing; a box needs size"});
  expect_has(body_error_of(
                 scenario_with_body("shape = { type = \"box\", size = [1, 1, 1], mass = 1, density = 2 }")),
             {"the amount of matter is given 2 times"});
  expect_has(body_error_of(scenario_with_body("shape = { type = \"box\", size = [1, -1, 1], mass = 1 }")),
             {"b.toml:2:", "[body.shape] type:", "box"});
  expect_has(
      body_error_of(scenario_with_body("shape = { type = \"box\", size = [1, 1, 1], mass = 1 }\nmass = 2")),
      {"[body] mass: got 2 kg, but the shape already gives the mass (1 kg)"});
  expect_has(body_error_of(scenario_with_body("shape = { type = \"box\", size = [1, 1, 1], mass = 1 }\n"
                                              "pivot = [0, 0, 0]\npivot_to_com = [0, 0, 1]")),
             {"[body] pivot: given with [body] pivot_to_com"});
}

TEST(ScenarioBody, MeshMistakesAreNamed) {
  expect_has(body_error_of(scenario_with_body("mesh = { file = \"meshes/none.stl\", density = 1000 }")),
             {"[body.mesh] file:", "none.stl"});
  expect_has(body_error_of(scenario_with_body("mesh = { density = 1000 }")), {"[body.mesh] file: missing"});
  expect_has(body_error_of(scenario_with_body("mesh = { file = \"meshes/l_bracket.obj\", density = -1 }")),
             {"[body.mesh] density: got -1, expected a number > 0"});
}

}  // namespace
}  // namespace poinsot::io

namespace poinsot::io {
namespace {

TEST(ScenarioBody, TheSameKeysAsAMultibodyBody) {
  // The reader is shared with multibody files: explicit K, J as its diagonal, a shape's axis, the mass on the
  // body, a composite body file.
  const Scenario k = parse_scenario(scenario_with_body("poinsot = [1.0, 1.5, 2.5]"));
  EXPECT_EQ(k.body.inertia(), Vec3(4.0, 3.5, 2.5).asDiagonal().toDenseMatrix());  // J = tr(K) I − K
  const Scenario d = parse_scenario(scenario_with_body("inertia = [1, 2, 3]"));
  EXPECT_EQ(d.body.inertia(), Vec3(1, 2, 3).asDiagonal().toDenseMatrix());
  // A cylinder along x: J = diag(m r²/2, m(3r² + l²)/12, same) [MK].
  const double m = 2.0, r = 0.1, l = 0.5;
  const Scenario c =
      parse_scenario(scenario_with_body("shape = { type = \"cylinder\", radius = 0.1, length = 0.5, axis = "
                                        "\"x\" }\nmass = 2\npivot = [0, 0, 0]"));
  const Vec3 J(m * r * r / 2, m * (3 * r * r + l * l) / 12, m * (3 * r * r + l * l) / 12);
  EXPECT_LE(test::max_abs_diff(c.body.inertia_com(), J.asDiagonal().toDenseMatrix()),
            4 * test::kEps * J.norm());
  EXPECT_NE(c.body_description.find("along x"), std::string::npos);
  // The flywheel body file of the inertia layer's tests: its mass properties, centre of mass off the origin.
  const Scenario w = parse_scenario(scenario_with_body("composite = { file = \"wheel.toml\" }"), "b.toml",
                                    POINSOT_SOURCE_DIR "/tests/data/inertia");
  const inertia::BodyFileResult wheel =
      inertia::load_body_file(POINSOT_SOURCE_DIR "/tests/data/inertia/wheel.toml");
  EXPECT_LE(test::max_abs_diff(w.body.inertia_com(), wheel.body.inertia_com),
            4 * test::kEps * wheel.body.inertia_com.norm());
  expect_has(w.body_description, {"composite", "wheel.toml", "2 parts, 1 voids"});
  expect_has(body_error_of(scenario_with_body("composite = { file = \"wheel.toml\", density = 2 }")),
             {"[body.composite] unknown key \"density\"; valid keys: file"});
  expect_has(body_error_of(scenario_with_body("shape = { type = \"box\", size = [1, 1, 1] }")),
             {"[body.shape] mass: missing; expected mass (kg) or density in the table, or [body] mass"});
  expect_has(body_error_of(scenario_with_body("inertia = [1, 2, 3]\nmass = 1")),
             {"[body] mass: given without a pivot"});
}

}  // namespace
}  // namespace poinsot::io
