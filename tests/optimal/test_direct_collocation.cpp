#include "poinsot/optimal/direct_collocation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::optimal {
namespace {

TEST(DirectCollocation, SphereMinimumEnergyIsTheEigenaxisCubic) {
  const double j = 2.5, theta = 2.0, T = 3.0;
  const Vec3 axis(1.0, -2.0, 0.5);
  const auto p = testing::sphere_energy_problem(j, theta, axis, T);
  CollocationOptions opt;
  opt.initial_intervals = 8;
  opt.mesh_tolerance = 1e-10;
  const DirectSolution s = solve_direct(p, opt);
  ASSERT_TRUE(s.converged) << s.status;
  const double exact = 12.0 * j * j * theta * theta / (T * T * T);
  std::printf("cost %.15g exact %.15g rel %.3g intervals %zu mesh its %d nlp its %d\n", s.cost, exact,
              s.cost / exact - 1, s.node_time.size() - 1, s.mesh_iterations, s.nlp_iterations);
  EXPECT_NEAR(s.cost / exact, 1.0, 1e-10);
}

TEST(DirectCollocation, BettsCoarse) {
  CollocationOptions opt;
  opt.initial_intervals = 20;
  opt.mesh_tolerance = 1e-6;
  opt.print_level = 0;
  const DirectSolution s = solve_direct(testing::betts_problem(), opt);
  std::printf("T %.12g rel %.3g intervals %zu mesh its %d nlp its %d status %s maxerr %.3g\n", s.final_time,
              s.final_time / testing::kBettsPublishedTime - 1, s.node_time.size() - 1, s.mesh_iterations,
              s.nlp_iterations, s.status.c_str(), s.max_mesh_error);
  double wmax = 0;
  for (auto& w : s.omega_body)
    wmax = std::max(wmax, w.cwiseAbs().maxCoeff());
  std::printf("max |w| %.6g\n", wmax);
  EXPECT_TRUE(s.converged);
}

}  // namespace
}  // namespace poinsot::optimal
