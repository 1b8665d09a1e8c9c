// dopri5: the global error follows the tolerance, the dense output is as accurate as the steps, step-size
// failure is reported with its time, and the axisymmetric closed form (paper eq. 4.2) is reproduced.
#include "poinsot/dynamics/dopri5.hpp"

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::Dopri5Integrator;

IntegratorOptions dopri5_options(double tol) {
  IntegratorOptions o;
  o.rtol = tol;
  o.atol = tol;
  o.dt = 0.5;
  return o;
}

TEST(Dopri5, GlobalErrorFollowsTheTolerance) {
  const State s0 = tumbling();
  const double T = 10.0;
  const State ref = reference(kBody, TorqueModel::none(), s0, T);
  double previous = 1.0;
  for (double tol : {1e-6, 1e-8, 1e-10}) {
    Dopri5Integrator m(kBody, TorqueModel::none(), dopri5_options(tol));
    const double e = state_error(run_adaptive(m, s0, T, 0.5), ref);
    // The controller bounds the local error per step by tol; over ~10²–10³ steps of a non-stiff problem the
    // global error stays within a small multiple of tol.
    EXPECT_LT(e, 30.0 * tol) << "tol " << tol;
    // and it falls with the tolerance (by ~tol^(5/5)... at least a factor 20 per factor 100 of tol).
    EXPECT_LT(e, previous / 20.0) << "tol " << tol;
    previous = e;
  }
}

TEST(Dopri5, DenseOutputIsAsAccurateAsTheSteps) {
  const State s0 = tumbling();
  Dopri5Integrator m(kBody, TorqueModel::none(), dopri5_options(1e-9));
  State s = s0;
  double worst = 0.0;
  for (int i = 0; i < 20; ++i) {
    const double t_prev = s.time;
    const auto r = m.step(s, 0.5);
    for (double f : {0.1, 0.37, 0.5, 0.81}) {
      const double t = t_prev + f * r.dt_taken;
      worst = std::max(worst, state_error(m.dense_output(t), reference(kBody, TorqueModel::none(), s0, t)));
    }
    // The interpolant reproduces the step's ends.
    EXPECT_LT(state_error(m.dense_output(s.time), s), 1e-14);
  }
  EXPECT_LT(worst, 30.0 * 1e-9);  // order-4 interpolant at the accuracy of the order-5 steps
}

TEST(Dopri5, ReproducesTheAxisymmetricClosedForm) {
  const double A = 1.0, C = 1.8;  // docs/conventions.md case c (oblate)
  const RigidBody body = RigidBody::from_principal_moments(Vec3(A, A, C));
  State s0;
  s0.omega_body = Vec3(1.0, 0.5, -2.0);
  Dopri5Integrator m(body, TorqueModel::none(), dopri5_options(1e-11));
  const State s = run_adaptive(m, s0, 20.0, 0.5);
  EXPECT_LT(state_error(s, axisymmetric_exact(A, C, s0, 20.0)), 1e-9);
}

TEST(Dopri5, ReportsAStepThatCannotMeetTheTolerance) {
  // A torque that becomes NaN at t > 0.3 s: every attempt beyond fails, the step shrinks below its floor.
  const auto bad =
      TorqueModel::callback([](double t, const Mat3&,
                               const Vec3&) { return t > 0.3 ? Vec3::Constant(std::nan("")) : Vec3::Zero(); },
                            false, "NaN after 0.3 s");
  Dopri5Integrator m(kBody, bad, dopri5_options(1e-8));
  State s = tumbling();
  const std::string msg = message_of<ComputationFailed>([&] { run_adaptive(m, s, 1.0, 0.1); });
  const auto at = msg.find("at t = ");
  ASSERT_NE(at, std::string::npos) << msg;
  EXPECT_NEAR(std::stod(msg.substr(at + 7)), 0.3, 1e-6) << msg;
}

TEST(Dopri5, RejectsBadTolerances) {
  IntegratorOptions o;
  o.rtol = -1.0;
  EXPECT_THROW(Dopri5Integrator(kBody, TorqueModel::none(), o), InvalidInput);
  Dopri5Integrator m(kBody, TorqueModel::none());
  EXPECT_THROW(m.dense_output(0.0), InvalidInput);  // no step yet
}

}  // namespace
}  // namespace poinsot::test
