// The scenario driver: trajectory CSV and report, checked on the compound pendulum example against the
// period of the large-amplitude pendulum.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

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

TEST(Run, ProjectedRk4RunsTheSameScenarioToFourthOrder) {
  // The same pendulum with method = rk4: the report names the method and its projection iterations, the
  // joint holds, and the energy error is O(h⁴) against RATTLE's O(h²) (measured by `poinsot run
  // examples/multibody/compound_pendulum.toml --t-end 1 [--method rk4]`: 5.8e-13 J against 8.2e-7 J at h =
  // 1e-3; the pendulum's energy is m g l/2 (1 − cos 0.3) ≈ 0.22 J above the bottom).
  Scenario sc = compound_pendulum();
  sc.duration = 1.0;
  const RunSummary rattle = run_scenario(sc, nullptr, "");
  sc.method = MultibodyMethod::projected_rk4;
  std::ostringstream report;
  const RunSummary rk4 = run_scenario(sc, &report, "");
  EXPECT_NE(report.str().find("method: RK4 projected onto the joints (order 4, not symplectic)"),
            std::string::npos);
  EXPECT_NE(report.str().find("projection iterations per step: mean"), std::string::npos);
  EXPECT_EQ(rk4.kkt_method, KktMethod::tree);  // a hinge: Baraff's tree order
  EXPECT_LT(rk4.max_joint_gap, 2e-13);
  EXPECT_LT(rk4.max_joint_angle, 1.5e-13);
  EXPECT_LT(rk4.max_energy_error, 1e-3 * rattle.max_energy_error);
  EXPECT_GT(rattle.max_energy_error,
            1e-8);  // RATTLE's error is well above round-off: the ratio means something
}

