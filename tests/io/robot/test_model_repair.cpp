// Tests of model_repair.hpp: valid models come back byte for byte; each repaired tensor is valid and is the
// nearest valid one, against an independent projection (Eigen's eigensolver for the axes and Dykstra's
// alternating projections for the moments, instead of the library's Jacobi sweeps and face enumeration);
// only the edited values change in the text; --from-geometry writes the closed-form tensors.
#include "poinsot/io/robot/model_repair.hpp"

#include <array>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Eigenvalues>

#include "poinsot/inertia/validity.hpp"
#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

using test::max_abs_diff;

std::string model_path(const std::string& name) {
  return std::string(POINSOT_TEST_DATA_DIR "/models/") + name;
}

std::string bytes_of(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream s(text);
  for (std::string line; std::getline(s, line);)
    lines.push_back(line);
  return lines;
}

/// Dykstra's algorithm: projection of the moments onto the cone n_k·μ >= 0 (the triangle inequalities).
Vec3 dykstra(const Vec3& x) {
  const std::array<Vec3, 3> n{Vec3(-1, 1, 1), Vec3(1, -1, 1), Vec3(1, 1, -1)};
  Vec3 y = x;
  std::array<Vec3, 3> p{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  for (int it = 0; it < 20000; ++it) {
    const Vec3 before = y;
    for (std::size_t k = 0; k < 3; ++k) {
      const Vec3 z = y + p[k];
      const double s = n[k].dot(z);
      const Vec3 proj = s >= 0 ? z : Vec3(z - s / n[k].squaredNorm() * n[k]);
      p[k] = z - proj;
      y = proj;
    }
    if (it > 10 && (y - before).norm() < 1e-17) break;
  }
  return y;
}

/// The nearest valid tensor, computed independently of validity.hpp.
Mat3 independent_projection(const Mat3& J) {
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(J);
  return eig.eigenvectors() * dykstra(eig.eigenvalues()).asDiagonal() * eig.eigenvectors().transpose();
}

ModelRepair repaired(const RobotModel& m, RepairMode mode) {
  return repair_model(m, check_model(m), mode);
}

TEST(ModelRepair, ValidModelsComeBackByteForByte) {
  for (const char* file : {"valid_arm.urdf", "valid_arm.xml", "valid_robot.sdf"}) {
    const RobotModel m = load_robot_model(model_path(file));
    const ModelRepair r = repaired(m, RepairMode::nearest_valid);
    EXPECT_TRUE(r.edits.empty()) << file;
    EXPECT_EQ(r.text, bytes_of(model_path(file))) << file;
  }
}

TEST(ModelRepair, RepairedTensorsAreValidAndNearest) {
  for (const char* file : {"defects.urdf", "defects.xml", "defects.sdf"}) {
    const RobotModel before = load_robot_model(model_path(file));
    const ModelRepair r = repaired(before, RepairMode::nearest_valid);
    const RobotModel after = read_robot_model(r.text, file);
    ASSERT_EQ(after.links.size(), before.links.size());
    std::size_t edited = 0;
    for (std::size_t k = 0; k < before.links.size(); ++k) {
      const RobotLink& b = before.links[k];
      const RobotLink& a = after.links[k];
      if (!b.has_inertial) continue;
      const bool was_valid = inertia::check_inertia(b.inertia_link).valid;
      EXPECT_TRUE(inertia::check_inertia(a.inertia_link).valid) << file << " " << b.name;
      if (was_valid) {
        EXPECT_EQ(a.inertia_link, b.inertia_link) << file << " " << b.name;
        continue;
      }
      ++edited;
      // Nearest: the independent projection, to round-off of the written numbers (17 significant digits)
      // and of two eigensolvers (a few ulps of the trace).
      const Mat3 expected = independent_projection(b.inertia_link);
      EXPECT_LE(max_abs_diff(a.inertia_link, expected), 1e-13 * b.inertia_link.cwiseAbs().maxCoeff())
          << file << " " << b.name;
      EXPECT_EQ(a.com_link, b.com_link);
      EXPECT_EQ(a.mass, b.mass);
    }
    EXPECT_EQ(r.edits.size(), edited) << file;
    EXPECT_GT(edited, 0u) << file;
  }
}

TEST(ModelRepair, OnlyTheEditedValuesChange) {
  // In defects.urdf each tensor is on one line: exactly the <inertia> lines of the three invalid links
  // differ.
  const std::string original = bytes_of(model_path("defects.urdf"));
  const ModelRepair r = repaired(load_robot_model(model_path("defects.urdf")), RepairMode::nearest_valid);
  const auto a = lines_of(original);
  const auto b = lines_of(r.text);
  ASSERT_EQ(a.size(), b.size());
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (a[i] == b[i]) continue;
    changed.push_back(i);
    EXPECT_NE(b[i].find("<inertia ixx=\""), std::string::npos) << b[i];
  }
  EXPECT_EQ(changed.size(), 3u);
  EXPECT_EQ(r.edits.size(), 3u);
  // MJCF diaginertia stays three numbers (the repaired tensor is diagonal in the same frame), quat untouched.
  const ModelRepair m = repaired(load_robot_model(model_path("defects.xml")), RepairMode::nearest_valid);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(m.text, match, std::regex("diaginertia=\"([^\"]*)\"")));
  const auto numbers = lines_of(std::regex_replace(match[1].str(), std::regex(" "), "\n"));
  ASSERT_EQ(numbers.size(), 3u);
  // (10, 10, 25) moved along (1, 1, −1) by 5/3 onto I1 + I2 = I3.
  const double d = 5.0 / 3.0;
  EXPECT_NEAR(std::stod(numbers[0]), 10 + d, 1e-14);
  EXPECT_NEAR(std::stod(numbers[1]), 10 + d, 1e-14);
  EXPECT_NEAR(std::stod(numbers[2]), 25 - d, 1e-14);
  EXPECT_NE(m.text.find("quat=\"0.7071067811865476 0 0 0.7071067811865476\""), std::string::npos);
}

