// The command line's overrides on a multibody scenario (overrides.cpp; the single-body overload is tested
// with the scenario files, test_scenario.cpp).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

constexpr const char* kRod = R"([simulation]
dt = 1e-3
order = 4
[[bodies]]
name = "rod"
mass = 1.0
shape = { type = "rod", length = 1.0, radius = 0.01 }
)";

std::string error_of(multibody::Scenario sc, const ScenarioOverrides& o) {
  return test::message_of<InvalidInput>([&] { apply_overrides(sc, o); }, "apply_overrides");
}

TEST(Overrides, MultibodyStepDurationAndRowRate) {
  multibody::Scenario sc = parse_multibody_scenario(kRod, "rod.toml");
  ScenarioOverrides o;
  o.dt = 2e-3;
  o.t_end = 3.0;
  o.sample_dt = 0.0205;  // 10.25 steps of 2 ms: the nearest whole number of steps
  apply_overrides(sc, o);
  EXPECT_EQ(sc.dt, 2e-3);
  EXPECT_EQ(sc.duration, 3.0);
  EXPECT_EQ(sc.output_every, 10);
  ScenarioOverrides tiny;
  tiny.sample_dt = 1e-9;  // below one step: every step
  apply_overrides(sc, tiny);
  EXPECT_EQ(sc.output_every, 1);
}

TEST(Overrides, MultibodyMethodRk4IsOrderFourAndRattleKeepsTheFilesOrder) {
  multibody::Scenario sc = parse_multibody_scenario(kRod, "rod.toml");
  ScenarioOverrides o;
  o.method = "rk4";
  apply_overrides(sc, o);
  EXPECT_EQ(sc.method, multibody::MultibodyMethod::projected_rk4);
  EXPECT_EQ(sc.order, 4);
  sc = parse_multibody_scenario(kRod, "rod.toml");
  o.method = "rattle";
  apply_overrides(sc, o);
  EXPECT_EQ(sc.method, multibody::MultibodyMethod::rattle);
  EXPECT_EQ(sc.order, 4);  // the file's order = 4
}

TEST(Overrides, MultibodyBadValuesAreOneLineNamingTheOption) {
  const multibody::Scenario sc = parse_multibody_scenario(kRod, "rod.toml");
  ScenarioOverrides o;
  o.method = "euler";
  // The registry's message, which lists every multibody method (multibody/methods.hpp).
  const std::string message = error_of(sc, o);
  EXPECT_EQ(message.rfind("--method: got \"euler\", expected ", 0), 0u) << message;
  for (const multibody::MultibodyMethodInfo& m : multibody::multibody_methods())
    EXPECT_NE(message.find(m.name), std::string::npos) << message;
  o = {};
  o.dt = 0.0;
  EXPECT_EQ(error_of(sc, o), "--dt: got 0 s, expected a number > 0");
  o = {};
  o.t_end = std::nan("");
  EXPECT_EQ(error_of(sc, o), "--t-end: got nan s, expected a number > 0");
  o = {};
  o.sample_dt = -1.0;
  EXPECT_EQ(error_of(sc, o), "--sample-dt: got -1 s, expected a number > 0");
}

}  // namespace
}  // namespace poinsot::io
