#include "../../src/optimal/multiple_shooting.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/verification.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

// A coarse direct solution of Betts' problem (mesh error 1e-4): enough for the switching structure and the
// costates, and for the verification's direct–indirect agreement (1e-3; at a mesh error of 1e-3 it
// is 1.25e-3).
DirectSolution coarse_betts_direct(const ReorientationProblem& p) {
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-4;
  return solve_direct(p, opt);
}

// Multiple shooting solves the same boundary-value problem as single shooting: both converge to the
// Newton tolerance (1e-12 on the scaled residual) with RKF78 at 1e-13, so t* and the switches agree far
// below 1e-10 (measured: 1e-14 relative, 1e-12 s); both meet the published t* (8 digits) to 5e-8.
TEST(MultipleShooting, BettsAgreesWithSingleShooting) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "0.5 s in release, tens of seconds under ASan; the Jacobian test runs the same code there";
  const auto p = testing::betts_problem();
  const DirectSolution d = coarse_betts_direct(p);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution single = solve_indirect(p, d);
  ASSERT_TRUE(single.converged) << single.status;
  ShootingOptions o;
  o.shooting_nodes = 6;
  const IndirectSolution multiple = solve_indirect(p, d, o);
  ASSERT_TRUE(multiple.converged) << multiple.status;
  EXPECT_NEAR(multiple.final_time / single.final_time, 1.0, 1e-10);
  EXPECT_NEAR(multiple.final_time / testing::kBettsPublishedTime, 1.0, 5e-8);
  ASSERT_EQ(multiple.switch_times.size(), single.switch_times.size());
  ASSERT_EQ(multiple.switch_times.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_NEAR(multiple.switch_times[k], single.switch_times[k], 1e-10);
    EXPECT_EQ(multiple.switch_axes[k], single.switch_axes[k]);
  }
  EXPECT_NEAR(multiple.cost, single.cost, 1e-10 * single.cost);
  const VerificationReport v = verify(p, d, multiple);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_LT(v.resimulated_attitude_error, 1e-9);
}

// The sphere at minimum energy through multiple shooting: the eigenaxis cubic with cost 12 j²Θ²/T³, to
// 1e-11 (the shooting tolerance). (The norm-bound slew, whose σ passes through 0: NormBoundReversalAwayFrom-
// TheNodes below.)
TEST(MultipleShooting, SphereMinimumEnergyClosedForm) {
  const double j = 2.5, theta = 2.0, T = 3.0;
  const auto p = testing::sphere_energy_problem(j, theta, Vec3(1.0, -2.0, 0.5), T);
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-5;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  ShootingOptions o;
  o.shooting_nodes = 5;
  const IndirectSolution s = solve_indirect(p, d, o);
  ASSERT_TRUE(s.converged) << s.status;
  EXPECT_NEAR(s.cost / (12.0 * j * j * theta * theta / (T * T * T)), 1.0, 1e-11);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
}

