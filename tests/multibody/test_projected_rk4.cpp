// The projected RK4 against an independent single-body integration (order 4), against RATTLE's fourth-order
// composition (another formulation of the same equations), against closed forms (the conical pendulum's
// reaction, a spring's period), and for what the projection promises (joints, rotations and joint velocities
// at round-off after every step).
#include "poinsot/multibody/projected_rk4.hpp"

#include <cmath>
#include <numbers>
#include <string>
#include <tuple>

#include "allocation_counter.hpp"
#include "multibody_fixtures.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using test::kG;

std::pair<Mat3, Vec3> top_rk4(const test::Top& top, double T, double h) {
  auto [s, st] = test::top_system(top);
  ProjectedRk4 rk4(s, h);
  const int steps = static_cast<int>(std::lround(T / h));
  for (int n = 0; n < steps; ++n)
    rk4.step(st);
  EXPECT_NEAR(st.time, T, 1e-12);
  return {st.bodies[0].R_space_body, st.bodies[0].omega_body};
}

TEST(ProjectedRk4, HeavyTopConvergesAtOrderFourToTheSingleBodyTop) {
  // The same top as RATTLE's test: the reference integrates Euler's equations about the pivot in three
  // coordinates; here the top is a body with a ball joint, in twelve coordinates with multipliers.
  const test::Top top;
  const double T = 2.0;
  const auto [R_ref, w_ref] = test::top_reference(top, T, 30000);  // h = 6.7e-5: error ~ 1e-15
  double err[3];
  const double hs[3] = {2e-3, 1e-3, 5e-4};
  for (int k = 0; k < 3; ++k) {
    const auto [R, w] = top_rk4(top, T, hs[k]);
    err[k] = (R - R_ref).cwiseAbs().maxCoeff() + (w - w_ref).cwiseAbs().maxCoeff() / 3.0;
  }
  // Fourth order: halving h divides the error by 16 (12..20 allows the O(h⁵) term of a non-symmetric method,
  // which still shows: 19.8 and 18.1 from h = 4e-3; errors 7.8e-9, 4.3e-10 at 2e-3, 1e-3). The projection
  // onto |RᵀR − I| and the joint is O(h⁵) per step and keeps it.
  EXPECT_NEAR(err[0] / err[1], 16.0, 4.0);
  EXPECT_NEAR(err[1] / err[2], 16.0, 4.0);
  EXPECT_GT(err[2], 1e-12);  // above round-off: the ratios measure the method
}

TEST(ProjectedRk4, FallingChainAgreesWithRattleOrderFourAtOrderFour) {
  // Another formulation of the same equations: RATTLE (position level, multipliers ν) composed to order 4,
  // at a step small enough to be the reference (its error ~1e-13 m here).
  const int n = 6;
  const System s = test::rod_chain(n);
  const double T = 1.0;
  State ref = test::rod_chain_state(n);
  RattleOptions options;
  options.order = 4;
  Rattle rattle(s, 1.25e-4, options);
  for (int k = 0; k < 8000; ++k)
    rattle.step(ref);
  auto error_at = [&](double h) {
    State st = test::rod_chain_state(n);
    ProjectedRk4 rk4(s, h);
    for (int k = 0; k < static_cast<int>(std::lround(T / h)); ++k)
      rk4.step(st);
    double e = 0.0;
    for (std::size_t i = 0; i < st.bodies.size(); ++i)
      e = std::max(e, (st.bodies[i].x_space - ref.bodies[i].x_space).norm());
    return e;
  };
  const double e1 = error_at(4e-3), e2 = error_at(2e-3);
  EXPECT_NEAR(e1 / e2, 16.0, 4.0);  // measured 16.2
  EXPECT_LT(e2, 1e-7);              // measured 4.1e-9 m after 1 s of the six-link whip
}

