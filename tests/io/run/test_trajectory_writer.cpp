#include "poinsot/io/run/trajectory_writer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

std::filesystem::path writer_temp_dir(const std::string& name) {
  const auto d = ::poinsot::test::temp_path("poinsot_io_test_" + name);
  std::filesystem::remove_all(d);
  std::filesystem::create_directories(d);
  return d;
}

std::vector<std::string> lines_of(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::string> out;
  for (std::string line; std::getline(in, line);)
    out.push_back(line);
  return out;
}

std::vector<double> fields(const std::string& line) {
  std::vector<double> out;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, ',');)
    out.push_back(std::stod(f));
  return out;
}

TEST(TrajectoryCsvWriter, RowsReadBackExactlyWithTheirInvariants) {
  const auto dir = writer_temp_dir("csv");
  const auto body =
      dynamics::RigidBody::from_principal_moments(Vec3(1, 2, 3)).with_pivot(2.0, Vec3(0, 0, 0.1));
  const Vec3 g(0, 0, -9.81);
  std::vector<dynamics::State> states;
  for (int i = 0; i < 50; ++i) {
    dynamics::State s;
    s.time = 0.1 * i;
    s.R_space_body = test::random_rotation();
    s.omega_body = test::random_vector(3.0);
    states.push_back(s);
  }
  {
    TrajectoryCsvWriter w((dir / "t.csv").string(), body, g);
    for (const auto& s : states)
      w.write(s);
    EXPECT_EQ(w.rows(), 50);
  }  // the destructor flushes
  const auto lines = lines_of(dir / "t.csv");
  ASSERT_EQ(lines.size(), 52u);
  EXPECT_EQ(lines[0].rfind("# poinsot trajectory. Units: t s;", 0), 0u);
  EXPECT_EQ(lines[1],
            "t,qw,qx,qy,qz,wx,wy,wz,energy,L_space_x,L_space_y,L_space_z,L_body_x,L_body_y,L_body_z");
  for (std::size_t i = 0; i < states.size(); ++i) {
    const auto f = fields(lines[i + 2]);
    ASSERT_EQ(f.size(), 15u);
    const auto& s = states[i];
    const Quat q = s.quaternion();
    // Shortest round-trip text: every number reads back bit for bit.
    EXPECT_EQ(f[0], s.time);
    EXPECT_EQ(Vec3(f[5], f[6], f[7]), s.omega_body);
    EXPECT_EQ(f[1], q.w());
    EXPECT_EQ(f[8], dynamics::total_energy(body, s, g));
    EXPECT_EQ(Vec3(f[9], f[10], f[11]), dynamics::angular_momentum_space(body, s));
    EXPECT_EQ(Vec3(f[12], f[13], f[14]), dynamics::angular_momentum_body(body, s));
  }
}

TEST(TrajectoryCsvWriter, FlushHandsOverEveryWholeRow) {
  const auto dir = writer_temp_dir("flush");
  const auto body = dynamics::RigidBody::from_principal_moments(Vec3(1, 2, 3));
  TrajectoryCsvWriter w((dir / "t.csv").string(), body, Vec3::Zero());
  dynamics::State s;
  s.omega_body = Vec3(1, 2, 3);
  for (int i = 0; i < 7; ++i) {
    s.time = i;
    w.write(s);
  }
  w.flush();
  // While the writer is still open, the file holds the header and the 7 rows, each ending in a newline.
  std::ifstream in(dir / "t.csv");
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 9);
  EXPECT_EQ(text.back(), '\n');
}

TEST(TrajectoryCsvWriter, UnwritablePathIsAnInvalidInput) {
  const auto dir = writer_temp_dir("bad");
  std::ofstream(dir / "file") << "x";
  const auto body = dynamics::RigidBody::from_principal_moments(Vec3(1, 2, 3));
  EXPECT_THROW(TrajectoryCsvWriter((dir / "file" / "t.csv").string(), body, Vec3::Zero()), InvalidInput);
}

}  // namespace
}  // namespace poinsot::io
