// RATTLE in rotation-matrix coordinates against closed forms, an independent single-body integrator,
// conservation laws and its own convergence order.
#include "poinsot/multibody/rattle.hpp"

#include <cmath>
#include <numbers>
#include <tuple>

#include "allocation_counter.hpp"
#include "multibody_fixtures.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using poinsot::so3::hat;
using test::kG;  // the fixtures' gravity, m/s²

Mat3 rot_y(double a) {
  return Eigen::AngleAxisd(a, Vec3::UnitY()).toRotationMatrix();
}

// Period of small oscillations from the upward zero crossings of x(t) (linear interpolation; the error is
// O(h³) at a crossing, where x is nearly linear).
double measured_period(Rattle& rattle, State& st, int body, double duration) {
  std::vector<double> crossings;
  double prev_x = st.bodies[static_cast<std::size_t>(body)].x_space.x();
  double prev_t = st.time;
  while (st.time < duration) {
    rattle.step(st);
    const double x = st.bodies[static_cast<std::size_t>(body)].x_space.x();
    if (prev_x < 0.0 && x >= 0.0) crossings.push_back(prev_t + (st.time - prev_t) * (-prev_x) / (x - prev_x));
    prev_x = x;
    prev_t = st.time;
  }
  EXPECT_GE(crossings.size(), 3u);
  return (crossings.back() - crossings.front()) / static_cast<double>(crossings.size() - 1);
}

TEST(Rattle, CompoundPendulumOnHingeHasSmallOscillationPeriod) {
  const double m = 1.3, l = 0.8, r = 0.05, theta0 = 1e-3;
  System s;
  s.add_body("rod", m, test::rod_poinsot(m, l, r));
  s.add_hinge("pivot", 0, Vec3(-l / 2, 0, 0), Vec3::UnitY(), kWorld, Vec3::Zero(), Vec3::UnitY());
  s.set_gravity(Vec3(0, 0, -kG));
  State st;
  st.bodies.resize(1);
  st.bodies[0].R_space_body = rot_y(std::numbers::pi / 2 + theta0);  // body x hangs along −z, tilted by θ0
  st.bodies[0].x_space = st.bodies[0].R_space_body * Vec3(l / 2, 0, 0);
  check_consistent(s, st);
  Rattle rattle(s, 1e-3);
  EXPECT_TRUE(rattle.uses_tree_solver());
  const double I_pivot = m * l * l / 12 + m * r * r / 4 + m * l * l / 4;  // J_yy about the pivot
  const double expected = 2 * std::numbers::pi * std::sqrt(I_pivot / (m * kG * l / 2));
  const double period = measured_period(rattle, st, 0, 4 * expected);
  // Errors: RATTLE's phase error (ωh)²/24 ≈ 6e-7, the amplitude correction θ0²/16 ≈ 6e-8. Dropping the rod's
  // radius term m r²/4 would change the period by 1.7e-3.
  EXPECT_NEAR(period / expected, 1.0, 3e-6);
}

TEST(Rattle, WeldedPairSwingsLikeOneCompoundPendulum) {
  // A rod hung by a ball joint with a cube welded to its lower end: the composite's period.
  const double m1 = 1.0, l = 1.0, r = 0.02, m2 = 0.5, a = 0.2;
  System s;
  s.add_body("rod", m1, test::rod_poinsot(m1, l, r));
  s.add_body("cube", m2, (m2 * a * a / 12) * Mat3::Identity());
  s.add_ball("pivot", 0, Vec3(-l / 2, 0, 0), kWorld, Vec3::Zero());
  s.add_weld("weld", 1, Vec3(-a / 2, 0, 0), 0, Vec3(l / 2, 0, 0), Mat3::Identity());
  s.set_gravity(Vec3(0, 0, -kG));
  State st;
  st.bodies.resize(2);
  const double theta0 = 1e-3;
  const Mat3 R = rot_y(std::numbers::pi / 2 + theta0);
  st.bodies[0].R_space_body = R;
  st.bodies[0].x_space = R * Vec3(l / 2, 0, 0);
  st.bodies[1].R_space_body = R;
  st.bodies[1].x_space = R * Vec3(l + a / 2, 0, 0);
  check_consistent(s, st);
  Rattle rattle(s, 1e-3);
  const double d1 = l / 2, d2 = l + a / 2;
  const double I_pivot = m1 * l * l / 12 + m1 * r * r / 4 + m1 * d1 * d1 + m2 * a * a / 6 + m2 * d2 * d2;
  const double M_d = m1 * d1 + m2 * d2;
  const double expected = 2 * std::numbers::pi * std::sqrt(I_pivot / (M_d * kG));
  EXPECT_NEAR(measured_period(rattle, st, 1, 4 * expected) / expected, 1.0, 3e-6);
  EXPECT_LT(constraint_violation(s, st).joint_angle, 1e-12);
}