TEST(ProjectedRk4, ConstraintsStayAtRoundOffAndEnergyAtOrderFour) {
  // The 16-link chain falling from horizontal for 2 s (its free end whips through the lowest point).
  const int n = 16;
  const System s = test::rod_chain(n);
  State st = test::rod_chain_state(n);
  const double released = kG * n * n / 2.0;
  const double E0 = total_energy(s, st);
  double max_dE = 0, max_gap = 0, max_ortho = 0, max_velocity = 0;
  ProjectedRk4 rk4(s, 1e-3);
  for (int k = 0; k < 2000; ++k) {  // 2 s under sanitizers too (17 s there): 0.4 s fall short of the floor
    rk4.step(st);
    const ConstraintViolation v = constraint_violation(s, st);
    max_gap = std::max(max_gap, v.joint_gap);
    max_ortho = std::max(max_ortho, v.orthogonality);
    max_velocity = std::max(max_velocity, v.joint_velocity);
    max_dE = std::max(max_dE, std::abs(total_energy(s, st) - E0));
  }
  // The projection's tolerance is 1e-13 of the length scale on each component; the gap is a norm (√3).
  EXPECT_LT(max_gap, 2e-13 * s.length_scale());
  EXPECT_LT(max_ortho, 4e-15);     // Newton–Schulz to round-off
  EXPECT_LT(max_velocity, 1e-13);  // m/s: the velocity projection is exact
  // RK4's energy error: measured 1.9e-9 of the released energy (gap 5.4e-14 m, |RᵀR − I| 1.1e-15, joint
  // velocity 7.9e-15 m/s).
  EXPECT_LT(max_dE, 3e-8 * released);
  EXPECT_GT(max_dE, 1e-13 * released);  // not conserved by construction: the figure measures the method
}

TEST(ProjectedRk4, MultipliersAreTheExactOnesAtTheCurrentState) {
  // First same as last: the first stage of the next step is solved at the end of each step, and its solution
  // is exact_multipliers() of the state the step produced.
  const System s = test::rod_chain(5);
  State st = test::rod_chain_state(5);
  st.bodies[4].omega_body = Vec3(0, 0, 2.0);
  st.bodies[4].v_space = Vec3(0, 1.0, 0);
  project_velocities(s, st);
  ProjectedRk4 rk4(s, 2e-3);
  EXPECT_TRUE(rk4.multipliers().joint_force_space.empty());  // none before the first step
  for (int k = 0; k < 200; ++k) {
    rk4.step(st);
    if (k % 50 != 49) continue;
    const ExactMultipliers ex = exact_multipliers(s, st);
    const ExactMultipliers& got = rk4.multipliers();
    for (std::size_t j = 0; j < ex.joint_force_space.size(); ++j)
      EXPECT_LT((got.joint_force_space[j] - ex.joint_force_space[j]).norm(),
                1e-12 * (1 + ex.joint_force_space[j].norm()));
    for (std::size_t i = 0; i < ex.Lambda_body.size(); ++i) {
      EXPECT_LT((got.Lambda_body[i] - ex.Lambda_body[i]).norm(), 1e-12 * (1 + ex.Lambda_body[i].norm()));
      EXPECT_LT((got.omega_dot_body[i] - ex.omega_dot_body[i]).norm(),
                1e-11 * (1 + ex.omega_dot_body[i].norm()));
    }
  }
  // A state changed by the caller is noticed (the cached first stage is not reused for it).
  State other = test::rod_chain_state(5);
  rk4.step(other);
  const ExactMultipliers ex = exact_multipliers(s, other);
  EXPECT_LT((rk4.multipliers().joint_force_space[0] - ex.joint_force_space[0]).norm(),
            1e-12 * ex.joint_force_space[0].norm());
}

TEST(ProjectedRk4, ConicalPendulumKeepsItsClosedFormReaction) {
  // The steady conical pendulum, integrated for two revolutions: the reaction read after every step stays
  // the closed form m (Ω² ℓ sin θ inward + g ẑ) at the current position, to RK4's error (the orbit's phase
  // error is (Ωh)⁴-small; measured 7.2e-12 of mg).
  const test::Conical c;
  const System s = c.system();
  State st = c.state();
  ProjectedRk4 rk4(s, 1e-3);
  const int steps = static_cast<int>(2 * 2 * std::numbers::pi / c.Omega() / 1e-3);
  double err = 0.0;
  for (int k = 0; k < steps; ++k) {
    rk4.step(st);
    err = std::max(err, (rk4.multipliers().joint_force_space[0] - c.reaction(st.bodies[0].x_space)).norm());
  }
  EXPECT_LT(err, 1e-10 * c.m * kG);
}

TEST(ProjectedRk4, SpringPeriodIsTheClosedForm) {
  // A body on a spring to the world (no joint, no gravity): x'' = −(k/m) x, period 2π √(m/k). RK4's phase
  // error is (ωh)⁴/120 ≈ 5e-12 at ω = 5 rad/s, h = 1e-3.
  const double m = 2.0, k = 50.0;
  auto [s, st] = test::spring_oscillator(m, k);
  ProjectedRk4 rk4(s, 1e-3);
  const double period = 2 * std::numbers::pi * std::sqrt(m / k);
  // After exactly one period (rounded to the step) x returns to −0.1 cos(ω t).
  const int steps = static_cast<int>(std::lround(period / 1e-3));
  for (int n = 0; n < steps; ++n)
    rk4.step(st);
  const double expected = -0.1 * std::cos(std::sqrt(k / m) * st.time);
  EXPECT_NEAR(st.bodies[0].x_space.x(), expected, 1e-11);
}