// The block-sparse Jacobian (a node's columns re-integrate its own segment only; the others the whole
// horizon) against central differences of the whole residual with a tenfold larger step, on Betts' problem
// with four segments (five switches, one or more inside each segment), away from the solution. Both are
// central differences of the same function: they agree to the truncation error of the larger step
// (1e-8 relative) plus the integration noise (1e-13 / 1e-4), far below 1e-5 of each column's size, and every
// entry the sparse Jacobian leaves out must be zero.
TEST(MultipleShooting, JacobianMatchesCentralDifferences) {
  const auto p = testing::betts_problem();
  const DirectSolution d = coarse_betts_direct(p);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  detail::SwitchGuess sw;
  for (int i = 0; i < 3; ++i)
    sw.initial_sign[i] = s.arcs.front().torque_body[i] > 0.0 ? 1.0 : -1.0;
  sw.times = s.switch_times;
  sw.axes = s.switch_axes;
  const int M = 4;
  // Node references and values from the converged samples, then moved off the solution.
  std::vector<Mat3> refs;
  std::vector<std::size_t> at;
  for (int m = 1; m < M; ++m) {
    std::size_t k = 0;
    while (k + 1 < s.time.size() && s.time[k] < s.final_time * m / M)
      ++k;
    at.push_back(k);
    refs.push_back(s.attitude[k]);
  }
  const ShootingOptions o;
  const detail::Shooter shooter(p, o, sw, true, refs, 0.2);
  Eigen::VectorXd x(shooter.size());
  x << s.costate_attitude_initial, s.costate_omega_initial, s.final_time,
      Eigen::Map<const Eigen::VectorXd>(s.switch_times.data(), 5), Eigen::VectorXd::Zero(12 * (M - 1));
  for (int m = 1; m < M; ++m) {
    const std::size_t k = at[static_cast<std::size_t>(m - 1)];
    shooter.set_node(x, m, s.attitude[k] * so3::exp(Vec3(1e-3, -2e-3, 1e-3)), s.omega_body[k] * 1.01,
                     s.costate_attitude_body[k] * 0.99, s.costate_omega[k] * 1.02);
  }
  x.segment<3>(3) *= 1.01;
  x[6] *= 1.001;
  Eigen::VectorXd F;
  ASSERT_TRUE(shooter.residual(x, F));
  std::vector<detail::Shooter::SegmentEnd> ends;
  ASSERT_TRUE(shooter.segment_ends(x, ends));
  Eigen::SparseMatrix<double> sparse;
  ASSERT_TRUE(shooter.jacobian(x, ends, F, sparse));
  const Eigen::MatrixXd J = sparse;
  EXPECT_LT(sparse.nonZeros(), J.size() / 2);  // block sparse: the node blocks stay apart
  for (int j = 0; j < x.size(); ++j) {
    const double h = 1e-4 * std::max(std::abs(x[j]), 1e-2);
    Eigen::VectorXd xp = x, xm = x, Fp, Fm;
    xp[j] += h;
    xm[j] -= h;
    ASSERT_TRUE(shooter.residual(xp, Fp) && shooter.residual(xm, Fm));
    const Eigen::VectorXd c = (Fp - Fm) / (2.0 * h);
    const double size = std::max(c.cwiseAbs().maxCoeff(), 1e-300);
    EXPECT_LT((c - J.col(j)).cwiseAbs().maxCoeff(), 1e-5 * size) << "column " << j;
  }
}

// Where multiple shooting is needed: the racket spinning at 1 rad/s about its unstable intermediate axis
// for T = 30 s (λT = 26.6, so a costate error grows by e^{26.6} ≈ 4e11 over the horizon) and ending 0.5 rad
// ahead of the free spin, at minimum energy. From the same direct solution (which follows the spin: it meets
// the closed-form cost 12 J_y²Δ²/T³ to its mesh error, 7e-6 measured) single shooting fails — its first
// shot misses by a scaled residual of 118 and Newton stalls after 2 iterations at 17 — while eight
// segments (growth e^{3.3} each) converge in 2 iterations to the closed form to 1e-10 (measured 3e-12: the
// Newton tolerance 1e-12 and RKF78 at 1e-13) and pass every check, the dop853 re-simulation included.
TEST(MultipleShooting, UnstableSpinNeedsNodes) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "0.8 s in release, tens of seconds under ASan; the sphere and Jacobian tests run there";
  const double w = 1.0, T = 30.0, delta = 0.5, J_y = 0.01638;
  const auto p = testing::racket_spin_phase_problem(w, T, delta);
  const double closed_form = 12.0 * J_y * J_y * delta * delta / (T * T * T);
  CollocationOptions opt;
  opt.initial_intervals = 80;
  opt.mesh_tolerance = 1e-6;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  // The mesh error 1e-6 bounds the cost's relative error to about 1e-5 (measured 7e-6).
  EXPECT_NEAR(d.cost / closed_form, 1.0, 5e-5);
  const IndirectSolution single = solve_indirect(p, d);
  EXPECT_FALSE(single.converged) << "single shooting was expected to fail over λT = 26.6";
  EXPECT_FALSE(verify(p, d, single).passed);
  ShootingOptions o;
  o.shooting_nodes = 8;
  const IndirectSolution multiple = solve_indirect(p, d, o);
  ASSERT_TRUE(multiple.converged) << multiple.status;
  EXPECT_NEAR(multiple.cost / closed_form, 1.0, 1e-10);
  EXPECT_NEAR(multiple.cost / d.cost, 1.0, 5e-5);
  const VerificationReport v = verify(p, d, multiple);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_LT(v.resimulated_attitude_error, 1e-6);
}