std::pair<Mat3, Vec3> top_multibody(const test::Top& top, double T, double h, int order = 2) {
  auto [s, st] = test::top_system(top);
  RattleOptions options;
  options.order = order;
  Rattle rattle(s, h, options);
  const int steps = static_cast<int>(std::lround(T / h));
  for (int n = 0; n < steps; ++n)
    rattle.step(st);
  return {st.bodies[0].R_space_body, st.bodies[0].omega_body};
}

TEST(Rattle, HeavyTopConvergesAtOrderTwoToTheSingleBodyTop) {
  const test::Top top;
  const double T = 2.0;                                            // about 3 nutation periods at this spin
  const auto [R_ref, w_ref] = test::top_reference(top, T, 30000);  // RK4, h = 1e-4: error (ωh)⁴ ~ 1e-15
  double err[3];
  Mat3 R_h[3];
  const double hs[3] = {2e-3, 1e-3, 5e-4};
  for (int k = 0; k < 3; ++k) {
    const auto [R, w] = top_multibody(top, T, hs[k]);
    R_h[k] = R;
    err[k] = (R - R_ref).cwiseAbs().maxCoeff() + (w - w_ref).cwiseAbs().maxCoeff() / 3.0;
  }
  // Second order: halving h divides the error by 4 (3.5..4.5 allows the O(h⁴) term).
  EXPECT_NEAR(err[0] / err[1], 4.0, 0.5);
  EXPECT_NEAR(err[1] / err[2], 4.0, 0.5);
  // RATTLE is symmetric, so its error expands in h², h⁴: one Richardson step leaves O(h⁴):
  // measured 3e-9 for h = (2e-3, 1e-3) and 1.4e-10 for (1e-3, 5e-4), the raw error being 1.5e-5 at 5e-4.
  const Mat3 R_rich = (4 * R_h[2] - R_h[1]) / 3;
  EXPECT_LT((R_rich - R_ref).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_GT(err[2], 1e-7);  // the comparison is meaningful: the raw error is far above the 1e-9 tolerance
}

TEST(Rattle, HeavyTopConvergesAtOrderFourToTheSingleBodyTop) {
  const test::Top top;
  const double T = 2.0;
  const auto [R_ref, w_ref] = test::top_reference(top, T, 30000);  // RK4, h = 1e-4: error ~ 1e-15
  double err[3];
  const double hs[3] = {4e-3, 2e-3, 1e-3};
  for (int k = 0; k < 3; ++k) {
    const auto [R, w] = top_multibody(top, T, hs[k], 4);
    err[k] = (R - R_ref).cwiseAbs().maxCoeff() + (w - w_ref).cwiseAbs().maxCoeff() / 3.0;
  }
  // Fourth order: halving h divides the error by 16 (13..19 allows the O(h⁶) term of a symmetric method).
  EXPECT_NEAR(err[0] / err[1], 16.0, 3.0);
  EXPECT_NEAR(err[1] / err[2], 16.0, 3.0);
  // And far below order 2 at the same step (measured 1.3e-8 against 6e-5).
  const auto [R2, w2] = top_multibody(top, T, 1e-3, 2);
  EXPECT_LT(err[2], 1e-3 * ((R2 - R_ref).cwiseAbs().maxCoeff() + (w2 - w_ref).cwiseAbs().maxCoeff() / 3.0));
}

struct RunStats {
  double max_energy_error = 0.0;
  double max_gap = 0.0;
  double max_orthogonality = 0.0;
  double first_half_max = 0.0;
  double second_half_max = 0.0;
};

RunStats run_and_watch(const System& s, State st, double h, int steps, int order = 2) {
  RattleOptions options;
  options.order = order;
  Rattle rattle(s, h, options);
  const double E0 = total_energy(s, st);
  RunStats stats;
  for (int n = 0; n < steps; ++n) {
    rattle.step(st);
    const double dE = std::abs(total_energy(s, st) - E0);
    stats.max_energy_error = std::max(stats.max_energy_error, dE);
    (n < steps / 2 ? stats.first_half_max : stats.second_half_max) =
        std::max(n < steps / 2 ? stats.first_half_max : stats.second_half_max, dE);
    const ConstraintViolation v = constraint_violation(s, st);
    stats.max_gap = std::max(stats.max_gap, v.joint_gap);
    stats.max_orthogonality = std::max(stats.max_orthogonality, v.orthogonality);
  }
  return stats;
}

TEST(Rattle, DoublePendulumEnergyBoundedAndConstraintsAtRoundOff) {
  const System s = test::rod_chain(2);
  State st = test::rod_chain_state(2);
  st.bodies[1].omega_body = Vec3(0, 0, 3.0);  // out-of-plane motion: a 3-D chaotic double pendulum
  st.bodies[1].v_space = Vec3(0, 1.5, 0);
  const double released = 2 * kG;  // m g l N²/2 with m = l = 1, N = 2
  const RunStats a = run_and_watch(s, st, 1e-3, 20000 / test::slowdown());
  // The energy error of a symplectic method oscillates at O(h²) without drift: both halves of the run share
  // the same bound (measured 4.0e-5 and 4.3e-5 of the released energy; 5e-4 at h = 4e-3, i.e. order 2).
  EXPECT_LT(a.max_energy_error, 1e-4 * released);
  EXPECT_LT(a.second_half_max, 3.0 * a.first_half_max + 1e-9 * released);
  EXPECT_LT(a.max_gap, 1e-12);
  EXPECT_LT(a.max_orthogonality, 1e-12);
}

TEST(Rattle, ChainFallingFromHorizontalKeepsEnergyAndJoints) {
  const int n = 8;
  const System s = test::rod_chain(n);
  const double released = kG * n * n / 2.0;
  const RunStats a = run_and_watch(s, test::rod_chain_state(n), 1e-3, 4000 / test::slowdown());
  // Measured 7e-5 of the released energy over 4 s (the tip of a chain falling from horizontal whips fast).
  EXPECT_LT(a.max_energy_error, 2e-4 * released);
  EXPECT_LT(a.max_gap, 1e-12);
  EXPECT_LT(a.max_orthogonality, 1e-12);
}

// A chain of 4 falling for 0.8 s at steps h, h/2, h/4: the ratio of the successive differences of the final
// positions, 2^order for a method of that order.
double chain_convergence_ratio(int order, double h) {
  const System s = test::rod_chain(4);
  auto run = [&](double step) {
    State st = test::rod_chain_state(4);
    RattleOptions options;
    options.order = order;
    Rattle rattle(s, step, options);
    for (int k = 0; k < static_cast<int>(std::lround(0.8 / step)); ++k)
      rattle.step(st);
    EXPECT_NEAR(st.time, 0.8, 1e-12);  // the substeps of order 4 land on each step's end exactly
    return st;
  };
  const State a = run(h), b = run(h / 2), c = run(h / 4);
  double dab = 0, dbc = 0;
  for (std::size_t i = 0; i < 4; ++i) {
    dab = std::max(dab, (a.bodies[i].x_space - b.bodies[i].x_space).norm());
    dbc = std::max(dbc, (b.bodies[i].x_space - c.bodies[i].x_space).norm());
  }
  return dab / dbc;
}

TEST(Rattle, FourthOrderKeepsTheFallingChainsEnergyHundredsOfTimesBetter) {
  const int n = 8;
  const System s = test::rod_chain(n);
  const double released = kG * n * n / 2.0;
  const int steps = 4000 / test::slowdown();
  const RunStats two = run_and_watch(s, test::rod_chain_state(n), 1e-3, steps, 2);
  const RunStats four = run_and_watch(s, test::rod_chain_state(n), 1e-3, steps, 4);
  // The whip of the tip dominates both; order 4 cuts the peak error by O((ωh)²): measured 7.1e-5 -> 2.5e-7 of
  // the released energy over 4 s (280 times), 3.3e-7 -> 2.5e-11 over the 0.8 s of sanitizer builds.
  EXPECT_LT(four.max_energy_error, two.max_energy_error / 100.0);
  EXPECT_LT(four.max_gap, 1e-12);
  EXPECT_LT(four.max_orthogonality, 1e-12);
  EXPECT_GT(two.max_energy_error, 1e-9 * released);  // the comparison is meaningful
}

TEST(Rattle, FourthOrderOnAChain) {
  EXPECT_NEAR(chain_convergence_ratio(4, 8e-3), 16.0, 3.0);  // measured 16.0
}

TEST(Rattle, AFailedStepLeavesTheStateAsItWas) {
  // A spin that is fine for the first substep of order 4 (γ₁h|ω| < 1) but not for the middle one
  // (|γ₂|h|ω| > 1): the step fails after a substep has moved the state, and must undo it.
  System s;
  s.add_body_from_inertia("spinner", 1.0, Vec3(1, 2, 2.5).asDiagonal());
  State st;
  st.bodies.resize(1);
  const double h = 0.1;
  st.bodies[0].omega_body = Vec3(0.1, 0.2, 1.0);
  RattleOptions options;
  options.order = 4;
  Rattle rattle(s, h, options);
  rattle.step(st);  // a good step: its multipliers are those of a spinning body, Λ = (j(ω)² + j(ω̇))K ≠ 0
  EXPECT_GT(rattle.velocity_stage().Lambda_body[0].norm(), 0.1);
  st.bodies[0].omega_body = Vec3(0, 0, 7.0);  // γ₁h|ω| = 0.95, |γ₂|h|ω| = 1.19
  const State before = st;
  EXPECT_THROW(rattle.step(st), ComputationFailed);
  EXPECT_EQ(st.time, before.time);
  EXPECT_EQ(st.bodies[0].R_space_body, before.bodies[0].R_space_body);
  EXPECT_EQ(st.bodies[0].omega_body, before.bodies[0].omega_body);
  EXPECT_EQ(st.bodies[0].x_space, before.bodies[0].x_space);
  EXPECT_EQ(rattle.velocity_stage().Lambda_body[0], Mat3::Zero());  // none from a failed step
  EXPECT_EQ(rattle.position_stage().Lambda_body[0], Mat3::Zero());
}

TEST(Rattle, StepsAllocateNothingOnTrees) {
  // Both O(N) solvers (ball chain; Baraff's tree order, here with a hinge) and both orders: after the first
  // step, stepping and reading the multipliers allocate nothing (the workspace is sized in the constructor).
  System chain = test::rod_chain(6);
  const auto [tree, tree_state] = test::hinge_tree();
  for (int order : {2, 4}) {
    for (const auto& [system, start, method] :
         {std::tuple{chain, test::rod_chain_state(6), KktMethod::ball_chain},
          std::tuple{tree, tree_state, KktMethod::tree}}) {
      RattleOptions options;
      options.order = order;
      const long long before_construction = poinsot::test::allocation_count();
      Rattle rattle(system, 1e-3, options);
      // The counter is live in this executable: the constructor sizes its workspace.
      ASSERT_GT(poinsot::test::allocation_count(), before_construction);
      ASSERT_EQ(rattle.kkt_method(), method);
      State st = start;
      rattle.step(st);
      const long long before = poinsot::test::allocation_count();
      for (int k = 0; k < 50; ++k) {
        rattle.step(st);
        (void)rattle.position_stage();
        (void)rattle.velocity_stage();
      }
      EXPECT_EQ(poinsot::test::allocation_count() - before, 0)
          << "order " << order << ", " << kkt_method_name(method);
      EXPECT_LT(constraint_violation(system, st).joint_gap, 1e-12);
    }
  }
}

TEST(Rattle, RejectsAnOrderItDoesNotHave) {
  const System s = test::rod_chain(1);
  RattleOptions options;
  options.order = 3;
  EXPECT_THROW(Rattle(s, 1e-3, options), InvalidInput);
}

TEST(Rattle, SecondOrderOnAChain) {
  EXPECT_NEAR(chain_convergence_ratio(2, 4e-3), 4.0, 0.5);
}

TEST(Rattle, FreeSystemConservesMomentaExactly) {
  // Three bodies (one a lamina with singular K) joined by a ball and a hinge, no gravity, tumbling.
  System s;
  s.add_body_from_inertia("a", 1.0, Vec3(0.1, 0.2, 0.25).asDiagonal());
  s.add_body("plate", 0.5, Vec3(0.02, 0.01, 0.0).asDiagonal());  // K singular: a lamina
  s.add_body_from_inertia("c", 2.0, Vec3(0.3, 0.3, 0.1).asDiagonal());
  s.add_ball("ab", 0, Vec3(0.3, 0, 0), 1, Vec3(-0.2, 0, 0));
  s.add_hinge("bc", 2, Vec3(0, 0.4, 0), Vec3(0, 0, 1), 1, Vec3(0, -0.1, 0), Vec3(0, 0, 1));
  State st;
  st.bodies.resize(3);
  st.bodies[0].x_space = Vec3(-0.3, 0, 0);
  st.bodies[1].x_space = Vec3(0.2, 0, 0);
  st.bodies[2].x_space = Vec3(0.2, -0.5, 0);
  // Velocities consistent with the joints: a common rigid rotation plus a hinge rate about z.
  const Vec3 Omega(0.7, -1.1, 2.0);
  for (BodyState& b : st.bodies) {
    b.v_space = Omega.cross(b.x_space) + Vec3(0.1, 0.2, -0.3);
    b.omega_body = Omega;
  }
  st.bodies[2].omega_body += Vec3(0, 0, 1.5);
  st.bodies[2].v_space += Vec3(0, 0, 1.5).cross(Vec3(0, -0.4, 0));
  EXPECT_LT(constraint_violation(s, st).joint_velocity, 1e-15);
  const State st0 = st;
  for (int order : {2, 4}) {  // each substep of the composition conserves them, so does the whole step
    st = st0;
    RattleOptions options;
    options.order = order;
    Rattle rattle(s, 2e-3, options);
    const Vec3 P0 = linear_momentum(s, st), L0 = angular_momentum(s, st);
    const double E0 = total_energy(s, st);
    for (int n = 0; n < 3000 / test::slowdown(); ++n)
      rattle.step(st);
    // Exact up to the Newton tolerance (1e-13 of the positions per step) and round-off.
    EXPECT_LT((linear_momentum(s, st) - P0).norm(), 1e-11 * P0.norm()) << "order " << order;
    EXPECT_LT((angular_momentum(s, st) - L0).norm(), 1e-10 * L0.norm()) << "order " << order;
    EXPECT_LT(std::abs(total_energy(s, st) - E0), 1e-4 * E0) << "order " << order;
    EXPECT_LT(constraint_violation(s, st).joint_gap, 1e-12) << "order " << order;
    EXPECT_LT(constraint_violation(s, st).joint_angle, 1e-12) << "order " << order;
  }
}

TEST(Rattle, ClosedLoopFallsBackToSparseLuAndHolds) {
  // A spatial four-bar: three bars joined by ball joints, both ends held at fixed points of the world (a loop
  // through the world), falling under an oblique gravity.
  const auto [s, st] = test::four_bar_loop();
  check_consistent(s, st);
  EXPECT_FALSE(Rattle(s, 1e-3).uses_tree_solver());
  const RunStats a = run_and_watch(s, st, 1e-3, 3000 / test::slowdown());
  EXPECT_LT(a.max_energy_error, 1e-5 * kG);
  EXPECT_LT(a.max_gap, 1e-12);
  EXPECT_LT(a.max_orthogonality, 1e-12);
}

TEST(Rattle, SpringOscillatorPeriodAndDampedPairMomentum) {
  // A body on a spring to the world (no gravity, rest length 0): x'' = −(k/m) x, period 2π √(m/k).
  const double m = 2.0, k = 50.0;
  auto [s, st] = test::spring_oscillator(m, k);
  Rattle rattle(s, 1e-3);
  const double expected = 2 * std::numbers::pi * std::sqrt(m / k);
  // Phase error (ωh)²/24 ≈ 1e-6 at ω = 5 rad/s.
  EXPECT_NEAR(measured_period(rattle, st, 0, 4 * expected) / expected, 1.0, 3e-6);

  // Two bodies joined by a spring-damper with an offset attachment: internal forces, so the total momentum
  // is conserved exactly, while the damper only removes energy (second order with the extrapolated
  // velocities).
  System pair;
  pair.add_body_from_inertia("a", 1.0, Vec3(0.1, 0.2, 0.3).asDiagonal());
  pair.add_body_from_inertia("b", 2.0, Vec3(0.2, 0.2, 0.1).asDiagonal());
  pair.add_spring({"sd", 0, 1, Vec3(0.1, 0.2, 0), Vec3(-0.1, 0, 0.1), 30.0, 0.8, 0.5});
  State ps;
  ps.bodies.resize(2);
  ps.bodies[1].x_space = Vec3(1, 0, 0);
  ps.bodies[0].v_space = Vec3(0, 1, 0.5);
  ps.bodies[0].omega_body = Vec3(1, -2, 3);
  Rattle pr(pair, 1e-3);
  const Vec3 P0 = linear_momentum(pair, ps), L0 = angular_momentum(pair, ps);
  double E = total_energy(pair, ps);
  const double E0 = E;
  double max_rise = 0.0;
  for (int n = 0; n < 2000 / test::slowdown(); ++n) {
    pr.step(ps);
    const double E1 = total_energy(pair, ps);
    max_rise = std::max(max_rise, E1 - E);
    E = E1;
  }
  EXPECT_LT((linear_momentum(pair, ps) - P0).norm(), 1e-12 * P0.norm());
  EXPECT_LT((angular_momentum(pair, ps) - L0).norm(), 1e-11 * L0.norm());
  EXPECT_LT(E, 0.9 * E0);          // the damper has removed energy
  EXPECT_LT(max_rise, 1e-5 * E0);  // up to the O(h²) oscillation of the conservative part
}

}  // namespace
}  // namespace poinsot::multibody
