// A multibody run into its files (io/run/multibody_run.hpp): the diagnostics against formulas written out for
// the rod, the reactions of a hanging chain against statics, the report, summary.json, a stop request and a
// failure.
#include "poinsot/io/run/multibody_run.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "../multibody/multibody_fixtures.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

namespace fs = std::filesystem;

fs::path multibody_run_temp_dir(const std::string& name) {
  const auto d = ::poinsot::test::temp_path("poinsot_io_multibody_run_" + name);
  fs::remove_all(d);
  return d;
}

/// The rows of a CSV file after its header, as numbers (the first `text_columns` fields skipped).
std::vector<std::vector<double>> read_rows(const fs::path& path, std::string& header, int text_columns = 0) {
  std::ifstream in(path);
  std::getline(in, header);
  std::vector<std::vector<double>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::istringstream fields(line);
    std::string f;
    for (int c = 0; std::getline(fields, f, ','); ++c)
      if (c == 0 || c > text_columns) row.push_back(std::stod(f));
    rows.push_back(row);
  }
  return rows;
}

/// examples/multibody/compound_pendulum.toml built directly: a rod (1 kg, 1 m, radius 1 cm, along body x)
/// hinged at one end about space y, released 0.3 rad from the vertical.
multibody::Scenario compound_pendulum() {
  const double m = 1, l = 1, r = 0.01, th = 0.3;
  multibody::Scenario sc;
  sc.system.add_body("rod", m, multibody::test::rod_poinsot(m, l, r));
  sc.system.set_gravity(Vec3(0, 0, -9.81));
  multibody::BodyState b;
  b.R_space_body = Eigen::AngleAxisd(std::numbers::pi / 2 + th, Vec3::UnitY()).toRotationMatrix();
  b.x_space = b.R_space_body * Vec3(l / 2, 0, 0);  // the pivot at the origin
  sc.initial.bodies.push_back(b);
  sc.system.add_hinge("pivot", 0, Vec3(-l / 2, 0, 0), Vec3::UnitY(), multibody::kWorld, Vec3::Zero(),
                      Vec3::UnitY());
  sc.dt = 1e-3;
  return sc;
}

TEST(MultibodyRun, DiagnosticsRowsAreTheObservablesOfTheTrajectoryRows) {
  // The compound pendulum pushed (ω projected onto the hinge's axis), 503 steps written every 7 (the
  // last row is the final step, not a multiple of 7). Each diagnostics row is checked against the trajectory
  // row of the same index, through formulas written out here for the rod (not the library's observables):
  // T = ½ m|v|² + ½ Σ J_k ω_k², V = m g z, p = m|v|, L = x × m v + R J ω, the gap |x + R (−l/2, 0, 0)| of the
  // pivot at the origin. v, ω and x are printed with 17 digits (exact round trip), so T and V agree to the
  // last bits (1e-14 relative: a sum of three terms); R comes back through the printed quaternion, off by
  // ~1e-16, which bounds the difference in L (~1e-15 kg·m²/s) and the gap (~1e-16 m): 1e-13 leaves margin.
  multibody::Scenario sc = compound_pendulum();
  sc.initial.bodies[0].omega_body = Vec3(0.4, 2.0, -0.3);
  multibody::project_velocities(sc.system, sc.initial);
  sc.duration = 0.503;
  sc.output_every = 7;
  MultibodyRunOptions o;
  o.trajectory_csv = (::poinsot::test::temp_path("poinsot_mb_diag_traj.csv")).string();
  o.diagnostics_csv = (::poinsot::test::temp_path("poinsot_mb_diag_diag.csv")).string();
  const MultibodyRunSummary s = run_multibody_scenario(sc, o);
  std::string traj_header, diag_header;
  const auto traj = read_rows(o.trajectory_csv, traj_header);
  const auto diag = read_rows(o.diagnostics_csv, diag_header);
  EXPECT_EQ(diag_header,
            "t,energy,energy_error,kinetic,potential,linear_momentum,L_space_x,L_space_y,L_space_z,joint_gap,"
            "joint_angle,orthogonality");
  EXPECT_EQ(traj_header.substr(0, 12), "t,rod.x,rod.");
  ASSERT_EQ(traj.size(), 1u + 503u / 7u + 1u);
  ASSERT_EQ(diag.size(), traj.size());
  EXPECT_EQ(s.rows, static_cast<long long>(traj.size()));
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
  EXPECT_LE(max_error, s.run.max_energy_error);
  EXPECT_GT(max_error, 0.0);
}

