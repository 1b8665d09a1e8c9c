// make_integrator and the registry (methods.hpp): every entry's factory gives a method that moves the body
// correctly, the option checks of each method apply, a torque-free method refuses a torque, an unknown name
// lists the registry's names, and the lists and defaults derived from the registry. The properties every
// method must have are in test_integrator_contract.cpp.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "dynamics_test_util.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::make_integrator;

TEST(IntegratorFactory, CreatesEveryMethod) {
  for (const dynamics::MethodInfo& e : dynamics::methods()) {
    const auto m = make_integrator(e.name, kBody, TorqueModel::none());
    ASSERT_TRUE(m) << e.name;
    EXPECT_EQ(m->name(), e.name);
    // Every method moves a tumbling body the same way over one short step (adaptive ones take at most the
    // configured dt = 1 ms); the local error of the order-2 methods is O((hω)³) ~ 1e-6.
    State s0;
    s0.omega_body = Vec3(1.0, 0.6, -0.8);
    State s = s0;
    m->step(s, 0.01);
    EXPECT_GT(s.time, 0.0);
    EXPECT_LT(state_error(s, reference(kBody, TorqueModel::none(), s0, s.time)), 1e-5) << e.name;
  }
  // A null torque means none.
  EXPECT_NO_THROW(make_integrator("dlm", kBody, nullptr));
}

TEST(IntegratorFactory, ExactRefusesATorque) {
  EXPECT_THROW(make_integrator("exact", kBody, TorqueModel::constant_body(Vec3(0, 0, 1))), InvalidInput);
}

TEST(IntegratorFactory, UnknownNameListsTheValidOnes) {
  POINSOT_EXPECT_THROWS_MESSAGE(make_integrator("euler", kBody, TorqueModel::none()), InvalidInput,
                                "method: got \"euler\"", "expected one of " + dynamics::method_names());
  EXPECT_EQ(dynamics::method_names(), "exact, rk4, dopri5, dop853, dlm, rattle");
}

TEST(IntegratorFactory, DefaultsAreRegistryEntries) {
  EXPECT_EQ(dynamics::method_info(dynamics::kDefaultMethod).name, "dop853");
  EXPECT_EQ(dynamics::method_info(dynamics::kDefaultLambdaMethod).name, "rattle");
  EXPECT_EQ(dynamics::preserved_names({}), "nothing");
  EXPECT_EQ(dynamics::preserved_names(dynamics::method_info("dlm").preserves), "L_space, |L|, RᵀR = I");
}

// The user documentation is prose, not generated: this keeps its lists of methods complete.
TEST(IntegratorFactory, DocumentationNamesEveryMethod) {
  const auto read = [](const char* path) {
    std::ifstream in(std::string(POINSOT_SOURCE_DIR "/") + path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
  };
  const std::string scenario = read("docs/scenario.md");
  const std::string integrators = read("docs/integrators.md");
  const auto row = scenario.find("| `method` | string |");
  ASSERT_NE(row, std::string::npos);
  const std::string method_row = scenario.substr(row, scenario.find('\n', row) - row);
  for (const dynamics::MethodInfo& e : dynamics::methods()) {
    // (append, not "literal" + string: GCC 12's false -Wrestrict)
    const std::string quoted = std::string("\"").append(e.name).append("\"");
    const std::string cell = std::string("| `").append(e.name).append("` |");
    EXPECT_NE(method_row.find(quoted), std::string::npos) << e.name << " missing from docs/scenario.md";
    EXPECT_NE(integrators.find(cell), std::string::npos) << e.name << " missing from docs/integrators.md";
  }
}

TEST(IntegratorFactory, ChecksTheOptions) {
  IntegratorOptions o;
  o.dt = -1.0;
  for (const dynamics::MethodInfo& e : dynamics::methods()) {
    if (e.order > 0) {  // exact has no step to check
      EXPECT_THROW(make_integrator(e.name, kBody, TorqueModel::none(), o), InvalidInput) << e.name;
    }
  }
  o = IntegratorOptions{};
  o.atol = 0.0;
  EXPECT_THROW(make_integrator("dop853", kBody, TorqueModel::none(), o), InvalidInput);
  o = IntegratorOptions{};
  o.newton_max_iterations = 0;
  EXPECT_THROW(make_integrator("rattle", kBody, TorqueModel::none(), o), InvalidInput);
}

}  // namespace
}  // namespace poinsot::test