TEST(ProjectedRk4, HingesAndClosedLoopsUseTheirSolversAndHold) {
  // A tree with a hinge (Baraff's tree order) and a spatial four-bar (a loop through the world: sparse LU),
  // against RATTLE order 4 at a quarter of the step: they agree to the methods' O(h⁴) errors.
  const auto [tree, tree_state] = test::hinge_tree();
  const auto [loop, loop_state] = test::four_bar_loop();
  for (const auto& [system, start, method] :
       {std::tuple{tree, tree_state, KktMethod::tree}, std::tuple{loop, loop_state, KktMethod::sparse_lu}}) {
    const double h = 2e-3;
    ProjectedRk4 rk4(system, h);
    EXPECT_EQ(rk4.kkt_method(), method);
    RattleOptions options;
    options.order = 4;
    Rattle rattle(system, h / 4, options);
    State a = start, b = start;
    double max_gap = 0.0, max_angle = 0.0;
    for (int k = 0; k < 500; ++k) {
      rk4.step(a);
      for (int r = 0; r < 4; ++r)
        rattle.step(b);
      const ConstraintViolation v = constraint_violation(system, a);
      max_gap = std::max(max_gap, v.joint_gap);
      max_angle = std::max(max_angle, v.joint_angle);
    }
    double diff = 0.0;
    for (std::size_t i = 0; i < a.bodies.size(); ++i)
      diff = std::max(diff, (a.bodies[i].x_space - b.bodies[i].x_space).norm());
    EXPECT_LT(diff, 1e-7) << kkt_method_name(method);  // measured 1.8e-8 (tree), 3.8e-11 (loop) m after 1 s
    EXPECT_LT(max_gap, 2e-13 * system.length_scale()) << kkt_method_name(method);  // √3 × the tolerance
    // The projection's tolerance (absolute on these rows), plus the rounding of recomputing them.
    EXPECT_LT(max_angle, 1.5e-13) << kkt_method_name(method);
  }
}

TEST(ProjectedRk4, StepsAllocateNothingOnTrees) {
  const auto [tree, tree_state] = test::hinge_tree();
  for (const auto& [system, start] :
       {std::pair{test::rod_chain(6), test::rod_chain_state(6)}, std::pair{tree, tree_state}}) {
    const long long before_construction = poinsot::test::allocation_count();
    ProjectedRk4 rk4(system, 1e-3);
    ASSERT_GT(poinsot::test::allocation_count(), before_construction);  // the counter is live
    State st = start;
    rk4.step(st);
    const long long before = poinsot::test::allocation_count();
    for (int k = 0; k < 50; ++k)
      rk4.step(st);
    EXPECT_EQ(poinsot::test::allocation_count() - before, 0) << kkt_method_name(rk4.kkt_method());
  }
}

TEST(ProjectedRk4, AFailedStepLeavesTheStateAsItWasAndBadInputIsRefused) {
  // A spinning free body whose step is so large that RK4 leaves the rotations (h|ω| = 3): the
  // orthonormalisation refuses it, and the state is restored.
  System s;
  s.add_body_from_inertia("spinner", 1.0, Vec3(1, 2, 2.5).asDiagonal());
  State st;
  st.bodies.resize(1);
  st.bodies[0].omega_body = Vec3(0.1, 0.2, 1.0);
  ProjectedRk4 rk4(s, 0.1);
  rk4.step(st);
  EXPECT_GT(rk4.multipliers().Lambda_body[0].norm(), 0.1);
  st.bodies[0].omega_body = Vec3(0, 0, 30.0);
  const State before = st;
  EXPECT_THROW(rk4.step(st), ComputationFailed);
  EXPECT_EQ(st.time, before.time);
  EXPECT_EQ(st.bodies[0].R_space_body, before.bodies[0].R_space_body);
  EXPECT_EQ(st.bodies[0].omega_body, before.bodies[0].omega_body);
  EXPECT_TRUE(rk4.multipliers().Lambda_body.empty());  // none from a failed step

  using poinsot::test::message_of;
  poinsot::test::expect_has(message_of([&] { ProjectedRk4(s, 0.0); }), {"dt", "0"});
  ProjectedRk4Options bad;
  bad.max_iterations = 0;
  poinsot::test::expect_has(message_of([&] { ProjectedRk4(s, 1e-3, bad); }), {"max_iterations", "0", ">= 1"});
  State two;
  two.bodies.resize(2);
  poinsot::test::expect_has(message_of([&] { rk4.step(two); }), {"state has 2 bodies", "expected 1"});
}

}  // namespace
}  // namespace poinsot::multibody