TEST(MultibodyRun, DiagnosticsEveryStepReachTheSummarysEnergyError) {
  // With a row every step, the column's largest |E − E0| is the summary's max_energy_error: the same doubles
  // (E = T + V, observables.cpp) printed with 17 digits, which round-trip exactly.
  multibody::Scenario sc = compound_pendulum();
  sc.duration = 0.2;
  sc.output_every = 1;
  MultibodyRunOptions o;
  o.diagnostics_csv = (::poinsot::test::temp_path("poinsot_mb_diag_every.csv")).string();
  const MultibodyRunSummary s = run_multibody_scenario(sc, o);
  std::string header;
  const auto diag = read_rows(o.diagnostics_csv, header);
  ASSERT_EQ(diag.size(), 201u);
  double max_error = 0;
  for (const auto& d : diag)
    max_error = std::max(max_error, std::abs(d[2]));
  EXPECT_GT(s.run.max_energy_error, 0.0);
  EXPECT_EQ(max_error, s.run.max_energy_error);
  EXPECT_DOUBLE_EQ(diag.back()[1], s.run.energy_final);
}

TEST(MultibodyRun, HangingChainReactionsCarryTheWeightBelow) {
  // Eight rods (1 kg, 1 m) hanging straight down at rest stay at rest; statics gives the reaction on link k
  // from the joint above it: the weight of links k..7, (8 − k) m g upwards (the pivot carries all 78.48 N).
  // The run moves nothing but round-off (1e-16 m/s per step), so 1e-9 relative is ample. The report shows the
  // 5 largest reactions and points to reactions.csv for all 8.
  const int n = 8;
  multibody::Scenario sc;
  sc.system = multibody::test::rod_chain(n);
  sc.initial = multibody::test::rod_chain_state(n);
  const Mat3 down = Eigen::AngleAxisd(std::numbers::pi / 2, Vec3::UnitY()).toRotationMatrix();  // x → −z
  for (int i = 0; i < n; ++i) {
    sc.initial.bodies[static_cast<std::size_t>(i)].R_space_body = down;
    sc.initial.bodies[static_cast<std::size_t>(i)].x_space = Vec3(0, 0, -(i + 0.5));
  }
  sc.source = "hanging.toml";
  sc.duration = 0.01;
  const auto dir = multibody_run_temp_dir("hanging");
  MultibodyRunOptions o;
  o.out_dir = dir.string();
  const MultibodyRunSummary s = run_multibody_scenario(sc, o);
  std::string header;
  const auto rows = read_rows(dir / "reactions.csv", header, 3);
  EXPECT_EQ(header, "t,joint,body_a,body_b,Fx,Fy,Fz,F_norm,Cx,Cy,Cz,C_norm");
  ASSERT_EQ(rows.size(), static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) {
    const auto& row = rows[static_cast<std::size_t>(k)];
    const double weight = (n - k) * 1.0 * multibody::test::kG;
    EXPECT_EQ(row[0], 0.01);
    EXPECT_NEAR(row[3], weight, 1e-9 * weight) << "joint " << k;  // Fz
    EXPECT_NEAR(row[4], weight, 1e-9 * weight);                   // |F|
    EXPECT_NEAR(row[1], 0.0, 1e-9 * weight);
  }
  const auto lambda_rows = read_rows(dir / "multipliers.csv", header, 1);
  EXPECT_EQ(header.substr(0, 25), "t,body,x,y,z,Lambda_xx,La");
  ASSERT_EQ(lambda_rows.size(), static_cast<std::size_t>(n));
  EXPECT_NEAR(lambda_rows[3][3], -3.5, 1e-9);  // link3's centre of mass, z (m)
  const std::string report = test::read_text(dir / "report.txt");
  EXPECT_NE(report.find("the 5 largest of 8 by |F|, all in " + (dir / "reactions.csv").string()),
            std::string::npos)
      << report;
  EXPECT_NE(report.find("'pivot'  'link0'  78.48"), std::string::npos) << report;
  EXPECT_NE(report.find("'j4'"), std::string::npos);
  EXPECT_EQ(report.find("'j5'"), std::string::npos);  // the sixth largest is only in the file
  EXPECT_EQ(report, format_multibody_report(sc, s));
  const auto j = nlohmann::json::parse(test::read_text(dir / "summary.json"));
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["files"]["reactions"], (dir / "reactions.csv").string());
  EXPECT_EQ(j["rows"], s.rows);
}

