// The exact integrator (exact_integrator.hpp): the closed form behind the Integrator interface.
#include "poinsot/dynamics/exact_integrator.hpp"

#include <gtest/gtest.h>
#include <string>

#include "free_body_reference.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot_test.hpp"

namespace poinsot::dynamics {
namespace {

using test::max_abs_diff;

State start() {
  State s;
  s.time = 1.0;
  s.R_space_body = test::random_rotation();
  s.omega_body = Vec3(0.4, 1.1, -0.7);
  return s;
}

TEST(ExactIntegrator, RefusesTorqueWithAClearMessage) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5));
  EXPECT_NO_THROW(make_exact_integrator(body, nullptr));
  EXPECT_NO_THROW(make_exact_integrator(body, TorqueModel::none()));
  POINSOT_EXPECT_THROWS_MESSAGE(make_exact_integrator(body, TorqueModel::constant_body(Vec3(0.0, 0.0, 0.1))),
                                InvalidInput, "exact: the closed-form solution is torque-free; got torque");
}

TEST(ExactIntegrator, StepsFollowTheClosedFormAndTheReference) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5));
  auto integ = make_exact_integrator(body, TorqueModel::none());
  EXPECT_EQ(integ->name(), "exact");
  EXPECT_EQ(integ->order(), 0);
  EXPECT_FALSE(integ->is_adaptive());
  EXPECT_TRUE(integ->has_dense_output());
  const State s0 = start();
  const ExactFreeBody exact(body, s0);
  State s = s0;
  for (int i = 0; i < 1000; ++i) {
    const StepResult r = integ->step(s, 0.1);
    EXPECT_EQ(r.dt_taken, 0.1);
    EXPECT_EQ(r.rejected, 0);
  }
  // The same set-up throughout (cached): only the accumulated time differs from one evaluation at t.
  const State e = exact.state_at(s.time);
  EXPECT_LE(max_abs_diff(s.omega_body, e.omega_body), 1e-14);
  EXPECT_LE(max_abs_diff(s.R_space_body, e.R_space_body), 1e-14);
  const State ref = test::FreeBodyReference(body.inertia()).integrate(s0, s.time, 20000);
  EXPECT_LE(max_abs_diff(s.omega_body, ref.omega_body), 1e-12);
  EXPECT_LE(max_abs_diff(s.R_space_body, ref.R_space_body), 1e-12);
  // Dense output anywhere: the closed form itself.
  EXPECT_LE(max_abs_diff(integ->dense_output(-3.0).R_space_body, exact.state_at(-3.0).R_space_body), 1e-15);
}

TEST(ExactIntegrator, ReinitialisesForAStateItDidNotProduce) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5));
  auto integ = make_exact_integrator(body, nullptr);
  State s = start();
  integ->step(s, 0.5);
  s.omega_body[2] += 0.3;  // the caller edits the state: a new motion
  const State edited = s;
  integ->step(s, 0.5);
  const State expect = ExactFreeBody(body, edited).state_at(edited.time + 0.5);
  EXPECT_LE(max_abs_diff(s.omega_body, expect.omega_body), 1e-15);
  EXPECT_LE(max_abs_diff(s.R_space_body, expect.R_space_body), 1e-15);
  // Negative steps run the motion backwards.
  integ->step(s, -0.5);
  EXPECT_LE(max_abs_diff(s.omega_body, edited.omega_body), 1e-14);
  EXPECT_LE(max_abs_diff(s.R_space_body, edited.R_space_body), 1e-14);
}

// A body held at a pivot with no torque rotates freely about the pivot, with J about the pivot.
TEST(ExactIntegrator, BodyAtAPivotWithoutTorque) {
  const RigidBody body =
      RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5)).with_pivot(2.0, Vec3(0.1, -0.2, 0.3));
  ASSERT_FALSE(body.is_diagonal());
  auto integ = make_exact_integrator(body, TorqueModel::none());
  State s = start();
  const State s0 = s;
  integ->step(s, 30.0);
  const State ref = test::FreeBodyReference(body.inertia()).integrate(s0, s.time, 6000);
  EXPECT_LE(max_abs_diff(s.omega_body, ref.omega_body), 1e-12);
  EXPECT_LE(max_abs_diff(s.R_space_body, ref.R_space_body), 1e-12);
}

TEST(ExactIntegrator, RejectsBadInput) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 2.5));
  auto integ = make_exact_integrator(body, nullptr);
  EXPECT_THROW(integ->dense_output(0.0), InvalidInput);
  State s = start();
  EXPECT_THROW(integ->step(s, std::nan("")), InvalidInput);
  s.R_space_body(0, 0) = 3.0;
  EXPECT_THROW(integ->step(s, 0.1), InvalidInput);
  Mat3 lambda;
  EXPECT_FALSE(integ->last_multiplier(lambda));
}

}  // namespace
}  // namespace poinsot::dynamics
