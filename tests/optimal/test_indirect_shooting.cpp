#include "poinsot/optimal/indirect_shooting.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "optimal_test_problems.hpp"
#include "poinsot/optimal/interpretation.hpp"
#include "poinsot/optimal/phased_collocation.hpp"
#include "poinsot/optimal/verification.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

// Betts' spacecraft, direct → indirect → verification. The shooting solution is exact up to the RKF78
// tolerance (1e-13) and the Newton tolerance (1e-12), so t* must match the published 8 digits (28.6304077,
// ±5e-8 in its last digit) to 5e-8 relative; the switching times are checked against the symmetry of the
// problem (none) and against the switching functions (σ_i(t_s) = 0 is a Newton equation).
TEST(IndirectShooting, BettsMinimumTimeMatchesThePublishedOptimum) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "about 4 s in release, minutes under ASan; the sanitizer build runs the smaller slews below";
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-5;  // enough for the switching structure and the costates the shooting needs
  const auto p = testing::betts_problem();
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  // Hermite–Simpson blurs the switches: t* to about 6.5e-5 at this mesh tolerance (73 intervals at 1e-6:
  // 9e-6).
  EXPECT_NEAR(d.final_time / testing::kBettsPublishedTime, 1.0, 1e-4);
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  EXPECT_NEAR(s.final_time / testing::kBettsPublishedTime, 1.0, 5e-8);
  ASSERT_EQ(s.switch_times.size(), 5u);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_LT(v.resimulated_attitude_error, 1e-9);
  // The rate bound 0.5 rad/s is not active at the optimum (peak |ω_i| ≈ 0.19 rad/s).
  double peak = 0.0;
  for (const auto& w : s.omega_body)
    peak = std::max(peak, w.cwiseAbs().maxCoeff());
  EXPECT_LT(peak, 0.4);
  // Beside the eigenaxis manoeuvre about the principal x axis, 2√(Θ J_1/u_1) = 34.311 s: 16.6 % saved.
  const ManoeuvreInterpretation m = interpret(p, s);
  ASSERT_TRUE(m.eigenaxis_available);
  EXPECT_NEAR(m.eigenaxis_cost, 2.0 * std::sqrt(150.0 * std::numbers::pi / 180.0 * 5621.0 / 50.0), 1e-12);
  EXPECT_NEAR(m.saving, 1.0 - s.final_time / m.eigenaxis_cost, 1e-15);
  EXPECT_GT(m.saving, 0.16);
}

// Bilimoria & Wie (1993): the 180° rest-to-rest slew of J = I about x with |u_i| ≤ 1 is faster than the
// eigenaxis manoeuvre 2√(Θ j/u) = 2√π. The optimum found here (T* = 3.2430832774 s, five switches) is
// symmetric in time: t_s + t_{6−s} = T*, a property the solver is not told.
TEST(IndirectShooting, PerAxisSphereSlewBeatsTheEigenaxisManoeuvre) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "about 1 s in release, a minute under ASan; the Betts and sphere-energy cases cover the code";
  ReorientationProblem p;
  p.attitude_final = Quat(0.0, 1.0, 0.0, 0.0);
  CollocationOptions opt;
  opt.initial_intervals = 20;
  opt.mesh_tolerance = 1e-6;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const double eigenaxis = 2.0 * std::sqrt(std::numbers::pi);
  EXPECT_LT(s.final_time, 0.92 * eigenaxis);
  EXPECT_NEAR(s.final_time, 3.2430832774, 1e-9);
  EXPECT_NEAR(d.final_time / s.final_time, 1.0, 1e-5);
  ASSERT_EQ(s.switch_times.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k)
    EXPECT_NEAR(s.switch_times[k] + s.switch_times[4 - k], s.final_time, 1e-9);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
}

// The sphere at minimum energy: the indirect solution is the eigenaxis cubic, cost 12 j²Θ²/T³, to the
// shooting tolerance.
TEST(IndirectShooting, SphereMinimumEnergyCost) {
  const double j = 2.5, theta = 2.0, T = 3.0;
  const auto p = testing::sphere_energy_problem(j, theta, Vec3(1.0, -2.0, 0.5), T);
  const DirectSolution d = testing::sphere_direct_seed(p);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  EXPECT_NEAR(s.cost / (12.0 * j * j * theta * theta / (T * T * T)), 1.0, 1e-11);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
}

