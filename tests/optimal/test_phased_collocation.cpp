// The phase-per-arc re-solve of minimum-time problems: every switch on a mesh node, t* and the switch times
// converging at the method's order h⁴, and meeting the indirect (shooting) optimum.
#include "poinsot/optimal/phased_collocation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

double max_switch_gap(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double gap = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
    gap = std::max(gap, std::abs(a[k] - b[k]));
  return gap;
}

PhasedSolution solve_phased(const ReorientationProblem& p, const DirectSolution& d,
                            const SwitchingStructure& s, int intervals_per_arc) {
  PhasedOptions o;
  o.intervals_per_arc = intervals_per_arc;
  PhasedSolution r = solve_direct_phased(p, d, s, o);
  EXPECT_TRUE(r.converged) << r.status;
  return r;
}

// Betts' spacecraft: with one phase per bang arc the controls are fixed, every switch is a node, and the
// transcription integrates smooth arcs, so the error in t* falls as h⁴ (measured 16.0 per halving: 4.4e-8,
// 2.8e-9, 1.7e-10, 1.1e-11 relative at 8, 16, 32, 64 intervals per arc). At 64 intervals per arc t* meets the
// indirect optimum (RKF78 at 1e-13, Newton at 1e-12) to 1e-10 and the switches to 1e-8 s (measured 8.6e-10
// s).
TEST(PhasedCollocation, BettsMeetsTheIndirectOptimumAtFourthOrder) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "about 2 s in release, minutes under ASan; the sphere slew below covers the code";
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-5;
  const auto p = testing::betts_problem();
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;

  const SwitchingStructure st = read_switching_structure(p, d);
  ASSERT_EQ(st.switch_times.size(), 5u);
  const PhasedSolution coarse = solve_phased(p, d, st, 8), fine = solve_phased(p, d, st, 16);
  const double e8 = std::abs(coarse.solution.final_time - s.final_time);
  const double e16 = std::abs(fine.solution.final_time - s.final_time);
  EXPECT_GT(e8 / e16, 12.0);  // h⁴: 16, not the h² of a blurred switch
  EXPECT_LT(e8 / e16, 20.0);

  const PhasedSolution r = solve_phased(p, d, st, 64);
  EXPECT_NEAR(r.solution.final_time / s.final_time, 1.0, 1e-10);
  EXPECT_NEAR(r.solution.final_time / testing::kBettsPublishedTime, 1.0, 5e-8);
  EXPECT_LT(max_switch_gap(r.switch_times, s.switch_times), 1e-8);
  // Every switch is a node: the torque jumps there, between the two copies of the node.
  EXPECT_LT(r.solution.max_mesh_error, 1e-9);

  // The same structure read from the indirect solution gives the same discrete optimum.
  const SwitchingStructure from_indirect = read_switching_structure(p, s);
  ASSERT_EQ(from_indirect.torque_lower.size(), st.torque_lower.size());
  for (std::size_t a = 0; a < st.torque_lower.size(); ++a)
    EXPECT_EQ(from_indirect.torque_lower[a], st.torque_lower[a]) << a;
  const PhasedSolution again = solve_phased(p, d, from_indirect, 8);
  EXPECT_NEAR(again.solution.final_time, coarse.solution.final_time, 1e-12 * s.final_time);
}

// The norm-bound sphere (J = j I, ‖u‖ ≤ ū, rest to rest through Θ about x): the eigenaxis slew, T =
// 2√(Θ j/ū) with the reversal at T/2 exactly. Two phases, u = ±ū x fixed: t* to h⁴ (measured 1.6e-6,
// 1.0e-7, 6.4e-9, 4.0e-10, 2.3e-11 relative at 4 … 64 intervals per arc) and the reversal to 4.9e-11 s at 64.
TEST(PhasedCollocation, NormBoundSphereReversalOnANode) {
  const double j = 1.5, ubar = 0.8, theta = 2.5;
  ReorientationProblem p;
  p.inertia_body = j * Mat3::Identity();
  p.bound = TorqueBound::norm;
  p.torque_max = Vec3::Constant(ubar);
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, Vec3::UnitX()));
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-6;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  const double T = 2.0 * std::sqrt(theta * j / ubar);

  const SwitchingStructure st = read_switching_structure(p, d);
  ASSERT_EQ(st.switch_times.size(), 1u);
  EXPECT_EQ(st.torque_lower[0], Vec3(ubar, 0.0, 0.0));
  EXPECT_EQ(st.torque_upper[1], Vec3(-ubar, 0.0, 0.0));
  const PhasedSolution coarse = solve_phased(p, d, st, 4), fine = solve_phased(p, d, st, 8);
  const double ratio = (coarse.solution.final_time - T) / (fine.solution.final_time - T);
  EXPECT_GT(ratio, 12.0);
  EXPECT_LT(ratio, 20.0);
  if (::poinsot::test::sanitized()) return;  // the re-solves below take minutes under ASan
  const PhasedSolution r = solve_phased(p, d, st, 64);
  EXPECT_NEAR(r.solution.final_time / T, 1.0, 1e-10);
  ASSERT_EQ(r.switch_times.size(), 1u);
  EXPECT_NEAR(r.switch_times[0], T / 2, 1e-8);
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  EXPECT_NEAR(r.solution.final_time / s.final_time, 1.0, 1e-10);
  EXPECT_LT(max_switch_gap(r.switch_times, s.switch_times), 1e-8);
}

TEST(PhasedCollocation, RefusesBadInput) {
  ReorientationProblem p;
  p.attitude_final = Quat(0.0, 1.0, 0.0, 0.0);
  DirectSolution d;
  d.final_time = 3.0;
  d.time = {0.0, 1.5, 3.0};
  d.attitude = {Quat::Identity(), Quat(Eigen::AngleAxisd(1.5, Vec3::UnitX())), Quat(0.0, 1.0, 0.0, 0.0)};
  d.omega_body.assign(3, Vec3::Zero());
  d.torque_body.assign(3, Vec3::Ones());
  SwitchingStructure s;
  s.switch_times = {1.0};
  s.torque_lower = s.torque_upper = {Vec3::Ones(), -Vec3::Ones()};
  EXPECT_NO_THROW(read_switching_structure(p, d));

  const auto message = [&](const ReorientationProblem& q, const SwitchingStructure& st, PhasedOptions o) {
    try {
      solve_direct_phased(q, d, st, o);
    } catch (const InvalidInput& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  SwitchingStructure wrong = s;
  wrong.torque_upper.pop_back();
  EXPECT_NE(message(p, wrong, {}).find("torque_lower/upper"), std::string::npos);
  wrong = s;
  wrong.switch_times = {3.5};
  EXPECT_NE(message(p, wrong, {}).find("switch_times[0] = 3.5"), std::string::npos);
  PhasedOptions o;
  o.intervals_per_arc = 0;
  EXPECT_NE(message(p, s, o).find("intervals_per_arc = 0"), std::string::npos);
  ReorientationProblem energy = p;
  energy.objective = Objective::minimum_energy;
  energy.final_time = 10.0;
  EXPECT_NE(message(energy, s, {}).find("expected minimum_time"), std::string::npos);
  EXPECT_THROW(read_switching_structure(energy, d), InvalidInput);
  EXPECT_THROW(read_switching_structure(p, IndirectSolution{}), InvalidInput);
}

}  // namespace
}  // namespace poinsot::optimal
