// Path constraints on hinge rates, |q̇| ≤ r, in both multibody transcriptions: the rate rows against the
// state's relative angular velocity, and the rate-bounded rest-to-rest turn of one rod against its closed
// form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "../../src/optimal/multibody_minimal_model.hpp"
#include "../../src/optimal/multibody_rate_rows.hpp"
#include "../../src/optimal/multibody_rotation_model.hpp"
#include "multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

TEST(MultibodyRateBounds, RowsAreTheHingeRatesInBothCoordinates) {
  // The arm moving at (θ̇1, θ̇2) = (0.7, −1.3) rad/s: the shoulder's rate is θ̇1 and the elbow's θ̇2 (both hinges
  // about +z), whichever coordinates the point variables are in.
  MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 4);
  p.rate_bounds = {{0, 5.0}, {1, 5.0}};
  const multibody::State s = testing::two_link_state(-0.4, 0.9, 0.7, -1.3);
  EXPECT_NEAR(hinge_rate(p.system, s, 0), 0.7, 1e-15);
  EXPECT_NEAR(hinge_rate(p.system, s, 1), -1.3, 1e-15);

  const detail::MultibodyMinimalModel minimal(p);
  const detail::MultibodyRotationModel rotation(p);
  const detail::QuadraticFunctions qm = detail::minimal_rate_rows(p, minimal);
  const detail::QuadraticFunctions qr = detail::rotation_rate_rows(p, rotation);
  Eigen::VectorXd wm = Eigen::VectorXd::Zero(minimal.point_size());
  wm.head(minimal.state_size()) = minimal.state_vector(s);
  Eigen::VectorXd wr = Eigen::VectorXd::Zero(rotation.point_size());
  wr.head(rotation.state_size()) = rotation.state_vector(s);
  double gm[2], gr[2];
  qm.values(wm.data(), gm);
  qr.values(wr.data(), gr);
  // Round-off of the rotation products (a few ulps of rates of order 1).
  for (int j = 0; j < 2; ++j) {
    EXPECT_NEAR(gm[j], j == 0 ? 0.7 : -1.3, 1e-14);
    EXPECT_NEAR(gr[j], j == 0 ? 0.7 : -1.3, 1e-14);
  }
}

/// One rod on a motor hinge, rest at 0 to rest at Θ in T, |θ̇| ≤ r with Θ/T < r < 3Θ/(2T) (the bound cuts the
/// unconstrained optimum's peak rate 3Θ/(2T)). With I θ̈ = u the optimum accelerates on [0, t₁] with u linear
/// and u(t₁) = 0 (the control is continuous at the junction of a first-order state constraint), coasts at r,
/// and decelerates symmetrically: θ̇(t₁) = r and the angle balance 2·(2rt₁/3) + r(T − 2t₁) = Θ give
/// t₁ = 3(rT − Θ)/(2r) and the cost 2∫₀^t₁ u² = 8I²r²/(3t₁) = 16 I² r³ / (9 (rT − Θ)). At r = 3Θ/(2T) this is
/// the unconstrained 12 I² Θ² / T³.
double bounded_cost(double theta, double T, double r) {
  const double I = testing::single_hinge_inertia();
  return 16.0 * I * I * r * r * r / (9.0 * (r * T - theta));
}

MultibodyOptimum solve_bounded(double r, int intervals, MultibodyCoordinates c) {
  MultibodyProblem p = testing::single_hinge(1.2, 2.0, intervals);
  p.rate_bounds = {{0, r}};
  MultibodyOptions o;
  o.coordinates = c;
  return solve_multibody(p, o);
}

double peak_rate(const MultibodyOptimum& m) {
  double peak = 0.0;
  for (const multibody::State& s : m.states)
    peak = std::max(peak, std::abs(s.bodies[0].omega_body.z()));
  return peak;
}

