#include "poinsot/optimal/verification.hpp"

#include <gtest/gtest.h>

#include "optimal_test_problems.hpp"

namespace poinsot::optimal {
namespace {

// The checks pass on the minimum-energy sphere slew and catch a tampered solution: a torque history that is
// not the one the costates imply (the control no longer minimises H, and the replay misses the target).
TEST(Verification, PassesOnTheOptimumAndCatchesATamperedControl) {
  const auto p = testing::sphere_energy_problem(2.5, 2.0, Vec3(1.0, -2.0, 0.5), 3.0);
  const DirectSolution d = testing::sphere_direct_seed(p);
  IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const VerificationReport ok = verify(p, d, s);
  EXPECT_TRUE(ok.passed) << (ok.failures.empty() ? "" : ok.failures.front());
  EXPECT_LT(ok.hamiltonian_deviation, 1e-8);
  EXPECT_LT(ok.resimulated_attitude_error, 1e-6);  // piecewise-linear replay of a smooth control

  for (auto& u : s.torque_body)
    u *= 1.01;
  const VerificationReport bad = verify(p, d, s);
  EXPECT_FALSE(bad.passed);
  EXPECT_GT(bad.control_gap, 1e-6);
  EXPECT_GT(bad.resimulated_attitude_error, 1e-4);
}

TEST(Verification, ReportsAnUnsolvedIndirectProblem) {
  const auto p = testing::sphere_energy_problem(1.0, 1.0, Vec3::UnitZ(), 3.0);
  const VerificationReport r = verify(p, DirectSolution{}, IndirectSolution{});
  EXPECT_FALSE(r.passed);
  ASSERT_FALSE(r.failures.empty());
}

}  // namespace
}  // namespace poinsot::optimal
