// Unequal meshes and mesh refinement for the multibody transcriptions: the rod on a hinge, whose
// minimum-energy motion (θ cubic, u linear) Hermite–Simpson reproduces exactly on any mesh, and the
// refinement of the two-link arm against its fine-mesh cost.
#include "poinsot/optimal/multibody_refinement.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

TEST(MultibodyRefinement, UnequalMeshIsExactForTheCubicMotion) {
  // The rod from rest at 0 to rest at Θ in T: cost 12 I² Θ² / T³, u = 6IΘ/T² (1 − 2t/T) (cubic θ: Hermite–
  // Simpson is exact on any mesh). Ipopt's tolerance 1e-10 bounds the difference.
  MultibodyProblem p = testing::single_hinge(1.2, 2.0, 4);
  p.mesh = {0.1, 0.2, 0.3, 0.4};
  const MultibodyOptimum r = testing::solve_in(p, MultibodyCoordinates::minimal);
  ASSERT_TRUE(r.converged) << r.status;
  const double I = testing::single_hinge_inertia();
  EXPECT_NEAR(r.cost, 12.0 * I * I * 1.44 / 8.0, 1e-9 * r.cost);
  EXPECT_DOUBLE_EQ(r.time[2], 0.2);  // the first node, 0.1 T
  EXPECT_DOUBLE_EQ(r.time[3], 0.4);  // the second interval's midpoint, (0.1 + 0.1) T
  // control_at on the unequal mesh: the linear closed form at points between the collocation points.
  for (const double t : {0.05, 0.33, 0.61, 1.0, 1.77, 1.99})
    EXPECT_NEAR(control_at(r, t)(0), 6.0 * I * 1.2 / 4.0 * (1.0 - t), 1e-7) << t;
  p.mesh = {0.5, 0.5, 0.5, -0.5};
  EXPECT_THROW(validate(p), InvalidInput);
  p.mesh = {0.5, 0.5};
  try {
    validate(p);
    ADD_FAILURE();
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("mesh: got 2 fractions"), std::string::npos) << e.what();
  }
}

TEST(MultibodyRefinement, ArmIntervalsAreSplitUntilTheLocalErrorMeetsTheTolerance) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "3.6 s in release, 142 s under ASan; the unequal-mesh test runs the same transcription there";
  // The arm (minimal coordinates) from 8 equal intervals, tolerance 1e-3 rad on each interval's local error.
  // Measured: N = 8, 22 with largest local errors 1.4e-1, 7.9e-4 rad; on 22 equal intervals the largest is
  // 5.1e-3 and the re-simulation misses the target by 1.6e-1 rad against 2.0e-2 on the refined mesh (costs
  // 39.2913 and 39.3472 N²·m²·s; 39.35276577 on 128 equal intervals).
  const MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 8);
  MultibodyOptions o;
  o.coordinates = MultibodyCoordinates::minimal;
  const MultibodyRefinement r = refine_multibody(p, o, 1e-3);
  ASSERT_TRUE(r.tolerance_met) << r.optimum.status;
  ASSERT_GE(r.rounds.size(), 2u);
  for (std::size_t k = 1; k < r.rounds.size(); ++k) {
    EXPECT_LT(r.rounds[k].max_error, r.rounds[k - 1].max_error);
    EXPECT_GT(r.rounds[k].intervals, r.rounds[k - 1].intervals);
  }
  EXPECT_EQ(r.problem.intervals, r.rounds.back().intervals);
  EXPECT_LE(r.rounds.back().max_error, 1e-3);
  // Against equal intervals of the same number: a smaller largest local error and a re-simulation closer to
  // the target.
  const MultibodyProblem q = testing::two_link_arm(1.0, 0.5, 1.5, r.problem.intervals);
  const MultibodyOptimum equal = solve_multibody(q, o);
  ASSERT_TRUE(equal.converged) << equal.status;
  const std::vector<double> errors = interval_errors(q, equal);
  const MultibodyReplay refined = replay_controls(r.problem, r.optimum, 64);
  const MultibodyReplay uniform = replay_controls(q, equal, 64);
  EXPECT_GT(*std::max_element(errors.begin(), errors.end()), r.rounds.back().max_error);
  EXPECT_LT(refined.attitude_error, uniform.attitude_error);
  EXPECT_LT(refined.max_joint_gap, 1e-12);
}

TEST(MultibodyRefinement, RefusesABadTolerance) {
  const MultibodyProblem p = testing::single_hinge(1.2, 2.0, 4);
  EXPECT_THROW(refine_multibody(p, {}, 0.0), InvalidInput);
  EXPECT_THROW(refine_multibody(p, {}, 1e-3, -1), InvalidInput);
}

}  // namespace
}  // namespace poinsot::optimal
