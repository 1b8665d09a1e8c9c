// Tests of the PLY checks made before assimp reads a file (src/inertia/ply_check.hpp), through load_mesh: a
// box written as binary PLY in both byte orders, with lists of 8-bit and 32-bit lengths and an extra scalar
// per face, reads back to the box's closed-form mass properties (the walk accepts valid files); a list
// declaring more values than the file holds — the fuzzing finding, 3·10^8 indices in a 300-byte file — is
// refused with one line before assimp allocates for it, in binary and ASCII; so are negative and fractional
// lengths, a body cut short and an unknown property type. The files are written by the test into a temporary
// folder.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

namespace fs = std::filesystem;

class PlyCheck : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(dir_); }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& name, const std::string& bytes) const {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << bytes;
    return p.string();
  }
  std::string refusal(const std::string& name, const std::string& bytes) const {
    const std::string path = write(name, bytes);
    return test::message_of<InvalidInput>([&] { load_mesh(path); }, name);
  }
  fs::path dir_ = test::temp_path("ply_check");
};

/// `value` as `T` in the given byte order.
template <class T>
std::string bytes_of(T value, bool little) {
  std::string b(sizeof(T), '\0');
  std::memcpy(b.data(), &value, sizeof(T));
  if (little != (std::endian::native == std::endian::little)) std::reverse(b.begin(), b.end());
  return b;
}

const Vec3 kPlyBoxSize(2.0, 1.0, 0.5);  // exactly representable in float

/// The box as binary PLY: float vertices; faces with a list of length type `Count` and an extra int
/// property after it (a scalar the walk must step over).
template <class Count>
std::string binary_box(bool little, const char* count_type) {
  const TriangleMesh m = box_mesh(kPlyBoxSize);
  std::string s = fmt::format(
      "ply\nformat {} 1.0\ncomment poinsot test\nelement vertex {}\nproperty float x\nproperty float y\n"
      "property float z\nelement face {}\nproperty list {} int vertex_indices\nproperty int "
      "flags\nend_header\n",
      little ? "binary_little_endian" : "binary_big_endian", m.vertices.size(), m.triangles.size(),
      count_type);
  for (const auto& v : m.vertices)
    for (int k = 0; k < 3; ++k)
      s += bytes_of(static_cast<float>(v[k]), little);
  for (const auto& t : m.triangles) {
    s += bytes_of(static_cast<Count>(3), little);
    for (auto i : t)
      s += bytes_of(static_cast<std::int32_t>(i), little);
    s += bytes_of(std::int32_t{7}, little);
  }
  return s;
}

void expect_ply_box(const TriangleMesh& m) {
  const MassProperties p = mesh_mass_properties(m, 1.0);
  const MassProperties f = box(kPlyBoxSize.prod(), kPlyBoxSize);
  EXPECT_NEAR(p.mass, f.mass, 1e-14);  // float coordinates of exact binary values: exact up to summation
  EXPECT_LE(test::max_abs_diff(p.inertia_com, f.inertia_com), 1e-14);
}

TEST_F(PlyCheck, ValidBinaryFilesInBothByteOrdersRead) {
  expect_ply_box(load_mesh(write("le8.ply", binary_box<std::uint8_t>(true, "uchar"))));
  expect_ply_box(load_mesh(write("be8.ply", binary_box<std::uint8_t>(false, "uint8"))));
  expect_ply_box(load_mesh(write("le32.ply", binary_box<std::uint32_t>(true, "uint"))));
  expect_ply_box(load_mesh(write("be32.ply", binary_box<std::int32_t>(false, "int32"))));
}

/// A tetrahedron's header and vertices, then one face whose list length is `length` (uint32), then 3 indices.
std::string huge_face(bool little, std::uint32_t length) {
  std::string s = fmt::format(
      "ply\nformat {} 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uint int vertex_indices\nend_header\n",
      little ? "binary_little_endian" : "binary_big_endian");
  for (float c : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f})
    s += bytes_of(c, little);
  s += bytes_of(length, little);
  for (std::int32_t i : {0, 1, 2})
    s += bytes_of(i, little);
  return s;
}