// A minimum-energy slew of an asymmetric body (moments 4.63, 13.40, 12.48 kg·m²) by 177° in 15.4 s, problem
// 13 of seed 2 of the benchmark's energy family: the torque −σ/2 is smooth, and its DOP853 replay from the
// samples (a local cubic between them) must reach the target far inside the threshold of 1e-6 rad. With 64
// uniform samples (0.24 s apart) the replay missed by 1.5e-6 rad and the extremal, converged to 1e-12, was
// not verified; the samples are now halved until their second difference is below 1e-5 of the torque's
// largest norm, and the miss is 4.4e-10 rad (amplification 2): a tenth of the threshold is required. Oracles:
// the minimum principle's checks, the direct optimum's cost (1e-3), the independent replay.
TEST(IndirectShooting, MinimumEnergySamplesResolveTheTorqueForItsReplay) {
  ReorientationProblem p;
  p.inertia_body = Vec3(4.632836403703844, 13.398713278902793, 12.4839605668905).asDiagonal();
  p.objective = Objective::minimum_energy;
  p.bound = TorqueBound::norm;
  p.torque_max = Vec3::Constant(1.993595586886461);
  p.final_time = 15.418043392394674;
  p.attitude_final = Quat(Eigen::AngleAxisd(
      3.096949852109522, Vec3(0.5206724398501528, -0.8512217903502655, -0.06573944031841092).normalized()));
  const DirectSolution d = solve_direct(p, {});
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_LT(v.resimulated_attitude_error, 1e-7);
  EXPECT_LT(v.resimulated_rate_error, 1e-7);
}

// The Newton progress callback: called once per iteration (single shooting: as many times as the solution's
// iteration count) with the accepted residual, which only decreases and ends at the solution's; the solution
// is the same bit for bit without it.
TEST(IndirectShooting, NewtonProgressReportsEachIteration) {
  const auto p = testing::sphere_energy_problem(2.5, 2.0, Vec3(1.0, -2.0, 0.5), 3.0);
  const DirectSolution d = testing::sphere_direct_seed(p);
  ASSERT_TRUE(d.converged) << d.status;
  std::vector<double> residuals;
  ShootingOptions watched;
  watched.on_newton_iteration = [&](double residual) { residuals.push_back(residual); };
  const IndirectSolution s = solve_indirect(p, d, watched);
  ASSERT_TRUE(s.converged) << s.status;
  ASSERT_EQ(static_cast<int>(residuals.size()), s.iterations);
  ASSERT_GE(residuals.size(), 1u);
  for (std::size_t k = 1; k < residuals.size(); ++k)
    EXPECT_LT(residuals[k], residuals[k - 1]) << "iteration " << k;
  EXPECT_EQ(residuals.back(), s.residual);
  const IndirectSolution plain = solve_indirect(p, d);
  EXPECT_EQ(plain.cost, s.cost);
  EXPECT_EQ(plain.iterations, s.iterations);
}

// The norm-bound sphere (‖u‖ ≤ ū, J = j I, rest to rest through Θ) in minimum time: the eigenaxis bang-bang
// manoeuvre, 2√(Θ j/ū), is optimal (‖L̇_space‖ = ‖u‖, and the duration bound is attained). σ passes through 0
// at T/2, where u reverses: the reversal time is a Newton unknown, so the optimum comes out to the shooting's
// accuracy (1e-12 relative) and the reversal at T/2. Checked by the verification like any other optimum.
TEST(IndirectShooting, NormBoundSphereReversesAtHalfTime) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "about 2 s in release, 11 s under ASan; PhasedCollocation.NormBoundSphereReversalOnANode "
                    "covers the reversal there";
  const double j = 1.5, ubar = 0.8, theta = 2.5;
  ReorientationProblem p;
  p.inertia_body = j * Mat3::Identity();
  p.bound = TorqueBound::norm;
  p.torque_max = Vec3::Constant(ubar);
  // About a body axis: about a generic axis the shooting stalls at a residual of 1e-5
  // (docs/optimal_control_theory.md) and says so.
  const Vec3 n = Vec3::UnitX();
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, n));
  const DirectSolution d = testing::sphere_direct_seed(p);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const double T = 2.0 * std::sqrt(theta * j / ubar);
  EXPECT_NEAR(s.final_time / T, 1.0, 1e-12);
  ASSERT_EQ(s.switch_times.size(), 1u);
  EXPECT_EQ(s.switch_axes[0], -1);
  EXPECT_NEAR(s.switch_times[0], T / 2, 1e-10 * T);
  // Bang-bang along the eigenaxis: u = ū n, then −ū n. At the reversal itself σ is at its round-off level
  // (1e-12), so the direction of −σ/‖σ‖ there is only good to about 1e-5: those two samples are left out.
  for (std::size_t k = 0; k < s.time.size(); ++k) {
    if (s.time[k] == s.switch_times[0]) continue;
    const double sign = s.time[k] < s.switch_times[0] ? 1.0 : -1.0;
    EXPECT_LT((s.torque_body[k] - sign * ubar * n).norm(), 1e-9 * ubar) << s.time[k];
  }
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
}

