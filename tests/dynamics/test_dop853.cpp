// dop853: agrees with the axisymmetric closed form (paper eq. 4.2) to near round-off, follows its tolerance,
// and its order-7 dense output is as accurate as its steps (the flips are located on it, test_simulation).
#include "poinsot/dynamics/dop853.hpp"

#include <limits>

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot/dynamics/dopri5.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::Dop853Integrator;

IntegratorOptions dop853_options(double tol, double dt = 0.5) {
  IntegratorOptions o;
  o.rtol = tol;
  o.atol = tol;
  o.dt = dt;
  return o;
}

TEST(Dop853, ReferenceAgreesWithTheAxisymmetricClosedForm) {
  // The reference used by the other tests: at rtol = atol = 1e-14 over 10 s it matches eq. (4.2) to ~1e-13.
  const double A = 2.0, C = 1.0;  // docs/conventions.md case b
  const RigidBody body = RigidBody::from_principal_moments(Vec3(A, A, C));
  State s0;
  s0.R_space_body = so3::exp(Vec3(-0.4, 0.1, 0.9));
  s0.omega_body = Vec3(0.3, -0.4, 1.2);
  const State s = reference(body, TorqueModel::none(), s0, 10.0);
  EXPECT_LT(state_error(s, axisymmetric_exact(A, C, s0, 10.0)), 5e-13);
}

TEST(Dop853, GlobalErrorFollowsTheTolerance) {
  const State s0 = tumbling();
  const double T = 10.0;
  // The oracle here is dopri5 at a tighter tolerance than tested (another method), and eq. (4.2) above.
  IntegratorOptions tight = dop853_options(1e-14, 0.05);
  dynamics::Dopri5Integrator other(kBody, TorqueModel::none(), tight);
  const State ref = run_adaptive(other, s0, T, 0.05);
  for (double tol : {1e-7, 1e-9, 1e-11}) {
    Dop853Integrator m(kBody, TorqueModel::none(), dop853_options(tol));
    const double e = state_error(run_adaptive(m, s0, T, 0.5), ref);
    EXPECT_LT(e, 30.0 * tol) << "tol " << tol;
  }
}

// Every step, the first included, is at most max_step, whatever step is asked; without max_step the first
// step is the one asked. The largest step must be > 0 (infinity: none); a bad one is named in the message.
TEST(Dop853, StepsAreAtMostMaxStep) {
  IntegratorOptions o = dop853_options(1e-6, 0.5);
  o.max_step = 0.01;
  Dop853Integrator capped(kBody, TorqueModel::none(), o);
  State s = tumbling();
  double h = 1.0;
  double largest = 0.0;
  for (int k = 0; k < 50; ++k) {
    const auto r = capped.step(s, h);
    largest = std::max(largest, r.dt_taken);
    EXPECT_LE(r.dt_next, 0.01);
    h = 1.0;  // asks for more than the cap every time
  }
  EXPECT_EQ(largest, 0.01);
  Dop853Integrator free(kBody, TorqueModel::none(), dop853_options(1e6, 0.5));  // accepts any step
  State f = tumbling();
  EXPECT_EQ(free.step(f, 0.5).dt_taken, 0.5);
  for (const double bad : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN()}) {
    o.max_step = bad;
    POINSOT_EXPECT_THROWS_MESSAGE(Dop853Integrator(kBody, TorqueModel::none(), o), InvalidInput,
                                  "dop853: max_step: got");
  }
  o.max_step = std::numeric_limits<double>::infinity();
  EXPECT_NO_THROW(Dop853Integrator(kBody, TorqueModel::none(), o));
}

TEST(Dop853, DenseOutputIsAsAccurateAsTheSteps) {
  const State s0 = tumbling();
  Dop853Integrator m(kBody, TorqueModel::none(), dop853_options(1e-10, 2.0));
  State s = s0;
  double worst = 0.0;
  double largest_step = 0.0;
  for (int i = 0; i < 10; ++i) {
    const double t_prev = s.time;
    const auto r = m.step(s, 2.0);
    largest_step = std::max(largest_step, r.dt_taken);
    for (double f : {0.13, 0.5, 0.77}) {
      const double t = t_prev + f * r.dt_taken;
      worst = std::max(worst, state_error(m.dense_output(t), reference(kBody, TorqueModel::none(), s0, t)));
    }
    EXPECT_LT(state_error(m.dense_output(s.time), s), 1e-14);
  }
  EXPECT_GT(largest_step, 0.2);  // large steps, so the interpolant is really exercised
  EXPECT_LT(worst, 30.0 * 1e-10);
}

TEST(Dop853, GravityTopConservesItsEnergyWithinTheTolerance) {
  const RigidBody top =
      RigidBody::from_principal_moments(Vec3(0.002, 0.002, 0.004)).with_pivot(1.0, Vec3(0, 0, 0.1));
  const Vec3 g(0, 0, -9.81);
  const auto gravity = TorqueModel::gravity(top, g);
  State s;
  s.R_space_body = so3::exp(Vec3(M_PI / 3, 0, 0));
  s.omega_body = Vec3(0, 0, 100.0);
  Dop853Integrator m(top, gravity, dop853_options(1e-12, 0.01));
  const double E0 = dynamics::total_energy(top, s, g);
  const State s1 = run_adaptive(m, s, 2.0, 0.01);
  EXPECT_LT(std::abs(dynamics::total_energy(top, s1, g) - E0) / std::abs(E0), 1e-10);
  // ω3 is conserved exactly for a symmetric top with the centre of mass on its axis (τ3 = 0).
  EXPECT_NEAR(s1.omega_body.z(), 100.0, 1e-8);
}

}  // namespace
}  // namespace poinsot::test