// The norm-bound sphere's minimum-time slew (the eigenaxis bang-bang manoeuvre, T = 2√(Θj/ū), the reversal of
// u at T/2 where σ passes through 0) by multiple shooting. With nodes at mT/M the reversal sat on the middle
// node for even M: the knot's condition jumped from the previous segment's end to the node's unknowns as it
// crossed the node, and the control's direction at the start of the next segment, where σ ≈ 0, depended on
// the node's p_ω across σ's line, where −ū σ/‖σ‖ is not smooth — Newton stalled at 2.9e-9 (M = 4). The nodes
// are now placed a quarter of a segment or more from every knot of the guess: M = 4 converges to the
// tolerance (measured 7e-13, T to 2.4e-14, the reversal at T/2 to 1e-15 s), and passes the verification.
TEST(MultipleShooting, NormBoundReversalAwayFromTheNodes) {
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
  ShootingOptions o;
  o.shooting_nodes = 4;
  const IndirectSolution s = solve_indirect(p, d, o);
  ASSERT_TRUE(s.converged) << s.status;
  const double T = 2.0 * std::sqrt(theta * j / ubar);
  // The Newton tolerance (1e-12 on the scaled residual) and RKF78 at 1e-13 bound T's error near 1e-12.
  EXPECT_NEAR(s.final_time / T, 1.0, 1e-12);
  ASSERT_EQ(s.switch_times.size(), 1u);
  EXPECT_NEAR(s.switch_times[0], T / 2, 1e-10 * T);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
}

TEST(MultipleShooting, RefusesABadNodeCount) {
  const auto p = testing::sphere_energy_problem(1.0, 1.0, Vec3::UnitZ(), 2.0);
  CollocationOptions opt;
  opt.initial_intervals = 4;
  opt.mesh_tolerance = 1e-2;
  const DirectSolution d = solve_direct(p, opt);
  ShootingOptions o;
  o.shooting_nodes = 0;
  EXPECT_THROW(solve_indirect(p, d, o), InvalidInput);
  o.shooting_nodes = 1001;
  EXPECT_THROW(solve_indirect(p, d, o), InvalidInput);
}

}  // namespace
}  // namespace poinsot::optimal

namespace poinsot::optimal {
namespace {

// Stopping a tumble in minimum time under ‖u‖ ≤ ū with a free final attitude: T* = ‖Jω_0‖/ū exactly (the
// duration bound, attained by u = −ū L/‖L‖ for any inertia), with the extremal p_θ ≡ 0,
// σ = J⁻¹p_ω = L_body/(ū‖L‖). Brody's racket spun at 2 rad/s about the intermediate axis (T* = 3.28 s; at
// the example's 6.28 rad/s the shooting stalls, docs/measurements/optimal_shooting.md): the direct method
// from the momentum-dumping guess, then single and multiple shooting from its costates, must reach T* to
// 1e-10 (the shooting is exact up to RKF78 at 1e-13 and the Newton tolerance), with p_θ(0) = 0 and p_ω(0) the
// closed form to 1e-8 of its size, and pass the verification.
TEST(MultipleShooting, DetumblingMeetsTheMomentumBound) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "1.3 s in release, tens of seconds under ASan; the sphere and Jacobian tests run there";
  ReorientationProblem p;
  p.inertia_body = Vec3(0.00121, 0.01638, 0.01748).asDiagonal();
  p.bound = TorqueBound::norm;
  p.torque_max = Vec3::Constant(0.01);
  p.omega_initial = Vec3(0.05, 2.0, 0.05);
  p.free_final_attitude = true;
  const Vec3 L0 = p.inertia_body * p.omega_initial;
  const double T_star = L0.norm() / 0.01;
  const Vec3 p_omega_star = p.inertia_body * L0 / (0.01 * L0.norm());
  CollocationOptions opt;
  opt.initial_intervals = 40;
  opt.mesh_tolerance = 1e-5;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  EXPECT_NEAR(d.final_time / T_star, 1.0, 1e-4);
  for (int M : {1, 8}) {
    ShootingOptions o;
    o.shooting_nodes = M;
    // The smooth control is replayed piecewise-linearly from the samples: 64 per arc over one arc misses the
    // attitude by 7e-6 rad, above the 1e-6 the verification allows; 512 samples over the horizon suffice.
    o.samples_per_arc = 512 / M;
    const IndirectSolution s = solve_indirect(p, d, o);
    ASSERT_TRUE(s.converged) << "M = " << M << ": " << s.status;
    EXPECT_NEAR(s.final_time / T_star, 1.0, 1e-10) << "M = " << M;
    EXPECT_LT(s.costate_attitude_initial.norm(), 1e-8 * p_omega_star.norm() / T_star) << "M = " << M;
    EXPECT_LT((s.costate_omega_initial - p_omega_star).norm(), 1e-8 * p_omega_star.norm()) << "M = " << M;
    const VerificationReport v = verify(p, d, s);
    EXPECT_TRUE(v.passed) << "M = " << M << ": " << (v.failures.empty() ? "" : v.failures.front());
  }
}

}  // namespace
}  // namespace poinsot::optimal
