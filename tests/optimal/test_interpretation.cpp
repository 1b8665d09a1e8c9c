#include "poinsot/optimal/interpretation.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "optimal_test_problems.hpp"

namespace poinsot::optimal {
namespace {

// The minimum-energy sphere slew is the eigenaxis cubic: no saving over the eigenaxis manoeuvre. With
// ω = θ̇ n and K = j/2 I, sym Λ = (j/2) θ̇² (n⊗n − I), so ∫σ dv has principal values (j/2)θ̇² (0, 1, 1):
// Tresca (j/4)θ̇², von Mises (j/2)θ̇², largest at θ̇ = 3Θ/(2T), s = ½. Samples fall within 1/126 of s = ½,
// so the peaks are matched to 1e-3 relative. The trace of ∫σ dv is 2 × kinetic energy (virial,
// docs/conventions.md, (6.1)).
TEST(Interpretation, SphereSlewStressAndEigenaxis) {
  const double j = 2.5, theta = 2.0, T = 3.0;
  const auto p = testing::sphere_energy_problem(j, theta, Vec3(1.0, -2.0, 0.5), T);
  CollocationOptions opt;
  opt.initial_intervals = 10;
  opt.mesh_tolerance = 1e-6;
  const DirectSolution d = solve_direct(p, opt);
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  const ManoeuvreInterpretation m = interpret(p, s);
  ASSERT_TRUE(m.eigenaxis_available);
  EXPECT_NEAR(m.saving, 0.0, 1e-10);
  const double rate = 1.5 * theta / T;
  EXPECT_NEAR(m.peak_tresca / (0.25 * j * rate * rate), 1.0, 1e-3);
  EXPECT_NEAR(m.peak_von_mises / (0.5 * j * rate * rate), 1.0, 1e-3);
  EXPECT_NEAR(m.peak_tresca_time, 0.5 * T, T / 60.0);
  for (std::size_t k = 0; k < s.time.size(); ++k) {
    const double kinetic = 0.5 * j * s.omega_body[k].squaredNorm();
    EXPECT_NEAR(m.stress_space[k].trace(), 2.0 * kinetic, 1e-12 * (1.0 + kinetic));
    // L = R J ω for a sphere slewing about n: parallel to the fixed space axis R_0 n = n.
    EXPECT_LT(m.momentum_space[k].cross(Vec3(1.0, -2.0, 0.5).normalized()).norm(), 1e-9);
  }
}

}  // namespace
}  // namespace poinsot::optimal