TEST(MultibodyRateBounds, BoundedTurnMinimalCoordinatesAreExact) {
  // r = 0.75 rad/s (the unconstrained peak is 0.9): t₁ = 0.6 s, a node of the 10-interval mesh, as is T − t₁;
  // θ is a cubic on every interval and u linear, so Hermite–Simpson is exact. What remains is Ipopt's: it
  // relaxes every bound by bound_relax_factor = 1e-8 (absolute here), and the cost falls with the bound at |d
  // ln C/dr| = |3/r − T/(rT − Θ)| = 2.7 s/rad, so the cost is 2.7e-8 below the closed form (measured 2.6e-8);
  // 1e-7 asked, and the rate may exceed r by that 1e-8 (2e-8 asked).
  const double r = 0.75;
  const MultibodyOptimum m = solve_bounded(r, 10, MultibodyCoordinates::minimal);
  ASSERT_TRUE(m.converged) << m.status;
  EXPECT_NEAR(m.cost / bounded_cost(1.2, 2.0, r), 1.0, 1e-7);
  EXPECT_GT(m.cost, testing::single_hinge_inertia() * testing::single_hinge_inertia() * 12 * 1.44 / 8);
  // Respected at every point (to Ipopt's bound relaxation) and active on the coast.
  EXPECT_LT(peak_rate(m), r + 2e-8);
  EXPECT_GT(peak_rate(m), r * (1.0 - 1e-8));
}

TEST(MultibodyRateBounds, BoundedTurnRotationMatrixCoordinates) {
  // In R-coordinates the rate is bilinear in (R, V) and the motion is not polynomial: the cost converges at
  // Hermite–Simpson's order (measured −1.2e-5 relative at N = 10; 1e-4 asked), the bound holds at every point
  // to Ipopt's bound relaxation (1e-8) and is active, and the re-simulation reaches the target.
  const double r = 0.75;
  const MultibodyOptimum m = solve_bounded(r, 10, MultibodyCoordinates::rotation_matrix);
  ASSERT_TRUE(m.converged) << m.status;
  EXPECT_NEAR(m.cost / bounded_cost(1.2, 2.0, r), 1.0, 1e-4);
  EXPECT_LT(peak_rate(m), r + 2e-8);  // Ipopt's bound relaxation, 1e-8 (see above)
  EXPECT_GT(peak_rate(m), r * (1.0 - 1e-6));
  MultibodyProblem p = testing::single_hinge(1.2, 2.0, 10);
  p.rate_bounds = {{0, r}};
  const MultibodyReplay replay = replay_controls(p, m, 32);
  EXPECT_LT(replay.attitude_error, 1e-2);
  EXPECT_LT(replay.max_joint_gap, 1e-12);
}

TEST(MultibodyRateBounds, ArmShoulderBoundIsActiveAndRespected) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "about 2 s in release, 12 s under ASan; BoundedTurnMinimalCoordinatesAreExact covers the "
                    "rate rows there";
  // The arm of the tests, minimal coordinates, 8 intervals: the shoulder's rate bounded at 80 % of its
  // unconstrained peak. The bound is active and respected at every point, and the cost rises.
  MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 8);
  MultibodyOptions o;
  o.coordinates = MultibodyCoordinates::minimal;
  const MultibodyOptimum free = solve_multibody(p, o);
  ASSERT_TRUE(free.converged) << free.status;
  double peak = 0.0;
  for (const multibody::State& s : free.states)
    peak = std::max(peak, std::abs(hinge_rate(p.system, s, 0)));
  p.rate_bounds = {{0, 0.8 * peak}};
  const MultibodyOptimum bounded = solve_multibody(p, o);
  ASSERT_TRUE(bounded.converged) << bounded.status;
  double bounded_peak = 0.0;
  for (const multibody::State& s : bounded.states)
    bounded_peak = std::max(bounded_peak, std::abs(hinge_rate(p.system, s, 0)));
  EXPECT_LT(bounded_peak, 0.8 * peak * (1.0 + 2e-8));  // Ipopt's bound relaxation, 1e-8·max(1, |r|)
  EXPECT_GT(bounded_peak, 0.8 * peak * (1.0 - 1e-6));
  EXPECT_GT(bounded.cost, free.cost);
}

TEST(MultibodyRateBounds, BadBoundsAreOneLine) {
  MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 4);
  p.rate_bounds = {{0, 0.0}};
  EXPECT_THROW(validate(p), InvalidInput);
  try {
    validate(p);
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("rate_bounds[0]: rate_max: got 0 rad/s"), std::string::npos)
        << e.what();
  }
  p.rate_bounds = {{7, 1.0}};
  EXPECT_THROW(validate(p), InvalidInput);
  // A target moving faster than the bound.
  p.final_state = testing::two_link_state(-0.5, 0.5, 2.0, 0.0);
  p.rate_bounds = {{0, 1.0}};
  try {
    validate(p);
    ADD_FAILURE() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("the final state's rate 2 rad/s exceeds the bound 1 rad/s"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace poinsot::optimal
