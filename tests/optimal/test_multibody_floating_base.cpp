// The minimal-coordinate model of a floating base (a quaternion of the base, its angular velocity, the hinge
// angles and rates; the translation eliminated by the centre of mass at rest): its Lagrangian against the
// kinetic energy, its forward dynamics against the multibody layer's projected RK4, and the reaction-wheel
// slew against the single-axis closed form and the single-body optimum of the effective inertia.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include "../../src/optimal/multibody_minimal_model.hpp"
#include "minimal_model_rk4.hpp"
#include "multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

/// The offset wheel tumbling: the base turned by e, ω₀ = (0.3, −0.2, 0.5) rad/s, the wheel at 0.7 rad
/// spinning at 2 rad/s relative to the bus, the centre of mass at rest (a consistent state by construction).
MultibodyProblem tumbling_offset_wheel() {
  MultibodyProblem p = testing::offset_reaction_wheel();
  const detail::MultibodyMinimalModel model(p);
  Eigen::VectorXd w = Eigen::VectorXd::Zero(model.point_size());
  w.head<4>() = Eigen::Vector4d(0.9, 0.2, -0.3, 0.25).normalized();
  const detail::MinimalTree& tree = model.tree();
  w(tree.links[1].q) = 0.7;
  w.segment<3>(tree.positions) = Vec3(0.3, -0.2, 0.5);  // ω₀
  w(tree.links[1].v) = 2.0;
  p.initial_state = model.state_of(w.data(), 0.0);
  return p;
}

TEST(MultibodyFloatingBase, MassMatrixIsTheKineticEnergys) {
  // The Lagrangian's mass matrix, from the inverse dynamics at unit accelerations, against the kinetic energy
  // ½ Σ (m|v|² + ωᵀJω) of the decoded state (the centre of mass at rest: P = 0 leaves no translational
  // energy of the whole): ½ νᵀMν equals it to round-off, for any ν, and M is symmetric positive definite.
  const MultibodyProblem p = tumbling_offset_wheel();
  const detail::MultibodyMinimalModel model(p);
  const Eigen::VectorXd y = model.state_vector(p.initial_state);
  Eigen::MatrixXd M;
  Eigen::VectorXd bias;
  model.equations_of_motion(y, Eigen::VectorXd::Zero(1), M, bias);
  ASSERT_EQ(M.rows(), 4);
  EXPECT_LT((M - M.transpose()).norm(), 1e-13 * M.norm());
  // M − 0.1 I has a Cholesky factor exactly when M's least eigenvalue is above 0.1.
  const Eigen::MatrixXd shifted = M - 0.1 * Eigen::MatrixXd::Identity(M.rows(), M.cols());
  EXPECT_EQ(Eigen::LLT<Eigen::MatrixXd>(shifted).info(), Eigen::Success);
  const Eigen::VectorXd nu = y.tail(4);
  const multibody::State s = model.state_of(y.data(), 0.0);
  EXPECT_NEAR(0.5 * nu.dot(M * nu), multibody::kinetic_energy(p.system, s), 1e-13);
  EXPECT_LT(multibody::linear_momentum(p.system, s).norm(), 1e-14);
  // The decoded state is the one encoded (the round trip).
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_LT((s.bodies[i].R_space_body - p.initial_state.bodies[i].R_space_body).norm(), 1e-14);
    EXPECT_LT((s.bodies[i].x_space - p.initial_state.bodies[i].x_space).norm(), 1e-14);
    EXPECT_LT((s.bodies[i].omega_body - p.initial_state.bodies[i].omega_body).norm(), 1e-14);
    EXPECT_LT((s.bodies[i].v_space - p.initial_state.bodies[i].v_space).norm(), 1e-14);
  }
}

TEST(MultibodyFloatingBase, ForwardDynamicsIsTheProjectedRk4s) {
  // The tumbling offset wheel driven by u(t) = 0.8 sin(1.3 t) N·m for 4 s: the model's forward dynamics
  // (ν̇ = −M⁻¹(c − Bu)) integrated by RK4 in (e, θ, ω₀, θ̇), against the multibody layer's projected RK4 in
  // (x, R) of every body (replay_controls), on the same steps with the same held controls. Both are of order
  // 4, so their difference is the sum of their errors: it must fall by about 16 when the step is halved, and
  // be small against the motion (the bodies turn by several radians): measured 3.7e-6 and 2.3e-7 (a ratio of
  // 16.0) at 200 and 400 steps.
  MultibodyProblem p = tumbling_offset_wheel();
  MultibodyOptimum controls;
  for (int k = 0; k <= 2 * p.intervals; ++k) {
    const double t = p.final_time * k / (2.0 * p.intervals);
    controls.time.push_back(t);
    controls.controls.push_back(Eigen::VectorXd::Constant(1, 0.8 * std::sin(1.3 * t)));
  }
  double previous = 0.0;
  for (const int per_interval : {20, 40}) {
    const MultibodyReplay replay = replay_controls(p, controls, per_interval);
    const multibody::State mine = testing::integrate_minimal_model(p, controls, p.intervals * per_interval);
    const double d = testing::largest_state_difference(replay.final_state, mine);
    if (previous > 0.0) {
      EXPECT_GT(previous / d, 12.0);
    }
    previous = d;
    EXPECT_LT(d, 1e-5);
    EXPECT_GT(testing::largest_state_difference(p.initial_state, mine), 1.0);  // the motion is no small one
    // The minimal model's motion keeps the joint and P by construction; H is conserved by its dynamics.
    EXPECT_LT(
        (multibody::angular_momentum(p.system, mine) - multibody::angular_momentum(p.system, p.initial_state))
            .norm(),
        1e-5);
  }
}

