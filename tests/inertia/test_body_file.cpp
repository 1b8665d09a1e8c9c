// Tests of body_file.hpp: composites written in TOML against closed forms (two halves of a box make the box,
// a box minus a box-shaped void), a mesh part read from a file, and one-line errors naming the part.
#include "poinsot/inertia/body_file.hpp"

#include <filesystem>
#include <fstream>
#include <numbers>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

using test::kEps;
using test::max_abs_diff;

std::string message_of(const std::string& toml) {
  return test::message_of([&] { parse_body(toml); });
}

TEST(BodyFile, TwoHalvesMakeABox) {
  // Two 0.1 × 0.2 × 0.3 boxes side by side along x, the second given by density and rotated by π about z
  // (a symmetry of the box: no change) = one 0.2 × 0.2 × 0.3 box.
  const BodyFileResult r = parse_body(R"(
[[part]]
shape = "box"
size = [0.1, 0.2, 0.3]
mass = 3.0
position = [-0.05, 0, 0]

[[part]]
shape = "box"
size = [0.1, 0.2, 0.3]
density = 500.0
position = [0.05, 0, 0]
axis_angle = [0, 0, 1, 180]
degrees = true
)");
  EXPECT_EQ(r.parts, 2u);
  const MassProperties expected = box(6.0, Vec3(0.2, 0.2, 0.3));
  EXPECT_NEAR(r.body.mass, 6.0, 8 * kEps * 6);
  EXPECT_LE(r.body.com.norm(), 8 * kEps);
  EXPECT_LE(max_abs_diff(r.body.inertia_com, expected.inertia_com), 16 * kEps * expected.inertia_com.norm());
}

TEST(BodyFile, VoidIsSubtracted) {
  // A 0.2 × 0.2 × 0.3 box with the +x half removed leaves the −x half.
  const BodyFileResult r = parse_body(R"(
[[part]]
shape = "box"
size = [0.2, 0.2, 0.3]
density = 1000

[[void]]
shape = "box"
size = [0.1, 0.2, 0.3]
density = 1000
position = [0.05, 0, 0]
)");
  EXPECT_EQ(r.voids, 1u);
  const MassProperties half = box(6.0, Vec3(0.1, 0.2, 0.3));  // 1000 kg/m³ × 0.006 m³
  EXPECT_NEAR(r.body.mass, 6.0, 16 * kEps * 12);
  EXPECT_LE((r.body.com - Vec3(-0.05, 0, 0)).norm(), 16 * kEps);
  EXPECT_LE(max_abs_diff(r.body.inertia_com, half.inertia_com), 64 * kEps * half.inertia_com.norm());
}

TEST(BodyFile, MeshPartAndEulerPose) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / fmt::format("poinsot_body_{}", ::getpid());
  fs::create_directories(dir);
  write_binary_stl(box_mesh(Vec3(0.5, 1.0, 2.0)), (dir / "part.stl").string());
  std::ofstream(dir / "body.toml") << R"(
[[part]]
mesh = "part.stl"
mass = 2.0
position = [1, 2, 3]
euler = [90, 0, 0]
euler_sequence = "ZYX"
degrees = true
)";
  const BodyFileResult r = load_body_file((dir / "body.toml").string());
  fs::remove_all(dir);
  // Rotated by 90° about z: the x and y sizes swap.
  const MassProperties expected = box(2.0, Vec3(1.0, 0.5, 2.0));
  EXPECT_LE((r.body.com - Vec3(1, 2, 3)).norm(), 1e-14);
  EXPECT_LE(max_abs_diff(r.body.inertia_com, expected.inertia_com), 1e-14);
}

TEST(BodyFile, ErrorsNameThePartAndTheField) {
  EXPECT_NE(message_of("[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\n")
                .find("part 1: expected exactly one of mass"),
            std::string::npos);
  EXPECT_NE(
      message_of("[[part]]\nshape = \"box\"\nsize = [1, -1, 1]\nmass = 1\n").find("part 1: box: size y"),
      std::string::npos);
  EXPECT_NE(message_of("[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1\ncolour = 3\n")
                .find("unknown key \"colour\""),
            std::string::npos);
  EXPECT_NE(message_of("[[part]]\nshape = \n").find("TOML error at line"), std::string::npos);
  EXPECT_NE(message_of("").find("no [[part]]"), std::string::npos);
  EXPECT_NE(message_of("[[part]]\nshape = \"box\"\nsize = [1, 1, 1]\nmass = 1\n[[void]]\nshape = \"box\"\n"
                       "size = [1, 1, 1]\nmass = 2\n")
                .find("void 1:"),
            std::string::npos);
  EXPECT_NE(message_of("[[part]]\nmesh = \"no_such_file.stl\"\nmass = 1\n").find("part 1: mesh: cannot open"),
            std::string::npos);
  EXPECT_THROW(load_body_file("/nonexistent/body.toml"), InvalidInput);
}

TEST(BodyFile, TomlErrorQuotingSeveralLinesIsOneLine) {
  // toml++ quotes the offending text, here over two lines (a fuzzing finding).
  const std::string m = message_of("degrees = tr\neu\n");
  EXPECT_NE(m.find("TOML error at line 1"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

TEST(BodyFile, ShapeNameOverSeveralLinesIsQuotedOnOneLine) {
  // A TOML multi-line string as the shape name, quoted back in the refusal (a fuzzing finding).
  const std::string m = message_of("[[part]]\nshape = \"\"\"\nrod\nbox\"\"\"\nmass = 1\n");
  EXPECT_NE(m.find("shape: got \"rod box\", expected one of point"), std::string::npos) << m;
  EXPECT_EQ(m.find('\n'), std::string::npos) << m;
}

}  // namespace
}  // namespace poinsot::inertia