// Boundary arcs are handled for minimum time with per-axis bounds (test_rate_bound_shooting.cpp); under a
// norm bound σ would vanish along them (a singular arc), which the shooting does not handle: refused.
TEST(IndirectShooting, RefusesActiveRateBoundsUnderANormBound) {
  ReorientationProblem p;
  p.bound = TorqueBound::norm;
  p.attitude_final = Quat(0.0, 1.0, 0.0, 0.0);
  p.rate_max = 1.0;  // the unconstrained optimum reaches |ω_1| = √π ≈ 1.77 rad/s
  CollocationOptions opt;
  opt.initial_intervals = 8;
  opt.mesh_tolerance = 1e-3;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.status.find("rate bound is active"), std::string::npos) << s.status;
  EXPECT_FALSE(verify(p, d, s).passed);
}

// A first bang arc that the extremal does not have (problem 15 of the nonprincipal family, seed 5): the
// direct solution starts with u1 = +ū1 for one interval, an arc that shrinks with every mesh, then switches.
// Newton stalls at a residual of about 1e-2, with that switch driven to t → 0 (where the shooting's domain
// (0, T) holds it) or, from this mesh, at 0.040 s, 3.7 % of T; shot again without that arc, u1 = −ū1 from
// t = 0, it converges (without_vanishing_end_arcs, without_short_end_arcs). Oracles: the verification
// (H constant, the control minimising H at every sample, the DOP853 replay) and the final time of the
// phase-per-arc collocation over the direct switches (which shrinks that arc to nothing, and whose T meets
// the extremal's to its discretisation error, 32 intervals an arc). The direct T itself is 2.5e-4 above: its
// first interval spends time on the arc the extremal does not have.
TEST(IndirectShooting, AFirstArcThatTheExtremalDoesNotHaveIsDropped) {
  if (::poinsot::test::sanitized()) GTEST_SKIP() << "about 1 s in release (the direct phase)";
  ReorientationProblem p;
  p.inertia_body << 0.17488547918710465, -0.004325312179299989, 0.05018057823940357,  //
      -0.004325312179299989, 0.46531399808889157, 0.013490986739807177,               //
      0.05018057823940357, 0.013490986739807177, 0.38850519548750573;
  p.torque_max = Vec3(1.3623089002288467, 1.0925135270000585, 1.795612496620818);
  p.attitude_final = Quat(Eigen::AngleAxisd(
      1.1081211948686986, Vec3(-0.4661448318062666, 0.8774752828421832, 0.11289873241687774).normalized()));
  CollocationOptions seed;
  seed.mesh_tolerance = 1e-5;
  const DirectSolution d = solve_direct(p, seed);
  ASSERT_TRUE(d.converged) << d.status;
  ASSERT_GT(d.torque_body.front()[0], 0.0);  // the arc the extremal does not have
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  EXPECT_EQ(s.torque_body.front()[0], -p.torque_max[0]);
  for (std::size_t k = 0; k < s.switch_times.size(); ++k)
    EXPECT_GT(s.switch_times[k], 0.2) << "switch of u" << s.switch_axes[k] + 1;
  PhasedOptions fine;
  fine.intervals_per_arc = 32;  // Hermite–Simpson's O(h⁴): 2.2e-8 relative with 8 intervals per arc
  const PhasedSolution phased = solve_direct_phased(p, d, read_switching_structure(p, d), fine);
  ASSERT_TRUE(phased.converged) << phased.status;
  EXPECT_NEAR(s.final_time / phased.solution.final_time, 1.0, 1e-9);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_EQ(v.switching_sign_violations, 0);
}

}  // namespace
}  // namespace poinsot::optimal
