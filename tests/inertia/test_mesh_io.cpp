// Tests of mesh_io.hpp: the same box written in every supported format (STL ascii and binary, OBJ, PLY, OFF)
// reads back to the box's closed-form mass properties; bad files give one-line errors. The fixtures are
// written by the test into a temporary folder (small text files, nothing stored in the repository).
#include "poinsot/inertia/mesh_io.hpp"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

namespace fs = std::filesystem;
using test::max_abs_diff;

class MeshIo : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / fmt::format("poinsot_mesh_io_{}_{}", ::getpid(),
                                                   ::testing::UnitTest::GetInstance()->random_seed());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& text) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  fs::path dir_;
};

// Box 2 × 1 × 0.5 (exactly representable in float: the files are read in single precision).
const Vec3 kSize(2.0, 1.0, 0.5);

std::string stl_ascii(const TriangleMesh& m) {
  std::string s = "solid box\n";
  for (const auto& t : m.triangles) {
    s += " facet normal 0 0 0\n  outer loop\n";
    for (auto i : t) {
      const Vec3& v = m.vertices[static_cast<std::size_t>(i)];
      s += fmt::format("   vertex {} {} {}\n", v.x(), v.y(), v.z());
    }
    s += "  endloop\n endfacet\n";
  }
  return s + "endsolid box\n";
}

std::string obj(const TriangleMesh& m) {
  std::string s = "# box\n";
  for (const auto& v : m.vertices)
    s += fmt::format("v {} {} {}\n", v.x(), v.y(), v.z());
  for (const auto& t : m.triangles)
    s += fmt::format("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
  return s;
}

std::string ply(const TriangleMesh& m) {
  std::string s = fmt::format(
      "ply\nformat ascii 1.0\nelement vertex {}\nproperty float x\nproperty float y\nproperty float z\n"
      "element face {}\nproperty list uchar int vertex_indices\nend_header\n",
      m.vertices.size(), m.triangles.size());
  for (const auto& v : m.vertices)
    s += fmt::format("{} {} {}\n", v.x(), v.y(), v.z());
  for (const auto& t : m.triangles)
    s += fmt::format("3 {} {} {}\n", t[0], t[1], t[2]);
  return s;
}

std::string off(const TriangleMesh& m) {
  std::string s = fmt::format("OFF\n{} {} 0\n", m.vertices.size(), m.triangles.size());
  for (const auto& v : m.vertices)
    s += fmt::format("{} {} {}\n", v.x(), v.y(), v.z());
  for (const auto& t : m.triangles)
    s += fmt::format("3 {} {} {}\n", t[0], t[1], t[2]);
  return s;
}

void expect_box(const TriangleMesh& m) {
  MeshDiagnostics d;
  const MassProperties p = mesh_mass_properties(m, 1.0, {}, &d);
  const MassProperties f = box(kSize.prod(), kSize);
  EXPECT_EQ(d.vertices, 8u);  // welded
  EXPECT_TRUE(d.messages().empty());
  EXPECT_NEAR(p.mass, f.mass, 1e-14);
  EXPECT_LE(max_abs_diff(p.inertia_com, f.inertia_com), 1e-14);
}

TEST_F(MeshIo, EveryFormatReadsTheSameBox) {
  const TriangleMesh m = box_mesh(kSize);
  expect_box(load_mesh(write("box_ascii.stl", stl_ascii(m))));
  expect_box(load_mesh(write("box.obj", obj(m))));
  expect_box(load_mesh(write("box.ply", ply(m))));
  expect_box(load_mesh(write("box.off", off(m))));
  const std::string bin = (dir_ / "box_binary.stl").string();
  write_binary_stl(m, bin);
  expect_box(load_mesh(bin));
}

TEST_F(MeshIo, QuadsAreTriangulatedWithTheirWinding) {
  // A cube as six quads in OBJ, outward: assimp triangulates, the winding is kept.
  const std::string cube =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
      "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
  const MassProperties p = mesh_mass_properties(load_mesh(write("cube.obj", cube)), 1.0);
  EXPECT_NEAR(p.mass, 1.0, 1e-15);
  EXPECT_LE((p.com - Vec3(0.5, 0.5, 0.5)).norm(), 1e-15);
}

TEST_F(MeshIo, BadFilesGiveOneLineErrors) {
  auto message = [](const std::string& path) { return test::message_of([&] { load_mesh(path); }); };
  const std::string missing = message((dir_ / "missing.stl").string());
  EXPECT_NE(missing.find("cannot open"), std::string::npos) << missing;
  const std::string empty = message(write("empty.stl", ""));
  EXPECT_NE(empty.find("is empty"), std::string::npos) << empty;
  const std::string text = message(write("notes.txt", "this is not a mesh\n"));
  EXPECT_NE(text.find("cannot read"), std::string::npos) << text;
  for (const std::string& msg : {missing, empty, text})
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
}

TEST_F(MeshIo, ResourceLimitsAreCheckedBeforeTheWork) {
  const std::string cube = std::string(POINSOT_TEST_DATA_DIR) + "/inertia/cube_10cm.stl";  // 12 triangles
  const auto refusal = [](const std::string& path, const MeshLimits& limits) {
    return test::message_of<InvalidInput>([&] { load_mesh(path, limits); }, path);
  };
  MeshLimits few;
  few.max_triangles = 11;
  test::expect_has(refusal(cube, few), {"has 12 faces; the limit is 11 triangles", "--max-mesh-triangles"});
  few.max_triangles = 12;
  EXPECT_EQ(load_mesh(cube, few).triangles.size(), 12u);
  MeshLimits small;
  small.max_file_bytes = 100;
  test::expect_has(refusal(cube, small), {"is 1814 bytes; the limit is 100 bytes", "--max-mesh-bytes"});
  test::expect_has(refusal("/dev/zero", {}), {"\"/dev/zero\" is not a regular file"});
  // Fuzzing findings: assimp asserted on an OFF file whose face counts disagree, and looped without end on a
  // PLY header cut short; both are now one-line refusals.
  test::expect_has(refusal(write("bad.off", "OFF\n8 6 0\n0 0 0\n 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n"), {}),
                   {"bad.off", "cannot read"});
  test::expect_has(
      refusal(write("cut.ply", "ply\nformat ascii 1.0\nelement vertex 4\nproperty float  0 2 1\n3 0 1 3\n"),
              {}),
      {"cut.ply", "PLY header line 4: malformed property"});
}

}  // namespace
}  // namespace poinsot::inertia
