// The scenario driver: trajectory CSV and report, checked on the compound pendulum example against the
// period of the large-amplitude pendulum.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>

#include "poinsot/core/error.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

/// examples/multibody/compound_pendulum.toml built directly: a rod (1 kg, 1 m, radius 1 cm, along body x)
/// hinged at one end about space y, released 0.3 rad from the vertical (the file is read in tests/io).
Scenario compound_pendulum() {
  const double m = 1, l = 1, r = 0.01, th = 0.3;
  Scenario sc;
  sc.system.add_body("rod", m, Vec3(m * l * l / 12, m * r * r / 4, m * r * r / 4).asDiagonal());
  sc.system.set_gravity(Vec3(0, 0, -9.81));
  BodyState b;
  b.R_space_body = Eigen::AngleAxisd(std::numbers::pi / 2 + th, Vec3::UnitY()).toRotationMatrix();
  b.x_space = b.R_space_body * Vec3(l / 2, 0, 0);  // the pivot at the origin
  sc.initial.bodies.push_back(b);
  sc.system.add_hinge("pivot", 0, Vec3(-l / 2, 0, 0), Vec3::UnitY(), kWorld, Vec3::Zero(), Vec3::UnitY());
  sc.dt = 1e-3;
  return sc;
}

TEST(Run, CompoundPendulumExampleHasTheTextbookPeriod) {
  // The example starts at 0.3 rad: the period is T0 (1 + θ0²/16 + 11 θ0⁴/3072 + ...) (Jacobi elliptic
  // series), 2π √(I/(m g d)) (1.005653...) — checked here to 1e-4 with the half-period from the CSV.
  Scenario sc = compound_pendulum();
  sc.title = "compound pendulum of the test";
  sc.body_descriptions = {"solid cylinder along x"};
  sc.duration = 1.0;
  sc.output_every = 1;
  const std::string csv = testing::TempDir() + "/compound.csv";
  std::ostringstream report;
  run_scenario(sc, &report, csv);
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.substr(0, 12), "t,rod.x,rod.");
  double t_prev = 0, x_prev = 0, crossing = -1;
  while (std::getline(in, line)) {
    double t, x;
    std::sscanf(line.c_str(), "%lf,%lf", &t, &x);
    if (t > 0 && x_prev < 0 && x >= 0 && crossing < 0)
      crossing = t_prev + (t - t_prev) * (-x_prev) / (x - x_prev);
    t_prev = t;
    x_prev = x;
  }
  const double m = 1, l = 1, r = 0.01, g = 9.81, th = 0.3;
  const double T0 = 2 * std::numbers::pi * std::sqrt((m * l * l / 3 + m * r * r / 4) / (m * g * l / 2));
  const double T = T0 * (1 + th * th / 16 + 11 * std::pow(th, 4) / 3072);
  EXPECT_NEAR(crossing, T / 4, 1e-4 * T);  // from −0.3 rad to the bottom: a quarter period
  EXPECT_NE(report.str().find("joint 'pivot': reaction force"), std::string::npos);
  EXPECT_NE(report.str().find("body 'rod'"), std::string::npos);
  EXPECT_NE(report.str().find("  compound pendulum of the test\n"), std::string::npos);
  EXPECT_NE(report.str().find("body 'rod': solid cylinder along x\n"), std::string::npos);
}

TEST(Run, FailureKeepsTheRowsWritten) {
  // A spin far too fast for the step: h|ω| ≥ 1 stops the run with ComputationFailed; the CSV keeps its header
  // and the initial row.
  Scenario sc;
  sc.system.add_body_from_inertia("a", 1.0, Vec3(1, 2, 3).asDiagonal());
  sc.initial.bodies.resize(1);
  sc.initial.bodies[0].omega_body = Vec3(0, 0, 20);
  sc.dt = 0.1;
  sc.duration = 1.0;
  const std::string csv = testing::TempDir() + "/fast.csv";
  EXPECT_THROW(run_scenario(sc, nullptr, csv), ComputationFailed);
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header.substr(0, 6), "t,a.x,");
  EXPECT_EQ(row.substr(0, 2), "0,");
}

}  // namespace
}  // namespace poinsot::multibody
