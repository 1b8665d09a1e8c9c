// make_integrator: every name gives the method of that name and order, the option checks of each method
// apply, "exact" refuses a torque, and an unknown name lists the valid ones.
#include <gtest/gtest.h>

#include "dynamics_test_util.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::make_integrator;

TEST(IntegratorFactory, CreatesEveryMethod) {
  struct Expect {
    const char* name;
    int order;
    bool adaptive;
    bool dense;
  };
  for (const Expect& e :
       {Expect{"rk4", 4, false, false}, Expect{"dopri5", 5, true, true}, Expect{"dop853", 8, true, true},
        Expect{"dlm", 2, false, false}, Expect{"rattle", 2, false, false}, Expect{"exact", 0, false, true}}) {
    const auto m = make_integrator(e.name, kBody, TorqueModel::none());
    ASSERT_TRUE(m) << e.name;
    EXPECT_EQ(m->name(), e.name);
    EXPECT_EQ(m->order(), e.order) << e.name;
    EXPECT_EQ(m->is_adaptive(), e.adaptive) << e.name;
    EXPECT_EQ(m->has_dense_output(), e.dense) << e.name;
    // Every method moves a tumbling body the same way over one short step (adaptive ones take at most the
    // configured dt = 1 ms); the local error of the order-2 methods is O((hω)³) ~ 1e-6.
    State s0;
    s0.omega_body = Vec3(1.0, 0.6, -0.8);
    State s = s0;
    m->step(s, 0.01);
    EXPECT_GT(s.t, 0.0);
    EXPECT_LT(state_error(s, reference(kBody, TorqueModel::none(), s0, s.t)), 1e-5) << e.name;
  }
  // A null torque means none.
  EXPECT_NO_THROW(make_integrator("dlm", kBody, nullptr));
}

TEST(IntegratorFactory, ExactRefusesATorque) {
  EXPECT_THROW(make_integrator("exact", kBody, TorqueModel::constant_body(Vec3(0, 0, 1))), InvalidInput);
}

TEST(IntegratorFactory, UnknownNameListsTheValidOnes) {
  try {
    make_integrator("euler", kBody, TorqueModel::none());
    FAIL() << "expected InvalidInput";
  } catch (const InvalidInput& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("\"euler\""), std::string::npos) << msg;
    EXPECT_NE(msg.find("rk4, dopri5, dop853, dlm, rattle, exact"), std::string::npos) << msg;
  }
}

TEST(IntegratorFactory, ChecksTheOptions) {
  IntegratorOptions o;
  o.dt = -1.0;
  for (const char* name : {"rk4", "dopri5", "dop853", "dlm", "rattle"})
    EXPECT_THROW(make_integrator(name, kBody, TorqueModel::none(), o), InvalidInput) << name;
  o = IntegratorOptions{};
  o.atol = 0.0;
  EXPECT_THROW(make_integrator("dop853", kBody, TorqueModel::none(), o), InvalidInput);
  o = IntegratorOptions{};
  o.newton_max_iterations = 0;
  EXPECT_THROW(make_integrator("rattle", kBody, TorqueModel::none(), o), InvalidInput);
}

}  // namespace
}  // namespace poinsot::test
