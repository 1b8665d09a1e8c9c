// Boundary arcs of an active rate bound in the indirect method (src/optimal/rate_bound_shooting.*).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/verification.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

/// A sphere J = j I slewed through Θ about the cube diagonal (1, 1, 1)/√3 with |u_i| ≤ ū and |ω_i| ≤ r: by
/// symmetry the three axes move alike, each accelerating at ū/j to the bound r, coasting there, and braking:
/// T = Θ/(√3 r) + r j/ū whenever the coast exists (Θ/√3 > r² j/ū), against 2√(Θ j/(√3 ū)) without the bound.
ReorientationProblem diagonal_sphere(double j, double ubar, double r, double theta) {
  ReorientationProblem p;
  p.inertia_body = j * Mat3::Identity();
  p.torque_max = Vec3::Constant(ubar);
  p.rate_max = r;
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, Vec3::Ones().normalized()));
  return p;
}

TEST(RateBoundShooting, DiagonalSphereAcceleratesCoastsAndBrakes) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "about 1 s in release (the direct phase), a minute under ASan";
  const double j = 1.5, ubar = 0.8, r = 0.4, theta = 2.5;
  const ReorientationProblem p = diagonal_sphere(j, ubar, r, theta);
  CollocationOptions opt;
  opt.initial_intervals = 20;
  opt.mesh_tolerance = 1e-6;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const double T = theta / (std::sqrt(3.0) * r) + r * j / ubar;
  // Newton to 1e-12 on the scaled residual, RKF78 at 1e-13.
  EXPECT_NEAR(s.final_time / T, 1.0, 1e-11);
  ASSERT_EQ(s.rate_bound_arcs.size(), 3u);
  for (const auto& arc : s.rate_bound_arcs) {
    EXPECT_NEAR(arc.t_entry, r * j / ubar, 1e-10 * T);
    EXPECT_NEAR(arc.t_exit, T - r * j / ubar, 1e-10 * T);
    EXPECT_EQ(arc.side, 1.0);
  }
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_GE(v.rate_multiplier_min, 0.0);
  EXPECT_LE(v.rate_bound_excess, 1e-9);
}

}  // namespace
}  // namespace poinsot::optimal
