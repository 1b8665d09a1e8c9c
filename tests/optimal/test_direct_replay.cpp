#include "poinsot/optimal/direct_replay.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::optimal {
namespace {

constexpr double kReplayJ = 2.5, kReplayTheta = 2.0, kReplayT = 3.0;

DirectSolution replay_sphere_solution(double mesh_tolerance) {
  CollocationOptions opt;
  opt.initial_intervals = 8;
  opt.mesh_tolerance = mesh_tolerance;
  return solve_direct(testing::sphere_energy_problem(kReplayJ, kReplayTheta, Vec3(1.0, -2.0, 0.5), kReplayT),
                      opt);
}

// The minimum-energy sphere: the collocated control, replayed by DOP853, reaches the target to about the
// mesh error (the transcription's state error), and the replay error falls with it.
TEST(DirectReplay, ReachesTheTargetToTheMeshError) {
  const auto p = testing::sphere_energy_problem(kReplayJ, kReplayTheta, Vec3(1.0, -2.0, 0.5), kReplayT);
  const DirectSolution coarse = replay_sphere_solution(1e-5), fine = replay_sphere_solution(1e-8);
  ASSERT_TRUE(coarse.converged && fine.converged) << coarse.status << " / " << fine.status;
  const DirectReplay a = replay_direct(p, coarse), b = replay_direct(p, fine);
  EXPECT_EQ(a.final_time, kReplayT);
  EXPECT_LT(a.scaled_error(), 1e2 * coarse.max_mesh_error);
  EXPECT_LT(b.scaled_error(), 1e2 * fine.max_mesh_error);
  EXPECT_LT(b.scaled_error(), 0.1 * a.scaled_error());
  EXPECT_LT(b.scaled_error(), direct_replay_tolerance);
}

// An independent check: the same samples with every torque scaled by 1.01 turn the sphere about the same
// fixed axis by 1.01 Θ (j ω̇ = u with u ∥ n, linear in u), so the replay misses by 0.01 Θ = 0.02 rad, and it
// ends at rest as the unscaled control does (∫u dt scales too).
TEST(DirectReplay, SeesAControlThatMissesTheTarget) {
  const auto p = testing::sphere_energy_problem(kReplayJ, kReplayTheta, Vec3(1.0, -2.0, 0.5), kReplayT);
  DirectSolution d = replay_sphere_solution(1e-8);
  ASSERT_TRUE(d.converged) << d.status;
  for (auto& u : d.torque_body)
    u *= 1.01;
  const DirectReplay r = replay_direct(p, d);
  EXPECT_NEAR(r.attitude_error, 0.01 * kReplayTheta, 1e-6);
  EXPECT_LT(r.rate_error, 1e-6);
  EXPECT_NEAR(r.scaled_error(), r.attitude_error, 1e-12);
}

TEST(DirectReplay, RefusesSamplesThatAreNotAMesh) {
  const auto p = testing::sphere_energy_problem(kReplayJ, kReplayTheta, Vec3::UnitZ(), kReplayT);
  DirectSolution d;
  EXPECT_THROW(replay_direct(p, d), InvalidInput);
  d.time = {0.0, 2.0, 1.0};
  d.attitude.assign(3, Quat::Identity());
  d.omega_body.assign(3, Vec3::Zero());
  d.torque_body.assign(3, Vec3::Zero());
  d.final_time = 1.0;
  EXPECT_THROW(replay_direct(p, d), InvalidInput);
}

}  // namespace
}  // namespace poinsot::optimal
