// The multibody scenario keys of the rotation-matrix transcription's options and of minimum time: a rod on a
// ball joint with the no-twist condition, bounded stabilising variables and a mesh sequence, read from a file
// and solved, against the same problem built and solved in C++ and against the closed form; a minimum-time
// file against the bang-bang time; bad values as one located line.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <utility>

#include <Eigen/Geometry>

#include "../../optimal/multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/io/run/multibody_optimal_run.hpp"
#include "poinsot/io/scenario/multibody_optimal_scenario.hpp"

namespace poinsot::io {
namespace {

// One rod (1 kg, 1 m, radius 5 cm, along body x) on a ball joint with three motors at its end, no gravity,
// turned from rest at 0 to rest at 1.2 rad about z in 2 s. The turn is a bend about z (no twist about the
// rod's axis x), so the no-twist condition holds along the planar optimum, whose cost is the hinge's closed
// form 12 I² Θ² / T³ (I = J_zz + m (ℓ/2)²).
std::string ball_rod(const std::string& options) {
  return "[[bodies]]\nname = \"rod\"\nmass = 1.0\nshape = { type = \"rod\", length = 1.0, radius = 0.05 }\n"
         "position = [0.5, 0, 0]\n"
         "[[joints]]\nname = \"shoulder\"\ntype = \"ball\"\nbody_a = \"rod\"\npoint_a = [-0.5, 0, 0]\n"
         "[optimal_control]\nfinal_time = 2.0\ncoordinates = \"rotation_matrix\"\nintervals = 8\n"
         "actuators = [{ joint = \"shoulder\", torque_max = 50 }]\n" +
         options +
         "\n[[optimal_control.final]]\nbody = \"rod\"\nrotation = { axis = [0, 0, 1], angle = 1.2 }\n";
}
const std::string kBallRodOptions =
    "stabilisation_step = 0.3\nwarm_start = [4]\n"
    "no_twist = [{ joint = \"shoulder\", axis_a = [1, 0, 0], rotation = { axis = [0, 0, 1], angle = 0 } }]";

optimal::MultibodyProblem ball_rod_in_code(int intervals) {
  optimal::MultibodyProblem p;
  const int rod = p.system.add_body_from_inertia("rod", 1.0, optimal::testing::rod_inertia(1.0, 1.0, 0.05));
  const int ball = p.system.add_ball("shoulder", rod, Vec3(-0.5, 0, 0), multibody::kWorld, Vec3::Zero());
  p.initial_state.bodies.resize(1);
  p.initial_state.bodies[0].x_space = Vec3(0.5, 0, 0);
  p.final_state.bodies.resize(1);
  const Mat3 R = Eigen::AngleAxisd(1.2, Vec3::UnitZ()).toRotationMatrix();
  p.final_state.bodies[0].R_space_body = R;
  p.final_state.bodies[0].x_space = R * Vec3(0.5, 0, 0);
  p.final_time = 2.0;
  p.intervals = intervals;
  p.actuators = {{optimal::ActuatorKind::ball_torque, ball, 50.0}};
  p.no_twist = {{ball, Vec3::UnitX(), Mat3::Identity()}};
  return p;
}

TEST(MultibodyOptimalOptions, FileWithTheKeysGivesTheOptimumOfTheCppCall) {
  const MultibodyOptimalScenario sc =
      parse_multibody_optimal_scenario(ball_rod(kBallRodOptions), "<string>", "");
  EXPECT_EQ(sc.options.stabilisation_step, 0.3);
  ASSERT_EQ(sc.mesh_sequence, std::vector<int>{4});
  ASSERT_EQ(sc.problem.no_twist.size(), 1u);
  EXPECT_EQ(sc.problem.actuators[0].kind, optimal::ActuatorKind::ball_torque);
  const MultibodyOptimalRun run = run_multibody_optimal(sc);
  ASSERT_TRUE(run.optimal) << run.status;
  ASSERT_EQ(run.mesh_stages.size(), 1u);
  EXPECT_EQ(run.mesh_stages[0].intervals, 4);

  // The same problem and options in C++: 4 intervals from the naive guess, then 8 from that optimum.
  optimal::MultibodyOptions o;
  o.stabilisation_step = 0.3;
  const optimal::MultibodyOptimum coarse = optimal::solve_multibody(ball_rod_in_code(4), o);
  o.warm_start = &coarse;
  const optimal::MultibodyProblem p = ball_rod_in_code(8);
  const optimal::MultibodyOptimum r = optimal::solve_multibody(p, o);
  ASSERT_TRUE(r.converged) << r.status;
  // The file's rod inertia is computed by the shape reader, the code's by rod_inertia: equal to round-off,
  // so the two solves follow the same Ipopt path to the same point (measured agreement ~1e-15).
  EXPECT_NEAR(run.optimum.cost, r.cost, 1e-10 * r.cost);
  EXPECT_EQ(run.mesh_stages[0].nlp_iterations, coarse.nlp_iterations);
  EXPECT_EQ(run.optimum.nlp_iterations, r.nlp_iterations);
  for (std::size_t k = 0; k < r.states.size(); ++k) {
    EXPECT_LT((run.optimum.states[k].bodies[0].R_space_body - r.states[k].bodies[0].R_space_body).norm(),
              1e-9);
    EXPECT_LT(std::abs(optimal::twist_residual(p.system, r.states[k], p.no_twist[0])), 1e-9) << k;
  }
  // The closed form of the planar turn: R-coordinates' Hermite–Simpson error at N = 8 (2e-5 relative for
  // the hinge, docs/optimal_control_multibody.md), well inside 1e-4.
  const double I = optimal::testing::single_hinge_inertia();
  EXPECT_NEAR(r.cost, 12.0 * I * I * 1.44 / 8.0, 1e-4 * r.cost);
  // The report and summary.json name the options.
  const std::string report = multibody_optimal_report(run);
  EXPECT_NE(report.find("no twist: ball joint shoulder"), std::string::npos) << report;
  EXPECT_NE(report.find("stabilising variables bounded by c/h, c = 0.3"), std::string::npos) << report;
  EXPECT_NE(report.find("warm start: 4 intervals, converged"), std::string::npos) << report;
  const std::string summary = multibody_optimal_summary_json(run);
  for (const char* key : {"\"no_twist\"", "\"stabilisation_step\": 0.3", "\"mesh_sequence\""})
    EXPECT_NE(summary.find(key), std::string::npos) << key;
}

// The progress of a run with a mesh sequence: every Ipopt iteration of each mesh in order (the mesh's place
// and intervals, the iterations counting up to the mesh's own count), then the re-simulation; the result is
// the same bit for bit without it.
TEST(MultibodyOptimalOptions, ProgressFollowsTheMeshSequence) {
  const MultibodyOptimalScenario sc =
      parse_multibody_optimal_scenario(ball_rod(kBallRodOptions), "<string>", "");
  std::vector<OptimalProgress> seen;
  const MultibodyOptimalRun run =
      run_multibody_optimal(sc, [&](const OptimalProgress& p) { seen.push_back(p); });
  ASSERT_TRUE(run.optimal) << run.status;
  ASSERT_FALSE(seen.empty());
  EXPECT_EQ(seen.back().phase, "replay");
  std::vector<int> last_iteration(2, -1);
  for (std::size_t k = 0; k + 1 < seen.size(); ++k) {
    const OptimalProgress& p = seen[k];
    ASSERT_EQ(p.phase, "direct") << k;
    ASSERT_TRUE(p.direct.mesh_iteration == 1 || p.direct.mesh_iteration == 2) << k;
    if (k > 0) {
      EXPECT_GE(p.direct.mesh_iteration, seen[k - 1].direct.mesh_iteration) << k;
    }
    EXPECT_EQ(p.direct.intervals, p.direct.mesh_iteration == 1 ? 4 : 8) << k;
    int& last = last_iteration[static_cast<std::size_t>(p.direct.mesh_iteration - 1)];
    EXPECT_EQ(p.direct.nlp_iteration, last + 1) << k;
    last = p.direct.nlp_iteration;
  }
  EXPECT_EQ(last_iteration[0], run.mesh_stages[0].nlp_iterations);
  EXPECT_EQ(last_iteration[1], run.optimum.nlp_iterations);
  const MultibodyOptimalRun plain = run_multibody_optimal(sc);
  EXPECT_EQ(plain.optimum.cost, run.optimum.cost);
  EXPECT_EQ(multibody_optimal_summary_json(plain), multibody_optimal_summary_json(run));
}

// The rod on a hinge with |u| ≤ 1 N·m, turned through 1 rad in minimum time: T* = 2 √(Θ I / ū).
std::string hinge_rod(const std::string& options) {
  return "[[bodies]]\nname = \"rod\"\nmass = 1.0\nshape = { type = \"rod\", length = 1.0, radius = 0.05 }\n"
         "position = [0.5, 0, 0]\n"
         "[[joints]]\nname = \"motor\"\ntype = \"hinge\"\nbody_a = \"rod\"\npoint_a = [-0.5, 0, 0]\n"
         "axis_a = [0, 0, 1]\n"
         "[optimal_control]\nfinal_time = 2.0\ncoordinates = \"minimal\"\nintervals = 15\n"
         "actuators = [{ joint = \"motor\", torque_max = 1 }]\n" +
         options +
         "\n[[optimal_control.final]]\nbody = \"rod\"\nrotation = { axis = [0, 0, 1], angle = 1.0 }\n";
}

TEST(MultibodyOptimalOptions, MinimumTimeFileMeetsTheBangBangTime) {
  const MultibodyOptimalScenario sc = parse_multibody_optimal_scenario(
      hinge_rod("objective = \"minimum_time\"\nfinal_time_bounds = [0.5, 5]"), "<string>", "");
  EXPECT_EQ(sc.problem.objective, optimal::MultibodyObjective::minimum_time);
  const MultibodyOptimalRun run = run_multibody_optimal(sc);
  ASSERT_TRUE(run.optimal) << run.status;
  // The odd mesh blurs the switch by about 0.19/N² s (test_multibody_minimum_time.cpp): 8.6e-4 s at N = 15.
  const double T_star = 2.0 * std::sqrt(optimal::testing::single_hinge_inertia());
  EXPECT_GT(run.optimum.time.back() - T_star, 0.1 / 225);
  EXPECT_LT(run.optimum.time.back() - T_star, 0.3 / 225);
  EXPECT_NE(multibody_optimal_report(run).find("objective: minimum_time (T), T free in [0.5, 5] s"),
            std::string::npos);
  EXPECT_NE(multibody_optimal_summary_json(run).find("\"objective\": \"minimum_time\""), std::string::npos);
}

TEST(MultibodyOptimalOptions, FallingCatExampleIsTheCatOfTheTests) {
  // examples/optimal/falling_cat.toml (solved by tests/cli/test_cli_optimize_multibody.py): the cat of the
  // optimal/ tests, its three motors in the waist, the bound c and the mesh sequence.
  const MultibodyOptimalScenario sc =
      load_multibody_optimal_scenario(std::string(POINSOT_SOURCE_DIR) + "/examples/optimal/falling_cat.toml");
  const optimal::MultibodyProblem cat = optimal::testing::falling_cat(0.5, std::numbers::pi, 1.0, 12);
  for (const auto& [file, code] : {std::pair{&sc.problem.initial_state, &cat.initial_state},
                                   std::pair{&sc.problem.final_state, &cat.final_state}}) {
    for (std::size_t i = 0; i < 2; ++i) {
      // The file gives the rotations and positions to 17 digits: round-off.
      EXPECT_LT((file->bodies[i].R_space_body - code->bodies[i].R_space_body).norm(), 1e-15) << i;
      EXPECT_LT((file->bodies[i].x_space - code->bodies[i].x_space).norm(), 1e-15) << i;
    }
  }
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT((sc.problem.system.bodies()[i].inertia - cat.system.bodies()[i].inertia).norm(), 1e-15);
  }
  ASSERT_EQ(sc.problem.actuators.size(), 1u);
  EXPECT_EQ(sc.problem.actuators[0].kind, optimal::ActuatorKind::ball_torque);
  EXPECT_EQ(sc.problem.intervals, 12);
  EXPECT_EQ(sc.mesh_sequence, std::vector<int>{6});
  EXPECT_EQ(sc.options.stabilisation_step, optimal::testing::kCatStabilisationStep);
}

void expect_bad_option(const std::string& text, const std::string& fragment) {
  try {
    parse_multibody_optimal_scenario(text, "s.toml", "");
    ADD_FAILURE() << "expected InvalidInput containing " << fragment;
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
    EXPECT_EQ(msg.find('\n'), std::string::npos) << msg;
    EXPECT_EQ(msg.rfind("s.toml:", 0), 0u) << msg;
  }
}

TEST(MultibodyOptimalOptions, BadValuesAreOneLocatedLine) {
  expect_bad_option(ball_rod("stabilisation_step = 0.7"),
                    "stabilisation_step: got 0.7; expected a number from 0 to 0.6");
  expect_bad_option(ball_rod("stabilisation_step = -0.1"), "stabilisation_step: got -0.1");
  expect_bad_option(hinge_rod("stabilisation_step = 0.1"),
                    "stabilisation_step: got 0.1 with minimal coordinates");
  expect_bad_option(ball_rod("warm_start = [8]"),
                    "warm_start: got [8]; expected increasing whole numbers of intervals "
                    "from 2 to intervals − 1 = 7");
  expect_bad_option(ball_rod("warm_start = [4, 3]"), "warm_start: got [4, 3]");
  expect_bad_option(ball_rod("warm_start = \"coarse\""),
                    "[optimal_control] warm_start: got \"coarse\", expected an array of whole numbers");
  expect_bad_option(ball_rod("warm_start = [2.5]"),
                    "warm_start: got [2.5], expected an array of whole numbers");
  expect_bad_option(
      ball_rod("no_twist = [{ joint = \"elbow\", axis_a = [1, 0, 0] }]"),
      "[optimal_control.no_twist[0]] joint: got \"elbow\", expected the name of a ball joint (\"shoulder\")");
  expect_bad_option(ball_rod("no_twist = [{ joint = \"shoulder\" }]"),
                    "[optimal_control.no_twist[0]] axis_a: missing");
  expect_bad_option(ball_rod("no_twist = [{ joint = \"shoulder\", axis_a = [1, 1, 0] }]"),
                    "no_twist[0]: axis_a: got norm 1.41");
  expect_bad_option(ball_rod("no_twist = [{ joint = \"shoulder\", axis_a = [0, 0, 1] }]"),
                    "no_twist[0]: the final state has the twist");
  expect_bad_option(ball_rod("no_twist = [{ joint = \"shoulder\", axis_a = [1, 0, 0], spin = 1 }]"),
                    "unknown key \"spin\"");
  expect_bad_option(hinge_rod("objective = \"minimum_time\""),
                    "[optimal_control] final_time_bounds: missing");
  expect_bad_option(hinge_rod("objective = \"minimum_time\"\nfinal_time_bounds = [3, 5]"),
                    "final_time: got the bounds [3, 5] s and the guess 2 s");
  expect_bad_option(hinge_rod("objective = \"minimum_time\"\nfinal_time_bounds = [0.5]"),
                    "final_time_bounds: got [0.5], expected an array of 2 numbers");
  expect_bad_option(
      hinge_rod("objective = \"minimum_time\"\nfinal_time_bounds = [0.5, 5]\nenergy_weight = 1"),
      "energy_weight: given with objective = \"minimum_time\"");
  expect_bad_option(hinge_rod("objective = \"minimum_time_regularised\"\nfinal_time_bounds = [0.5, 5]"),
                    "energy_weight: missing");
  expect_bad_option(hinge_rod("final_time_bounds = [0.5, 5]"),
                    "final_time_bounds: given with objective = \"minimum_energy\"");
}

}  // namespace
}  // namespace poinsot::io
