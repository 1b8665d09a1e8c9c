// The surfaces a scenario gives its body for the viewer (io::Scenario::body_surface,
// multibody::Scenario::body_surfaces) and the rounding of the numbers the page only draws.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <numbers>
#include <string>

#include <fmt/format.h>

#include "../../../src/io/view/view_data.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/optimal_scenario.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

constexpr int kSegments = 48;  // the tessellation's segments around a curved shape's axis (scenario_body.hpp)

Scenario with_body(const std::string& body) {
  return parse_scenario("[body]\n" + body +
                            "\n[initial]\nomega_body = [0.1, 1.0, 0.2]\n[integrator]\nmethod = \"exact\"\n"
                            "[output]\nt_end = 1\n",
                        "<test>", POINSOT_SOURCE_DIR "/examples");
}

Vec3 lower(const inertia::TriangleMesh& m) {
  Vec3 lo = m.vertices.front();
  for (const Vec3& v : m.vertices)
    lo = lo.cwiseMin(v);
  return lo;
}
Vec3 upper(const inertia::TriangleMesh& m) {
  Vec3 hi = m.vertices.front();
  for (const Vec3& v : m.vertices)
    hi = hi.cwiseMax(v);
  return hi;
}

TEST(ViewSurface, ACylinderAlongXIsThePrismOnTheInscribedPolygonAboutItsCentre) {
  const Scenario sc =
      with_body(R"(shape = { type = "cylinder", radius = 0.05, length = 0.4, mass = 2.0, axis = "x" })");
  ASSERT_TRUE(sc.body_surface);
  const inertia::TriangleMesh& m = *sc.body_surface;
  // Bounds: ±L/2 along x; ±R across (a vertex at angle 0 and π/2 of the 48-gon), to round-off.
  EXPECT_TRUE(lower(m).isApprox(Vec3(-0.2, -0.05, -0.05), 1e-15));
  EXPECT_TRUE(upper(m).isApprox(Vec3(0.2, 0.05, 0.05), 1e-15));
  // The volume of the prism on the inscribed 48-gon, (n/2) sin(2π/n) R² L; its centroid at the origin. Both
  // are sums of 4·48 tetrahedra of size R² L: round-off 1e-16 of each, far below 1e-14 and 1e-15 m.
  const inertia::VolumeIntegrals v = inertia::volume_integrals(m, Vec3::Zero());
  const double prism = kSegments / 2.0 * std::sin(2 * std::numbers::pi / kSegments) * 0.05 * 0.05 * 0.4;
  EXPECT_NEAR(v.volume, prism, 1e-14 * prism);
  EXPECT_LE(v.first.norm() / v.volume, 1e-15);
}

TEST(ViewSurface, AMeshIsTheFilesTrianglesMovedToItsCentreOfMass) {
  const Scenario sc = with_body(R"(mesh = { file = "meshes/l_bracket.obj", density = 2700.0 })");
  ASSERT_TRUE(sc.body_surface);
  const inertia::TriangleMesh& m = *sc.body_surface;
  EXPECT_EQ(m.triangles.size(), 20u);
  EXPECT_EQ(m.vertices.size(), 12u);
  // The bracket (120 × 80 × 20 mm) keeps its size (to single precision: assimp reads coordinates as floats);
  // its centroid is now the origin, the rotation point.
  EXPECT_TRUE((upper(m) - lower(m)).isApprox(Vec3(0.12, 0.08, 0.02), 1e-7));
  const inertia::VolumeIntegrals v = inertia::volume_integrals(m, Vec3::Zero());
  EXPECT_LE(v.first.norm() / v.volume, 1e-15);
}

TEST(ViewSurface, TensorsAndRodsHaveNoSurfaceAndMultibodyBodiesKeepTheirs) {
  EXPECT_FALSE(with_body("principal_moments = [1, 2, 3]").body_surface);
  EXPECT_FALSE(  // a thin shell is a surface, not a solid the tessellation closes
      with_body(R"(shape = { type = "sphere", radius = 0.1, hollow = true, mass = 1.0 })").body_surface);
  const multibody::Scenario mb =
      load_multibody_scenario(POINSOT_SOURCE_DIR "/examples/multibody/double_pendulum.toml");
  ASSERT_EQ(mb.body_surfaces.size(), 2u);
  for (const auto& s : mb.body_surfaces) {  // rod radius 0.01 m, length 1 m along x: a cylinder
    ASSERT_TRUE(s);
    EXPECT_TRUE(upper(*s).isApprox(Vec3(0.5, 0.01, 0.01), 1e-15));
  }
}

TEST(ViewSurface, AnOptimalScenarioKeepsItsBodysShapeAndMass) {
  const OptimalScenario sc = parse_optimal_scenario(R"(
[body]
shape = { type = "box", size = [0.4, 0.2, 0.1], mass = 3.0 }
[optimal_control]
objective = "minimum_time"
torque_bound = "per_axis"
torque_max = [1.0, 1.0, 1.0]
[optimal_control.final]
orientation = { quaternion = [0.0, 1.0, 0.0, 0.0] }
)",
                                                    "<test>", "");
  ASSERT_TRUE(sc.body_surface && sc.body_mass);
  EXPECT_EQ(*sc.body_mass, 3.0);
  EXPECT_TRUE(upper(*sc.body_surface).isApprox(Vec3(0.2, 0.1, 0.05), 1e-15));  // the box's half sizes
  EXPECT_TRUE(lower(*sc.body_surface).isApprox(Vec3(-0.2, -0.1, -0.05), 1e-15));
}

TEST(ViewDrawDigits, RoundsToNineSignificantDigitsWhoseShortestTextIsThatShort) {
  for (double x : {1.0 / 3.0, -2.0e-7 / 3.0, 12345.678901234, 0.0, 9.999999999e10, -1e-300}) {
    const double r = rounded_for_drawing(x);
    EXPECT_LE(std::abs(r - x), 5e-9 * std::abs(x)) << x;
    char buf[40];
    const auto end = std::to_chars(buf, buf + sizeof buf, std::abs(r), std::chars_format::scientific).ptr;
    std::string digits(buf, end);  // the shortest round trip, d.ddde±x
    digits = digits.substr(0, digits.find('e'));
    std::erase(digits, '.');
    EXPECT_LE(digits.size(), 9u) << fmt::format("{}", r);
  }
}

}  // namespace
}  // namespace poinsot::io
