// Keep-out and keep-in cones (pointing_constraint.hpp) in the direct method, the indirect method and the
// verification, against closed forms: the quadratic form against Eigen's rotation, and the minimum-energy
// slew of a sphere, whose free optimum (the eigenaxis rotation, cost 12 j² Θ² / T³) a cone either misses (the
// optimum is unchanged) or crosses (a detour whose cost rises continuously from the free one).
#include "poinsot/optimal/pointing_constraint.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/direct_replay.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/verification.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

constexpr double kPi = std::numbers::pi;

// qᵀAq = sᵀR(q)b for any q (R of q/‖q‖ times ‖q‖²: the form is homogeneous), and the angle by atan2.
TEST(PointingConstraint, QuadraticFormIsTheCosineOfTheBoresightAngle) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    PointingConstraint c;
    c.boresight_body = Vec3(n(rng), n(rng), n(rng)).normalized();
    c.direction_space = Vec3(n(rng), n(rng), n(rng)).normalized();
    c.half_angle = 0.4;
    const Eigen::Vector4d q(n(rng), n(rng), n(rng), n(rng));
    const Quat unit = Quat(q[0], q[1], q[2], q[3]).normalized();
    const double cosine = c.direction_space.dot(unit.toRotationMatrix() * c.boresight_body);
    EXPECT_NEAR(q.dot(c.quadratic_form() * q), q.squaredNorm() * cosine, 1e-13 * q.squaredNorm());
    EXPECT_NEAR(std::cos(c.angle(unit)), cosine, 1e-14);
    EXPECT_NEAR(c.margin(unit), c.angle(unit) - 0.4, 1e-15);
    c.kind = PointingKind::keep_in;
    EXPECT_NEAR(c.margin(unit), 0.4 - c.angle(unit), 1e-15);
    EXPECT_NEAR(c.widened(0.1).half_angle, 0.3, 1e-15);
  }
}

// The sphere J = j I turned rest to rest by Θ = 150° about z in T at minimum energy: the free optimum turns
// the boresight x in the xy plane, through the direction at Θ/2 from x at T/2. The Sun lies α above that
// direction, so the free path passes α from it: a keep-out cone narrower than α is never touched, a wider
// one is.
constexpr double kJ = 2.0, kTheta = 150.0 * kPi / 180.0, kT = 4.0, kAlpha = 0.3;

ReorientationProblem sun_problem(double half_angle) {
  ReorientationProblem p = testing::sphere_energy_problem(kJ, kTheta, Vec3::UnitZ(), kT);
  const Vec3 halfway(std::cos(kTheta / 2), std::sin(kTheta / 2), 0.0);
  const Vec3 sun = std::cos(kAlpha) * halfway + std::sin(kAlpha) * Vec3::UnitZ();
  if (half_angle > 0.0) p.pointing.push_back({"sun", PointingKind::keep_out, Vec3::UnitX(), sun, half_angle});
  return p;
}

double free_cost() {
  return 12.0 * kJ * kJ * kTheta * kTheta / (kT * kT * kT);
}

DirectSolution solve_sun(double half_angle) {
  CollocationOptions opt;
  opt.initial_intervals = 16;
  opt.mesh_tolerance = 1e-8;
  return solve_direct(sun_problem(half_angle), opt);
}

