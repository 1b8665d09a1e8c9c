// Torque tables ([torque] type = "table"): the format and its errors, and the replay by `poinsot run`'s
// scenario of the control.csv that `poinsot optimize` writes: Betts' minimum-time optimum, integrated by
// integrators other than the verification's arc-by-arc DOP853, reaches the target attitude and rest.
#include "poinsot/io/scenario/torque_table.hpp"

#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/io/run/optimal_run.hpp"
#include "poinsot/io/scenario/optimal_scenario.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

TEST(TorqueTable, ParsesCommentsHeaderAndRows) {
  const auto tau = parse_torque_table(
      "# status: optimal (verified)\nt,ux,uy,uz\n0,1,2,3\n\n1.5,1,2,3\n1.5,-1,0,0\n2,-1,0,0\n", "c.csv");
  EXPECT_EQ(tau->time(), (std::vector<double>{0.0, 1.5, 1.5, 2.0}));
  EXPECT_EQ(tau->torque_rows()[2], Vec3(-1, 0, 0));
  EXPECT_EQ(tau->torque_body(1.0, Mat3::Identity(), Vec3::Zero()), Vec3(1, 2, 3));
  // Extra columns are ignored, spaces and CRLF line ends accepted.
  EXPECT_EQ(
      parse_torque_table("t, ux, uy, uz, note\r\n0, 1, 0, 0, 7\r\n1, 1, 0, 0, 8\r\n", "x")->time().size(),
      2u);
}

TEST(TorqueTable, RejectsMalformedTablesInOneLine) {
  for (const auto& [text, what] : {std::pair{"", "no header"}, std::pair{"t,ux,uy\n0,1,2\n", "header"},
                                   std::pair{"t,ux,uy,uz\n0,1,2\n1,1,2,3\n", "line 2: 3 values"},
                                   std::pair{"t,ux,uy,uz\n0,1,2,x\n1,1,2,3\n", "uz = \"x\""},
                                   std::pair{"t,ux,uy,uz\n0,1,2,3\n", "at least two rows"},
                                   std::pair{"t,ux,uy,uz\n1,1,2,3\n0,1,2,3\n", "ascending"}}) {
    try {
      parse_torque_table(text, "c.csv");
      ADD_FAILURE() << what;
    } catch (const InvalidInput& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_NE(m.find("c.csv"), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
  EXPECT_THROW(read_torque_table("/nonexistent/control.csv"), InvalidInput);
}

TEST(TorqueTable, ScenarioTypeTableNeedsFileAndTakesInterpolation) {
  const std::string body =
      "[body]\nprincipal_moments = [1, 2, 3]\n[initial]\nomega_body = [0, 0, 0]\n"
      "[output]\nt_end = 1.0\n";
  EXPECT_THROW(parse_scenario(body + "[torque]\ntype = \"table\"\n", "s.toml", ""), InvalidInput);
  EXPECT_THROW(
      parse_scenario(body + "[torque]\ntype = \"body\"\nvalue = [0, 0, 1]\nfile = \"c.csv\"\n", "s.toml", ""),
      InvalidInput);
  try {
    parse_scenario(body + "[torque]\ntype = \"table\"\nfile = \"missing.csv\"\n", "s.toml", "/nonexistent");
    ADD_FAILURE();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/missing.csv"), std::string::npos) << e.what();
  }
  // interpolation: "linear" (default) or "cubic", with type = "table" only; one line naming the key.
  const auto dir = ::poinsot::test::temp_path("poinsot_test_torque_table_interpolation");
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "c.csv") << "t,ux,uy,uz\n0,0,0,0\n1,1,0,0\n2,1,0,0\n3,0,0,0\n";
  const std::string table = body + "[torque]\ntype = \"table\"\nfile = \"c.csv\"\n";
  EXPECT_NE(parse_scenario(table, "s.toml", dir.string()).torque->describe().find("linear"),
            std::string::npos);
  EXPECT_NE(parse_scenario(table + "interpolation = \"cubic\"\n", "s.toml", dir.string())
                .torque->describe()
                .find("cubic"),
            std::string::npos);
  for (const std::string& bad :
       {table + "interpolation = \"spline\"\n",
        body + "[torque]\ntype = \"body\"\nvalue = [0, 0, 1]\ninterpolation = \"cubic\"\n"}) {
    try {
      parse_scenario(bad, "s.toml", dir.string());
      ADD_FAILURE() << bad;
    } catch (const InvalidInput& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("interpolation"), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  }
}

TEST(TorqueTable, ReplayOfBettsOptimumReachesTheTarget) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "0.6 s in release (the optimisation), far longer under ASan; the sphere replays of "
                    "tests/dynamics/test_tabulated_torque.cpp cover the same code there";
  OptimalScenario osc =
      load_optimal_scenario(std::string(POINSOT_SOURCE_DIR) + "/examples/optimal/betts.toml");
  // A coarse mesh is enough to seed the shooting, whose switch times are exact whatever the mesh (fast test).
  osc.collocation.mesh_tolerance = 1e-4;
  const OptimalRun run = run_optimal(osc);
  ASSERT_TRUE(run.optimal) << run.status;
  const auto dir = ::poinsot::test::temp_path("poinsot_test_torque_table");
  write_optimal_files(run, dir.string());
  const double T = run.indirect.final_time;
  const std::string text =
      "[body]\nprincipal_moments = [5621.0, 4547.0, 2364.0]\n[initial]\n"
      "omega_body = [0, 0, 0]\n[torque]\ntype = \"table\"\nfile = \"control.csv\"\n"
      "[output]\nt_end = " +
      std::to_string(T + 2.0) + "\n";
  const Scenario sc = parse_scenario(text, "replay.toml", dir.string());
  EXPECT_NE(sc.torque->describe().find("12 rows"), std::string::npos) << sc.torque->describe();
  const Mat3 target = osc.problem.attitude_final.toRotationMatrix();
  // Two seconds past T the body is still at rest at the target (τ = 0 after the table). Tolerances: the
  // adaptive methods at rtol = atol = 1e-13 over ~30 s and six arcs, each switch a breakpoint of the driver
  // (measured: dop853 4e-11 rad, dopri5 4e-10 rad); rk4 at dt = 0.01 s, O(h⁴) with ‖ω̇‖ ≤ 0.02 rad/s²
  // (measured 7e-14 rad; 7e-10 rad at dt = 0.1 s).
  for (const auto& [method, dt, tol] :
       {std::tuple{"dop853", 0.5, 1e-9}, std::tuple{"dopri5", 0.5, 1e-9}, std::tuple{"rk4", 0.01, 1e-9}}) {
    dynamics::IntegratorOptions opt;
    opt.dt = dt;
    opt.rtol = opt.atol = 1e-13;
    auto integrator = dynamics::make_integrator(method, sc.body, sc.torque, opt);
    dynamics::SimulationOptions so;
    so.t_end = T + 2.0;
    so.sample_dt = 1.0;
    const dynamics::State end =
        dynamics::simulate(sc.body, sc.torque, sc.initial, *integrator, so).final_state;
    EXPECT_LT(so3::angle_between(end.R_space_body, target), tol) << method;
    EXPECT_LT(end.omega_body.norm(), tol * 0.1) << method;
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace poinsot::io