TEST(ModelRepair, FromGeometryWritesTheGeometrysTensorInTheFilesFrame) {
  // valid_arm.urdf already carries its geometry's tensors: --from-geometry gives them back (to round-off of
  // the turned frames), written in each inertial frame (upper_arm: the cylinder's own axes).
  const RobotModel m = load_robot_model(model_path("valid_arm.urdf"));
  const ModelRepair r = repaired(m, RepairMode::from_geometry);
  EXPECT_EQ(r.edits.size(), 4u);
  const RobotModel after = read_robot_model(r.text, "a.urdf");
  for (std::size_t k = 0; k < m.links.size(); ++k) {
    // The cube is read from a float STL: 1e-7 relative; the shapes are closed forms to round-off.
    EXPECT_LE(max_abs_diff(after.links[k].inertia_file, m.links[k].inertia_file),
              1e-7 * m.links[k].inertia_file.trace())
        << m.links[k].name;
  }
  // A sphere of 500 kg and radius 0.2 m: 2/5 m r² = 8 kg·m² (defects.xml, full_bad: fullinertia rewritten).
  const ModelRepair x = repaired(load_robot_model(model_path("defects.xml")), RepairMode::from_geometry);
  const RobotModel xa = read_robot_model(x.text, "d.xml");
  EXPECT_LE(max_abs_diff(xa.links[1].inertia_link, Mat3(Vec3::Constant(8.0).asDiagonal())), 1e-14);
  // A box turned by 45° in a diaginertia frame: its tensor is not diagonal there, so the link is kept.
  const RobotModel turned = read_robot_model(
      "<mujoco><worldbody><body name=\"b\"><inertial mass=\"1\" diaginertia=\"1 1 1\"/>"
      "<geom type=\"box\" size=\"0.1 0.3 0.2\" quat=\"0.9238795325112867 0 0 0.3826834323650898\"/>"
      "</body></worldbody></mujoco>",
      "t.xml");
  const ModelRepair t = repaired(turned, RepairMode::from_geometry);
  EXPECT_TRUE(t.edits.empty());
  ASSERT_EQ(t.skipped.size(), 1u);
  test::expect_has(t.skipped[0], {"link b", "diaginertia cannot hold"});
  EXPECT_EQ(t.text, turned.text);
}

}  // namespace
}  // namespace poinsot::io
