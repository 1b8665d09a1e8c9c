#include "poinsot/optimal/indirect_shooting.hpp"

#include <gtest/gtest.h>

#include "optimal_test_problems.hpp"
#include "poinsot/optimal/verification.hpp"

namespace poinsot::optimal {
namespace {

TEST(IndirectShooting, Betts) {
  CollocationOptions opt;
  opt.initial_intervals = 20;
  opt.mesh_tolerance = 1e-6;
  const auto p = testing::betts_problem();
  const DirectSolution d = solve_direct(p, opt);
  ASSERT_TRUE(d.converged);
  const IndirectSolution s = solve_indirect(p, d);
  std::printf("status %s T %.12f rel %.3g its %d res %.3g\n", s.status.c_str(), s.final_time,
              s.final_time / testing::kBettsPublishedTime - 1, s.iterations, s.residual);
  for (std::size_t k = 0; k < s.switch_times.size(); ++k)
    std::printf("switch u%d at %.12f\n", s.switch_axes[k] + 1, s.switch_times[k]);
  EXPECT_TRUE(s.converged);
  const VerificationReport v = verify(p, d, s);
  std::printf("H %.3g dev %.3g gap %.3g viol %d drift %.3g orth %.3g lam %.3g resim %.3g %.3g di %.3g\n",
              v.hamiltonian_mean, v.hamiltonian_deviation, v.control_gap, v.switching_sign_violations,
              v.costate_drift, v.orthogonality, v.lambda_torque_error, v.resimulated_attitude_error,
              v.resimulated_rate_error, v.direct_indirect_difference);
  for (auto& f : v.failures)
    std::printf("FAIL %s\n", f.c_str());
}

}  // namespace
}  // namespace poinsot::optimal
