// Ball joints in the minimal-coordinate model (a relative quaternion and the relative angular velocity), on
// the falling cat of multibody_test_problems.hpp (two cylinders on a ball joint, free floating: the front
// half the base, the back half hung from the waist, whose body_a is the front): the Lagrangian against the
// kinetic energy and the forward dynamics against the multibody layer's projected RK4.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/Cholesky>

#include "../../src/optimal/multibody_minimal_model.hpp"
#include "minimal_model_rk4.hpp"
#include "multibody_test_problems.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

/// The bent cat tumbling: the front turned by e₀, ω₀ = (0.4, −0.3, 0.6) rad/s, the back turned at the waist
/// by the quaternion (0.95, 0.1, −0.2, 0.15) (normalised) with the relative rate ν = (1.1, 0.5, −0.7) rad/s,
/// the centre of mass at rest (a consistent state by construction).
MultibodyProblem tumbling_cat() {
  MultibodyProblem p = testing::falling_cat(0.5, std::numbers::pi, 1.0, 8);
  const detail::MultibodyMinimalModel model(p);
  const detail::MinimalTree& tree = model.tree();
  Eigen::VectorXd w = Eigen::VectorXd::Zero(model.point_size());
  w.head<4>() = Eigen::Vector4d(0.9, 0.2, -0.3, 0.25).normalized();
  w.segment<4>(tree.links[1].q) = Eigen::Vector4d(0.95, 0.1, -0.2, 0.15).normalized();
  w.segment<3>(tree.positions) = Vec3(0.4, -0.3, 0.6);
  w.segment<3>(tree.links[1].v) = Vec3(1.1, 0.5, -0.7);
  p.initial_state = model.state_of(w.data(), 0.0);
  return p;
}

TEST(MultibodyMinimalBall, MassMatrixIsTheKineticEnergys) {
  // As for the floating wheel (test_multibody_floating_base.cpp): ½ νᵀMν is the kinetic energy of the decoded
  // state, M symmetric positive definite (6 × 6: the base's ω₀ and the waist's ν), the round trip exact.
  const MultibodyProblem p = tumbling_cat();
  const detail::MultibodyMinimalModel model(p);
  ASSERT_TRUE(model.tree().floating);
  ASSERT_TRUE(model.tree().links[1].ball);
  const Eigen::VectorXd y = model.state_vector(p.initial_state);
  Eigen::MatrixXd M;
  Eigen::VectorXd bias;
  model.equations_of_motion(y, Eigen::VectorXd::Zero(3), M, bias);
  ASSERT_EQ(M.rows(), 6);
  EXPECT_LT((M - M.transpose()).norm(), 1e-13 * M.norm());
  // M − 1e-3 I has a Cholesky factor exactly when M's least eigenvalue is above 1e-3.
  const Eigen::MatrixXd shifted = M - 1e-3 * Eigen::MatrixXd::Identity(M.rows(), M.cols());
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(shifted).info(), Eigen::Success);
  const Eigen::VectorXd nu = y.tail(6);
  const multibody::State s = model.state_of(y.data(), 0.0);
  EXPECT_NEAR(0.5 * nu.dot(M * nu), multibody::kinetic_energy(p.system, s), 1e-13);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT((s.bodies[i].R_space_body - p.initial_state.bodies[i].R_space_body).norm(), 1e-14);
    EXPECT_LT((s.bodies[i].x_space - p.initial_state.bodies[i].x_space).norm(), 1e-14);
    EXPECT_LT((s.bodies[i].omega_body - p.initial_state.bodies[i].omega_body).norm(), 1e-14);
    EXPECT_LT((s.bodies[i].v_space - p.initial_state.bodies[i].v_space).norm(), 1e-14);
  }
}

TEST(MultibodyMinimalBall, ForwardDynamicsIsTheProjectedRk4s) {
  // The tumbling cat driven by the waist's τ(t) = (3 sin 2t, 2 cos 3t, −sin t)/100 N·m for 1 s: the model's
  // forward dynamics by RK4 against the projected RK4 (replay_controls) on the same steps with the same held
  // controls (see test_multibody_floating_base.cpp): the difference falls by about 16 when the step is
  // halved.
  const MultibodyProblem p = tumbling_cat();
  MultibodyOptimum controls;
  for (int k = 0; k <= 2 * p.intervals; ++k) {
    const double t = p.final_time * k / (2.0 * p.intervals);
    controls.time.push_back(t);
    controls.controls.push_back(
        Vec3(0.03 * std::sin(2.0 * t), 0.02 * std::cos(3.0 * t), -0.01 * std::sin(t)));
  }
  double previous = 0.0;
  for (const int per_interval : {10, 20}) {
    const int steps = p.intervals * per_interval;
    const MultibodyReplay replay = replay_controls(p, controls, per_interval);
    const multibody::State mine = testing::integrate_minimal_model(p, controls, steps);
    const double d = testing::largest_state_difference(replay.final_state, mine);
    double moved = 0.0;
    for (std::size_t i = 0; i < 2; ++i)
      moved = std::max(
          moved, so3::angle_between(p.initial_state.bodies[i].R_space_body, mine.bodies[i].R_space_body));
    if (previous > 0.0) {
      EXPECT_GT(previous / d, 12.0);
    }
    previous = d;
    EXPECT_LT(d, 1e-5);
    EXPECT_GT(moved, 0.5);
  }
}

TEST(MultibodyMinimalBall, FallingCatFromTheRigidTurn) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "a 2 s solve in release; the model's derivatives and dynamics are tested above";
  // The cat turned over (π about the spine in 1 s) in minimal coordinates, N = 6, from the cat turned rigidly
  // (falling_cat_rigid_turn): Ipopt converges (measured 21 iterations) to a local optimum whose cost tends to
  // that of the no-twist optimum the R-coordinate transcription finds from the same guess
  // (docs/measurements/optimal_multibody.md, "The falling cat": 0.63116 N²·m²·s at N = 24): measured 0.62043
  // here, −1.7 % (0.62890 at N = 12, 0.63098 at N = 24: −2.9e-4); the test allows 3 %. Unlike that optimum,
  // this motion twists (s·vee(M − Mᵀ) up to 0.87 of 2): the same cost, not the same trajectory (docs, "Not
  // done").
  const MultibodyProblem p = testing::falling_cat(0.5, std::numbers::pi, 1.0, 6);
  const MultibodyOptimum guess = testing::falling_cat_rigid_turn(0.5, std::numbers::pi, 1.0, 6);
  MultibodyOptions o;
  o.coordinates = MultibodyCoordinates::minimal;
  o.warm_start = &guess;
  const MultibodyOptimum m = solve_multibody(p, o);
  ASSERT_TRUE(m.converged) << m.status;
  EXPECT_NEAR(m.cost / 0.6311621493, 1.0, 0.03);
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT(
        so3::angle_between(m.states.back().bodies[i].R_space_body, p.final_state.bodies[i].R_space_body),
        1e-8);
  }
  // Re-simulated by the projected RK4: the joint holds and the momenta stay zero at round-off (measured
  // 1e-11 kg·m²/s); the target is missed by the coarse mesh's error (0.23 rad at N = 6, 0.034 at N = 12).
  const MultibodyReplay replay = replay_controls(p, m, 64);
  EXPECT_LT(replay.max_joint_gap, 1e-12);
  EXPECT_LT(replay.max_momentum_change, 1e-9);
  EXPECT_LT(replay.attitude_error, 0.4);
}

}  // namespace
}  // namespace poinsot::optimal
