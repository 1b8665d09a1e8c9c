// The Integrator base class: methods without dense output or multipliers say so (InvalidInput naming the
// method, false), and nominal_step reports the configured step.
#include "poinsot/dynamics/integrator.hpp"

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

TEST(Integrator, DenseOutputOfAFixedStepMethodIsRefused) {
  const auto m = dynamics::make_integrator("rk4", kBody, TorqueModel::none());
  try {
    m->dense_output(0.5);
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("rk4: no dense output"), std::string::npos) << e.what();
  }
}

TEST(Integrator, OnlyRattleHasAMultiplier) {
  for (const char* name : {"rk4", "dopri5", "dop853", "dlm", "rattle"}) {
    const auto m = dynamics::make_integrator(name, kBody, TorqueModel::none());
    State s;
    s.omega_body = Vec3(1, 2, 3);
    m->step(s, 1e-3);
    Mat3 lambda;
    EXPECT_EQ(m->last_multiplier(lambda), std::string(name) == "rattle") << name;
  }
}

TEST(Integrator, NominalStepIsTheConfiguredStep) {
  IntegratorOptions o;
  o.dt = 0.0123;
  for (const char* name : {"rk4", "dopri5", "dop853", "dlm", "rattle"})
    EXPECT_EQ(dynamics::make_integrator(name, kBody, TorqueModel::none(), o)->nominal_step(), 0.0123) << name;
}

}  // namespace
}  // namespace poinsot::test