// A cone the free optimum stays 0.05 rad clear of: the indirect method runs, the verification passes with a
// positive margin, and the optimum is the free one to the shooting's accuracy.
TEST(PointingConstraint, AConeTheFreeOptimumMissesLeavesItUnchanged) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "two solves on 212 intervals, 4 s in release and 37 s under ASan; the command-line test of "
           "the same slew (tests/cli/test_cli_optimize_pointing.py) runs the whole pipeline there";
  const ReorientationProblem p = sun_problem(kAlpha - 0.05);
  const DirectSolution d = solve_sun(kAlpha - 0.05);
  ASSERT_TRUE(d.converged) << d.status;
  const DirectReplay dr = replay_direct(p, d);
  EXPECT_EQ(d.pointing_widening, 0.0)
      << "replay margin " << dr.pointing.margin[0] << " at " << dr.pointing.time[0] << " intervals "
      << d.node_time.size() << " err " << dr.scaled_error();
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_NEAR(v.pointing.margin[0], 0.05, 1e-6);  // the closest approach, at T/2
  EXPECT_NEAR(v.pointing.time[0], kT / 2, 0.1);
  EXPECT_NEAR(s.cost / free_cost(), 1.0, 1e-10);
  const DirectSolution free = solve_sun(0.0);
  const IndirectSolution s_free = solve_indirect(sun_problem(0.0), free);
  ASSERT_TRUE(s_free.converged) << s_free.status;
  EXPECT_NEAR(s.cost / s_free.cost, 1.0, 1e-10);
  // The inactive cone's multipliers vanish (interior point: μ/slack at μ ≈ 1e-11).
  for (const double y : d.pointing_multiplier[0])
    EXPECT_LT(std::abs(y), 1e-9);
}

// Cones that cross the free path: the detour's cost rises with the half-angle, continuously from the free
// cost at θ = α (an intrusion ε displaces the path by O(ε), at a cost O(ε²)); the cone holds on the dense
// replay to 1e-9 rad; the indirect method refuses the active arc, so nothing is called optimal; the
// multipliers are positive on the active set and zero off it.
TEST(PointingConstraint, AConeAcrossThePathForcesADetourWhoseCostRisesContinuously) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP()
        << "three solves, 4 s in release and a minute under ASan; AConeTheFreeOptimumMissesLeavesItUnchanged "
           "runs the same code there";
  double previous_rise = 0.0;
  double rises[3] = {0, 0, 0};
  const double intrusions[3] = {0.01, 0.05, 0.15};
  for (int i = 0; i < 3; ++i) {
    const double theta = kAlpha + intrusions[i];
    const ReorientationProblem p = sun_problem(theta);
    const DirectSolution d = solve_sun(theta);
    ASSERT_TRUE(d.nlp_solved) << d.status;
    const DirectReplay replay = replay_direct(p, d);
    EXPECT_GE(replay.pointing.margin[0], -pointing_replay_tolerance) << "θ = " << theta;
    EXPECT_LT(replay.scaled_error(), direct_replay_tolerance);
    const IndirectSolution s = solve_indirect(p, d);
    EXPECT_FALSE(s.converged);
    EXPECT_TRUE(s.status.starts_with("not applied: the keep_out \"sun\" cone is active")) << s.status;
    rises[i] = d.cost / free_cost() - 1.0;
    EXPECT_GT(rises[i], previous_rise) << "θ = " << theta;
    previous_rise = rises[i];
    double largest = 0.0;
    for (const double y : d.pointing_multiplier[0])
      largest = std::max(largest, y);
    EXPECT_GT(largest, 0.0);
    // Complementarity y (cos θ' − c) = 0, θ' the widened half-angle: Ipopt meets it to its tolerance 1e-10
    // scaled by the mean multiplier (the defects' are O(10³) here), about 3e-7 of the largest cone
    // multiplier on this problem; so y vanishes off the active set, up to the barrier's μ/slack.
    const double cos_widened = std::cos(theta + d.pointing_widening);
    for (std::size_t k = 1; k < d.time.size(); ++k) {
      const double y = d.pointing_multiplier[0][k];
      const double slack = cos_widened - p.pointing[0].cosine(d.attitude[k]);
      EXPECT_GE(y, -1e-9 * largest);
      EXPECT_LT(std::abs(y * slack), 1e-6 * largest) << "t = " << d.time[k];
      const bool off_the_active_set = p.pointing[0].margin(d.attitude[k]) - d.pointing_widening > 1e-2;
      EXPECT_TRUE(!off_the_active_set || y < 1e-6 * largest)
          << "t = " << d.time[k] << ": multiplier " << y << " of " << largest;
    }
  }
  // The rise grows as ε² from the touching angle (the multiplier, dJ/dθ, starts from 0 there): its exponent
  // between ε = 0.01 and 0.05 rad.
  const double exponent = std::log(rises[1] / rises[0]) / std::log(intrusions[1] / intrusions[0]);
  EXPECT_NEAR(exponent, 2.0, 0.3);
}