TEST(MultibodyFloatingBase, ReactionWheelUnboundedIsTheSingleAxisClosedForm) {
  // The bus turned by Θ = 1 rad in 10 s, the wheel's angle free: the single axis I_zz θ̈ = −u with I = 2
  // kg·m², cost 12 I² Θ² / T³, in minimal coordinates from the naive guess.
  const double theta = 1.0, T = 10.0, I = 2.0;
  const MultibodyProblem p = testing::reaction_wheel(theta, T, 1.0, 8);
  const MultibodyOptimum m = testing::solve_in(p, MultibodyCoordinates::minimal);
  ASSERT_TRUE(m.converged) << m.status;
  const double exact = 12.0 * I * I * theta * theta / (T * T * T);
  EXPECT_NEAR(m.cost / exact, 1.0, 1e-4);  // measured +6.1e-6 (h⁴: the quaternion is no polynomial of t)
  EXPECT_LT(so3::angle_between(m.states.back().bodies[0].R_space_body, p.final_state.bodies[0].R_space_body),
            1e-8);
  const MultibodyReplay replay = replay_controls(p, m, 32);
  // Re-simulated: 1.2e-5 rad from the target (the transcription's error), the rates at T at round-off (the
  // motion is about z alone, where H_z is a linear invariant, which Runge–Kutta keeps).
  EXPECT_LT(replay.attitude_error, 1e-4);
  EXPECT_LT(replay.velocity_error, 1e-10);
  EXPECT_LT(replay.max_joint_gap, 1e-12);
}

TEST(MultibodyFloatingBase, BoundedReactionWheelConvergesToTheSingleBody) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "1.9 s in release; the unbounded slew above solves the same model under the sanitizers";
  // |u| ≤ 0.1 N·m (active: the unbounded peak is 0.12 N·m) from the naive guess (the interpolated
  // quaternions are not unit: the projection R(e/|e|) makes them attitudes). The single body of the
  // effective inertia J_bus + diag(0.5, 0.5, 0) (direct_collocation.hpp, mesh refined to 1e-9; docs/
  // measurements/optimal_multibody.md, "The measurement of the claim") costs 0.0483602207; the
  // transcription's error falls with N (measured −5.6e-5 at N = 8, −2.5e-5 at N = 16, −4.6e-6 at N = 32 in
  // bench_optimal_multibody: the bound's kinks at two instants slow Hermite–Simpson's h⁴ down), and the
  // controls, re-simulated by the projected RK4, reach the target to the transcription's error.
  const double single = 0.0483602207;
  double previous = 1.0;
  for (const int N : {8, 16}) {
    const MultibodyProblem p = testing::reaction_wheel(1.0, 10.0, 0.1, N);
    const MultibodyOptimum m = testing::solve_in(p, MultibodyCoordinates::minimal);
    ASSERT_TRUE(m.converged) << m.status;
    const double error = std::abs(m.cost / single - 1.0);
    EXPECT_LT(error, 1e-4) << "N = " << N;
    EXPECT_LT(error, 0.6 * previous) << "N = " << N;
    previous = error;
    const MultibodyReplay replay = replay_controls(p, m, 64);
    EXPECT_LT(replay.attitude_error, 1e-5) << "N = " << N;
    EXPECT_LT(replay.velocity_error, 1e-5) << "N = " << N;
    EXPECT_LT(replay.max_joint_gap, 1e-12);
    EXPECT_LT(replay.max_momentum_change, 1e-12);
  }
}

TEST(MultibodyFloatingBase, BadInputIsOneLine) {
  // A floating base whose centre of mass moves (P ≠ 0: the translation is not eliminated), and one under
  // gravity: one line each, naming the field.
  MultibodyProblem p = testing::reaction_wheel(1.0, 10.0, 0.1, 4);
  for (std::size_t i = 0; i < 2; ++i) {
    p.initial_state.bodies[i].v_space = Vec3(0.1, 0.0, 0.0);
    p.final_state.bodies[i].v_space = Vec3(0.1, 0.0, 0.0);
    p.final_state.bodies[i].x_space = Vec3(1.0, 0.0, 0.0);  // x_com + T P / M
  }
  MultibodyOptions o;
  o.coordinates = MultibodyCoordinates::minimal;
  try {
    (void)solve_multibody(p, o);
    ADD_FAILURE() << "a moving centre of mass was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("initial_state"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("linear momentum"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
  }
  MultibodyProblem q = testing::reaction_wheel(1.0, 10.0, 0.1, 4);
  q.system.set_gravity(Vec3(0.0, 0.0, -9.81));
  try {
    (void)solve_multibody(q, o);
    ADD_FAILURE() << "a floating base under gravity was accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("gravity"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace poinsot::optimal
