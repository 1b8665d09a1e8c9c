// The Integrator base class: methods without dense output or multipliers say so (InvalidInput naming the
// method, false), and nominal_step reports the configured step.
#include "poinsot/dynamics/integrator.hpp"

#include <string>

#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

TEST(Integrator, DenseOutputOfAFixedStepMethodIsRefused) {
  const auto m = dynamics::make_integrator("rk4", kBody, TorqueModel::none());
  POINSOT_EXPECT_THROWS_MESSAGE(m->dense_output(0.5), InvalidInput, "rk4: no dense output");
}

TEST(Integrator, OnlyRattleHasAMultiplier) {
  for (const dynamics::MethodInfo& info : dynamics::methods()) {
    const std::string name(info.name);
    const auto m = dynamics::make_integrator(name, kBody, TorqueModel::none());
    State s;
    s.omega_body = Vec3(1, 2, 3);
    m->step(s, 1e-3);
    Mat3 lambda;
    EXPECT_EQ(m->last_multiplier(lambda), name == "rattle") << name;
  }
}

TEST(Integrator, NominalStepIsTheConfiguredStep) {
  IntegratorOptions o;
  o.dt = 0.0123;
  for (const dynamics::MethodInfo& info : dynamics::methods())
    EXPECT_EQ(dynamics::make_integrator(info.name, kBody, TorqueModel::none(), o)->nominal_step(),
              info.order > 0 ? 0.0123 : 0.0)
        << info.name;
}

}  // namespace
}  // namespace poinsot::test