TEST(MultibodyRun, ReportNamesTheMethodTheBodiesAndTheJoints) {
  multibody::Scenario sc = compound_pendulum();
  sc.title = "compound pendulum of the test";
  sc.body_descriptions = {"solid cylinder along x"};
  sc.duration = 0.1;
  sc.method = multibody::MultibodyMethod::projected_rk4;
  sc.order = 4;
  const MultibodyRunSummary s = run_multibody_scenario(sc, {});
  const std::string report = format_multibody_report(sc, s);
  for (const char* part : {"multibody run: multibody\n", "  compound pendulum of the test\n",
                           "  body 'rod': solid cylinder along x\n",
                           "method: RK4 projected onto the joints (order 4, not symplectic)",
                           "projection iterations per step: mean", "joint reactions at t = 0.1 s",
                           "'pivot'  'rod'", "multipliers Λ at t = 0.1 s, body frame", "\ncost\n"}) {
    EXPECT_NE(report.find(part), std::string::npos) << part << "\n" << report;
  }
  EXPECT_EQ(report.find("\nfiles\n"), std::string::npos);  // nothing was written
}

TEST(MultibodyRun, StopRequestLeavesCompleteFilesAndAnInterruptedSummary) {
  // The stop is asked at the 4th row (t = 3 × 10 steps): every file ends at that row, summary.json says
  // interrupted, and the report says where.
  multibody::Scenario sc = compound_pendulum();
  const auto dir = multibody_run_temp_dir("stop");
  MultibodyRunOptions o;
  o.out_dir = dir.string();
  int rows = 0;
  o.stop_requested = [&] { return ++rows >= 4; };
  const MultibodyRunSummary s = run_multibody_scenario(sc, o);
  EXPECT_TRUE(s.run.interrupted);
  EXPECT_EQ(s.rows, 4);
  std::string header;
  const auto traj = read_rows(dir / "trajectory.csv", header);
  const auto diag = read_rows(dir / "diagnostics.csv", header);
  ASSERT_EQ(traj.size(), 4u);
  ASSERT_EQ(diag.size(), 4u);
  EXPECT_EQ(traj.back()[0], 0.03);
  const auto j = nlohmann::json::parse(test::read_text(dir / "summary.json"));
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_EQ(j["interrupted"], true);
  EXPECT_EQ(j["t_final"], 0.03);
  EXPECT_EQ(j["steps"], 30);
  EXPECT_NE(test::read_text(dir / "report.txt").find("INTERRUPTED at t = 0.03 s"), std::string::npos);
}

TEST(MultibodyRun, FailureKeepsTheRowsWrittenAndSaysFailed) {
  // A spin far too fast for the step: h|ω| ≥ 1 stops the run with ComputationFailed; both CSVs keep their
  // header and the initial row, summary.json says failed with the message, and no reactions are written.
  multibody::Scenario sc;
  sc.system.add_body_from_inertia("a", 1.0, Vec3(1, 2, 3).asDiagonal());
  sc.initial.bodies.resize(1);
  sc.initial.bodies[0].omega_body = Vec3(0, 0, 20);
  sc.dt = 0.1;
  sc.duration = 1.0;
  const auto dir = multibody_run_temp_dir("fast");
  MultibodyRunOptions o;
  o.out_dir = dir.string();
  EXPECT_THROW(run_multibody_scenario(sc, o), ComputationFailed);
  std::ifstream in(dir / "trajectory.csv");
  std::string header, row;
  std::getline(in, header);
  std::getline(in, row);
  EXPECT_EQ(header.substr(0, 6), "t,a.x,");
  EXPECT_EQ(row.substr(0, 2), "0,");
  std::ifstream din(dir / "diagnostics.csv");
  std::getline(din, header);
  std::getline(din, row);
  EXPECT_EQ(header.substr(0, 16), "t,energy,energy_");
  EXPECT_EQ(row.substr(0, 8), "0,600,0,");  // t = 0, E0 = ½ J₃ ω₃² = ½ · 3 · 20² J, E − E0 = 0
  const auto j = nlohmann::json::parse(test::read_text(dir / "summary.json"));
  EXPECT_EQ(j["status"], "failed");
  EXPECT_TRUE(j["failure"].is_string());
  EXPECT_TRUE(j["files"]["reactions"].is_null());
  EXPECT_FALSE(fs::exists(dir / "reactions.csv"));
  EXPECT_NE(test::read_text(dir / "report.txt").find("FAILED: "), std::string::npos);
}

TEST(MultibodyRun, UnwritableFolderIsRefusedBeforeTheFirstStep) {
  const auto dir = multibody_run_temp_dir("unwritable");
  fs::create_directories(dir);
  std::ofstream(dir / "file") << "x";
  MultibodyRunOptions o;
  o.out_dir = (dir / "file" / "run").string();
  EXPECT_THROW(run_multibody_scenario(compound_pendulum(), o), InvalidInput);
}

}  // namespace
}  // namespace poinsot::io