/// The rows of a CSV file after its header, as numbers.
std::vector<std::vector<double>> read_rows(const std::string& path, std::string& header) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string f;
    while (std::getline(fields, f, ','))
      row.push_back(std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

TEST(Run, DiagnosticsRowsAreTheObservablesOfTheTrajectoryRows) {
  // The compound pendulum pushed (ω projected onto the hinge's axis), 503 steps written every 7 (the
  // last row is the final step, not a multiple of 7). Each diagnostics row is checked against the trajectory
  // row of the same index, through formulas written out here for the rod (not the library's observables):
  // T = ½ m|v|² + ½ Σ J_k ω_k², V = m g z, p = m|v|, L = x × m v + R J ω, the gap |x + R (−l/2, 0, 0)| of the
  // pivot at the origin. v, ω and x are printed with 17 digits (exact round trip), so T and V agree to the
  // last bits (1e-14 relative: a sum of three terms); R comes back through the printed quaternion, off by
  // ~1e-16, which bounds the difference in L (~1e-15 kg·m²/s) and the gap (~1e-16 m): 1e-13 leaves margin.
  Scenario sc = compound_pendulum();
  sc.initial.bodies[0].omega_body = Vec3(0.4, 2.0, -0.3);
  project_velocities(sc.system, sc.initial);
  sc.duration = 0.503;
  sc.output_every = 7;
  const std::string traj_csv = testing::TempDir() + "/diag_traj.csv";
  const std::string diag_csv = testing::TempDir() + "/diag_diag.csv";
  const RunSummary s = run_scenario(sc, nullptr, traj_csv, diag_csv);
  std::string traj_header, diag_header;
  const auto traj = read_rows(traj_csv, traj_header);
  const auto diag = read_rows(diag_csv, diag_header);
  EXPECT_EQ(diag_header,
            "t,energy,energy_error,kinetic,potential,linear_momentum,L_space_x,L_space_y,L_space_z,joint_gap,"
            "joint_angle,orthogonality");
  ASSERT_EQ(traj.size(), 1u + 503u / 7u + 1u);
  ASSERT_EQ(diag.size(), traj.size());
  const double m = 1, l = 1, r = 0.01, g = 9.81;
  const Vec3 K(m * l * l / 12, m * r * r / 4, m * r * r / 4);  // compound_pendulum()'s Poinsot tensor
  const Vec3 J = Vec3::Constant(K.sum()) - K;                  // J = tr(K) I − K, about the centre of mass
  const double E0 = diag[0][1];
  double max_error = 0;
  for (std::size_t k = 0; k < diag.size(); ++k) {
    const std::vector<double>& a = traj[k];
    const std::vector<double>& d = diag[k];
    ASSERT_EQ(a.size(), 14u);
    ASSERT_EQ(d.size(), 12u);
    const Vec3 x(a[1], a[2], a[3]), v(a[8], a[9], a[10]), w(a[11], a[12], a[13]);
    const Mat3 R = Quat(a[4], a[5], a[6], a[7]).toRotationMatrix();
    const double T = 0.5 * m * v.squaredNorm() + 0.5 * w.dot(J.cwiseProduct(w));
    const double V = m * g * x.z();
    const Vec3 L = x.cross(m * v) + R * J.cwiseProduct(w);
    EXPECT_EQ(d[0], a[0]);
    EXPECT_NEAR(d[3], T, 1e-14 * (T + 1));
    EXPECT_NEAR(d[4], V, 1e-14 * (std::abs(V) + 1));
    EXPECT_NEAR(d[1], T + V, 1e-14 * (T + std::abs(V) + 1));
    EXPECT_DOUBLE_EQ(d[2], d[1] - E0);
    EXPECT_NEAR(d[5], m * v.norm(), 1e-14);
    EXPECT_NEAR(d[6], L.x(), 1e-13);
    EXPECT_NEAR(d[7], L.y(), 1e-13);
    EXPECT_NEAR(d[8], L.z(), 1e-13);
    EXPECT_NEAR(d[9], (x + R * Vec3(-l / 2, 0, 0)).norm(), 1e-13);
    EXPECT_LT(d[10], 1e-12);  // hinge angle: RATTLE holds the constraints to round-off (rattle.hpp)
    EXPECT_LT(d[11], 1e-12);
    max_error = std::max(max_error, std::abs(d[2]));
  }
  EXPECT_EQ(diag[0][2], 0.0);
  // The summary's maximum is over every step, the rows over every 7th: never above it; and RATTLE's energy
  // error on the swing is O(h²), not zero.
  EXPECT_LE(max_error, s.max_energy_error);
  EXPECT_GT(max_error, 0.0);
}

TEST(Run, DiagnosticsEveryStepReachTheSummarysEnergyError) {
  // With a row every step, the column's largest |E − E0| is the summary's max_energy_error: the same doubles
  // (E = T + V, observables.cpp) printed with 17 digits, which round-trip exactly.
  Scenario sc = compound_pendulum();
  sc.duration = 0.2;
  sc.output_every = 1;
  const std::string diag_csv = testing::TempDir() + "/diag_every.csv";
  const RunSummary s = run_scenario(sc, nullptr, "", diag_csv);
  std::string header;
  const auto diag = read_rows(diag_csv, header);
  ASSERT_EQ(diag.size(), 201u);
  double max_error = 0;
  for (const auto& d : diag)
    max_error = std::max(max_error, std::abs(d[2]));
  EXPECT_GT(s.max_energy_error, 0.0);
  EXPECT_EQ(max_error, s.max_energy_error);
  EXPECT_DOUBLE_EQ(diag.back()[1], s.energy_final);
}

TEST(Run, SampleTimesAreExactMultiplesOfTheStep) {
  // dt = 0.01 s has no exact binary form: adding it 50 times gives 0.5000000000000002, not 0.5.
  Scenario sc = compound_pendulum();
  sc.dt = 0.01;
  sc.duration = 0.5;
  sc.output_every = 1;
  const std::string csv = testing::TempDir() + "/times.csv";
  (void)run_scenario(sc, nullptr, csv);
  std::string header;
  const auto rows = read_rows(csv, header);
  ASSERT_EQ(rows.size(), 51u);
  for (std::size_t k = 0; k < rows.size(); ++k)
    EXPECT_EQ(rows[k][0], static_cast<double>(k) * 0.01) << "row " << k;
  EXPECT_EQ(rows.back()[0], 0.5);
}

TEST(Run, FailureKeepsTheRowsWritten) {
  // A spin far too fast for the step: h|ω| ≥ 1 stops the run with ComputationFailed; both CSVs keep their
  // header and the initial row.
  Scenario sc;
  sc.system.add_body_from_inertia("a", 1.0, Vec3(1, 2, 3).asDiagonal());
  sc.initial.bodies.resize(1);
  sc.initial.bodies[0].omega_body = Vec3(0, 0, 20);
  sc.dt = 0.1;
  sc.duration = 1.0;
  const std::string csv = testing::TempDir() + "/fast.csv";
  const std::string diag_csv = testing::TempDir() + "/fast_diagnostics.csv";
  EXPECT_THROW(run_scenario(sc, nullptr, csv, diag_csv), ComputationFailed);
  std::ifstream in(csv);
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header.substr(0, 6), "t,a.x,");
  EXPECT_EQ(row.substr(0, 2), "0,");
  std::ifstream din(diag_csv);
  std::getline(din, header);
  std::getline(din, row);
  EXPECT_EQ(header.substr(0, 16), "t,energy,energy_");
  EXPECT_EQ(row.substr(0, 8), "0,600,0,");  // t = 0, E0 = ½ J₃ ω₃² = ½ · 3 · 20² J, E − E0 = 0
}

}  // namespace
}  // namespace poinsot::multibody