TEST_F(PlyCheck, ListLongerThanTheFileIsRefusedBeforeAssimpAllocates) {
  // 3·10^8 indices of 4 bytes (1.2 GB of values; assimp allocated 2.4 GB for them) in a file of 300 bytes.
  for (bool little : {true, false}) {
    test::expect_has(refusal("huge.ply", huge_face(little, 300'000'000)),
                     {"huge.ply", "PLY element face 0 declares a list of 300000000 values with 12 bytes left",
                      "at most one per 4 bytes"});
  }
  // The boundary: 3 values of 4 bytes fit in the 12 bytes left, 4 do not.
  EXPECT_NO_THROW(load_mesh(write("three.ply", huge_face(true, 3))));
  test::expect_has(refusal("four.ply", huge_face(true, 4)), {"a list of 4 values with 12 bytes left"});
  // ASCII: each value takes at least a character and a separator.
  const std::string ascii_header =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n";
  test::expect_has(refusal("huge_ascii.ply", ascii_header + "300000000 0 1 2\n"),
                   {"PLY element face 0 declares a list of 300000000 values with 6 bytes left",
                    "at most one per 2 characters"});
  test::expect_has(refusal("negative.ply", ascii_header + "-1 0 1 2\n"), {"a list of -1 values"});
  test::expect_has(refusal("fraction.ply", ascii_header + "2.5 0 1 2\n"), {"a list of 2.5 values"});
  EXPECT_EQ(load_mesh(write("ascii.ply", ascii_header + "3 0 1 2\n")).triangles.size(), 1u);
}

TEST_F(PlyCheck, TruncatedBodiesAndUnknownTypesAreRefused) {
  const std::string box = binary_box<std::uint8_t>(true, "uchar");
  test::expect_has(refusal("cut_faces.ply", box.substr(0, box.size() - 3)),
                   {"PLY body ends inside element face 11 (the header declares 12)"});
  test::expect_has(refusal("cut_vertices.ply", box.substr(0, box.find("end_header\n") + 11 + 20)),
                   {"PLY body ends inside element vertex 1 (the header declares 8)"});
  std::string unknown = box;
  unknown.replace(unknown.find("property int flags"), 18, "property int9 flags");
  test::expect_has(refusal("unknown.ply", unknown), {"PLY header line 10", "property type \"int9\" unknown"});
  // Every refusal above is one line.
  for (const char* name : {"cut_faces.ply", "unknown.ply"}) {
    const std::string path = (dir_ / name).string();
    EXPECT_EQ(test::message_of<InvalidInput>([&] { load_mesh(path); }, name).find('\n'), std::string::npos);
  }
}

TEST_F(PlyCheck, ControlCharactersAndTextAfterEndHeaderAreRefused) {
  // Found by fuzzing: "end_header" followed by a vertical tab and more text on its line made assimp's ASCII
  // reader loop forever. The valid ASCII triangle below reads; each corruption of it is refused in one line.
  const std::string head =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
      "property float z\nelement face 1\nproperty list uchar int vertex_indices\n";
  const std::string body = "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
  EXPECT_EQ(load_mesh(write("triangle.ply", head + "end_header\n" + body)).triangles.size(), 1u);
  test::expect_has(refusal("vtab.ply", head + "end_header\v0 0 0end_header\n" + body),
                   {"PLY header line 9", "control character 0x0b"});
  test::expect_has(refusal("after.ply", head + "end_header 0 0 0\n" + body),
                   {"PLY header line 9", "text after end_header"});
  test::expect_has(refusal("formfeed.ply", "ply\nformat ascii 1.0\f\n" + body), {"control character 0x0c"});
}

}  // namespace
}  // namespace poinsot::inertia
