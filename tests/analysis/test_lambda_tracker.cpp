#include "poinsot/analysis/lambda_tracker.hpp"

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"
#include "reference_motion.hpp"

namespace poinsot::analysis {
namespace {
using dynamics::RigidBody;
using dynamics::State;
using test::kEps;

// Feeds the tracker the reference RK4 trajectory (h = 1e-3 s; error ~1e-12 over a few seconds at |ω| ~ 1).
LambdaProperties track(const RigidBody& body, const State& initial, double t_end,
                       std::shared_ptr<const dynamics::TorqueModel> torque = nullptr,
                       const LambdaTrackerOptions& options = {}) {
  LambdaTracker tracker(body, torque, initial, options);
  State s = initial;
  while (s.time < t_end - 1e-12) {
    s = test::advance(body, torque.get(), s, s.time + 0.1);
    tracker.observe(s);
  }
  return tracker.properties();
}

TEST(LambdaTracker, CaseBProlateAlongTheReferenceTrajectory) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 2.0, 1.0));
  State s0;
  s0.omega_body = Vec3(0.3, -0.4, 1.2);
  const LambdaProperties p = track(body, s0, 5.0);
  EXPECT_EQ(p.samples, 51);
  ASSERT_TRUE(p.closed_form.has_value());
  const AxisymmetricCheck& c = *p.closed_form;
  EXPECT_NEAR(c.inertia.A, 2.0, 1e-15);
  EXPECT_NEAR(c.inertia.C, 1.0, 1e-15);
  EXPECT_NEAR(std::abs(c.inertia.k[2]), 1.0, 1e-15);
  EXPECT_NEAR(c.eigenvalues[0], -1.0294, 5e-5);  // docs/conventions.md: λ1 < λ3 < λ2
  EXPECT_NEAR(c.eigenvalues[1], -0.845, 1e-15);
  EXPECT_NEAR(c.eigenvalues[2], -0.0656, 5e-5);
  // The trajectory's eigenvalues stay on the closed form to the reference integrator's error.
  EXPECT_LE(c.max_deviation, 1e-10);
  EXPECT_LE(p.eigenvalue_max_variation, 1e-10);
  EXPECT_LE(c.eigenvector_residual_max, 1e-10);
  EXPECT_LE(c.constant_matrix_deviation_max, 1e-10);
  EXPECT_LE(p.symmetry_error_max, 64 * kEps);
  EXPECT_LE(p.max_eigenvalue_max, 1e-15);
  EXPECT_LE(p.trace_plus_2T_max, 64 * kEps);
  EXPECT_LE(test::max_abs_diff(p.eigenvalues_initial, c.eigenvalues), 16 * kEps);
}

TEST(LambdaTracker, GeneralBodyEigenvaluesVary) {
  // docs/conventions.md C3: J = diag(2,3,4), ω0 = (1, 0.5, 0.3); eig Λ(0) → eig Λ(3 s) moves by 0.1178 (first
  // entry).
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  State s0;
  s0.omega_body = Vec3(1.0, 0.5, 0.3);
  const LambdaProperties p = track(body, s0, 3.0);
  EXPECT_FALSE(p.closed_form.has_value());
  EXPECT_GE(p.eigenvalue_max_variation, 0.1178 - 1e-4);
  EXPECT_NEAR(p.eigenvalues_final[0], -2.3779, 5e-5);
  EXPECT_LE(p.max_eigenvalue_max, 1e-15);
  EXPECT_LE(p.trace_plus_2T_max, 64 * kEps);
}

TEST(LambdaTracker, LaminaHasNoDivisionByZero) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
  State s0;
  s0.omega_body = Vec3(0.7, -0.3, 1.1);
  s0.R_space_body = test::random_rotation();
  const LambdaProperties p = track(body, s0, 2.0);
  EXPECT_TRUE(p.lambda_final.allFinite());
  EXPECT_LE(p.max_eigenvalue_max, 32 * kEps * p.lambda_scale);
  EXPECT_LE(p.symmetry_error_max, 64 * kEps);
  EXPECT_LE(p.lambda_final.col(2).norm(), 16 * kEps * p.lambda_scale);  // Λ = M K, K e3 = 0
  EXPECT_GT(p.eigenvalue_max_variation, 1e-3);                          // a general body: eigenvalues move
}

TEST(LambdaTracker, TorqueSymmetryUsesTheTorqueAndClosedFormIsOff) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 2.0, 1.0));
  const auto torque = dynamics::TorqueModel::constant_body(Vec3(0.2, 0.0, -0.1));
  State s0;
  s0.omega_body = Vec3(0.3, -0.4, 1.2);
  const LambdaProperties p = track(body, s0, 1.0, torque);
  EXPECT_FALSE(p.torque_free);
  EXPECT_FALSE(p.closed_form.has_value());  // the closed form is for the free body only
  EXPECT_LE(p.symmetry_error_max, 64 * kEps);
  EXPECT_LE(p.trace_plus_2T_max, 64 * kEps);
}

TEST(LambdaTracker, StressAndVolume) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  State s0;
  s0.omega_body = Vec3(1.0, 0.5, 0.3);
  LambdaTrackerOptions o;
  o.volume_m3 = 0.5;
  const LambdaProperties p = track(body, s0, 1.0, nullptr, o);
  ASSERT_TRUE(p.stress_initial.has_mean);
  EXPECT_NEAR(p.stress_initial.integral.trace, 2 * dynamics::kinetic_energy(body, s0), 1e-14);
  EXPECT_LE(test::max_abs_diff(p.stress_initial.integral.tensor, -p.lambda_initial), 1e-15);  // R(0) = I
  EXPECT_GE(p.von_mises_max, p.stress_initial.mean.von_mises);
  o.volume_m3 = -1.0;
  EXPECT_THROW(LambdaTracker(body, nullptr, s0, o), InvalidInput);
}

TEST(LambdaTracker, CompareMultiplierMeasuresTheDeviation) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  State s0;
  s0.omega_body = Vec3(1.0, 0.5, 0.3);
  LambdaTracker tracker(body, nullptr, s0);
  const Mat3 lambda = lambda_from_state(body, s0);
  Mat3 perturbed = lambda;
  perturbed(0, 1) += 1e-3;
  tracker.compare_multiplier(s0, perturbed);
  const LambdaProperties& p = tracker.properties();
  ASSERT_TRUE(p.has_integrator_multiplier);
  EXPECT_NEAR(p.integrator_multiplier_deviation_max, 1e-3, 1e-15);
  EXPECT_NEAR(p.integrator_multiplier_symmetry_error_max, std::sqrt(2.0) * 1e-3, 1e-15);
  EXPECT_EQ(p.samples, 1);
}

}  // namespace
}  // namespace poinsot::analysis