// The cones are widened where the replay of a mesh's solution crosses them between the collocation points,
// and the meshes of the widened solves are handed to CollocationOptions::accept_mesh with the widening they
// were solved with: what active_pointing_constraint (and the shooting's refusal) measures the margin from.
// Seen with a widening of 0, a solution on the widened edge of an active cone would pass for clear of it.
TEST(PointingConstraint, AcceptMeshSeesTheWideningOfEachMesh) {
  const double theta = kAlpha + 0.05;
  const ReorientationProblem p = sun_problem(theta);
  CollocationOptions opt;
  opt.initial_intervals = 16;
  opt.mesh_tolerance = 1e-8;
  std::vector<double> widenings;
  std::vector<bool> active;
  opt.accept_mesh = [&](const DirectSolution& d) -> std::optional<std::string> {
    widenings.push_back(d.pointing_widening);
    active.push_back(!active_pointing_constraint(p, d).empty());
    // Stopped above the tolerance, each widened solve starts from a mesh that is not converged either.
    return d.max_mesh_error <= 1e-4 ? std::optional<std::string>("a reason of the caller's") : std::nullopt;
  };
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.nlp_solved) << d.status;
  ASSERT_GT(d.pointing_widening, 0.0) << "the test needs a widened solve";
  ASSERT_FALSE(widenings.empty());
  EXPECT_EQ(widenings.front(), 0.0);  // the first solve: the cones as given
  std::size_t widened = 0;
  for (std::size_t k = 0; k < widenings.size(); ++k) {
    EXPECT_TRUE(active[k]) << "mesh " << k << ", widening " << widenings[k];
    EXPECT_LE(widenings[k], d.pointing_widening);  // a widening only grows
    if (widenings[k] > 0.0) ++widened;
  }
  EXPECT_GT(widened, 0U) << "no mesh of the widened solves reached accept_mesh";
}

// Keep-in: the boresight x must stay within 80° of x while the body turns 150° about z at minimum energy
// (the free path ends 150° away): the final attitude violates it, which validation refuses; a cone about the
// final boresight direction that the start meets too is accepted.
TEST(PointingConstraint, ValidationNamesTheConeThatTheEndsViolate) {
  ReorientationProblem p = sun_problem(0.0);
  p.pointing.push_back({"", PointingKind::keep_in, Vec3::UnitX(), Vec3::UnitX(), 80.0 * kPi / 180.0});
  try {
    validate(p);
    FAIL() << "accepted a final attitude outside the keep-in cone";
  } catch (const InvalidInput& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("optimal_control.keep_in[1]: ")) << e.what();
    EXPECT_NE(std::string(e.what()).find("final attitude"), std::string::npos) << e.what();
  }
  p.pointing.back().half_angle = 170.0 * kPi / 180.0;
  EXPECT_NO_THROW(validate(p));
  p.pointing.push_back({"sun", PointingKind::keep_out, Vec3::UnitX(), Vec3::UnitX(), 0.1});
  try {
    validate(p);
    FAIL() << "accepted an initial boresight inside a keep-out cone";
  } catch (const InvalidInput& e) {
    EXPECT_TRUE(std::string(e.what()).starts_with("optimal_control.keep_out[1]: ")) << e.what();
    EXPECT_NE(std::string(e.what()).find("initial attitude"), std::string::npos) << e.what();
  }
  p.pointing.back().direction_space = Vec3::Zero();
  EXPECT_THROW(validate(p), InvalidInput);
  p.pointing.back().direction_space = Vec3::UnitY();
  p.pointing.back().half_angle = kPi;
  EXPECT_THROW(validate(p), InvalidInput);
}

}  // namespace
}  // namespace poinsot::optimal
