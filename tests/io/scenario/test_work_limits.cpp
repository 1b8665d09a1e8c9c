// Tests of work_limits.hpp: a scenario whose step or sample count is over the limit is refused when it is
// read (one line naming the limit and the variable that raises it), and the variable raises it.
#include "poinsot/io/scenario/work_limits.hpp"

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/io/scenario/multibody_scenario.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

std::string single(const std::string& t_end, const std::string& dt, const std::string& sample_dt) {
  return "[body]\nshape = { type = \"box\", size = [1, 2, 3], mass = 1 }\n[initial]\nomega_body = [0, 1, 0]\n"
         "[integrator]\nmethod = \"rk4\"\ndt = " +
         dt + "\n[output]\nt_end = " + t_end + "\nsample_dt = " + sample_dt + "\n";
}

std::string refusal(const std::string& text) {
  return test::message_of<InvalidInput>([&] { parse_scenario(text, "s.toml"); }, text);
}

/// Sets an environment variable for the lifetime of the object.
struct ScopedEnv {
  const char* name;
  ScopedEnv(const char* n, const char* value) : name(n) { ::setenv(n, value, 1); }
  ~ScopedEnv() { ::unsetenv(name); }
};

TEST(WorkLimits, StepsAndSamplesOverTheLimitAreRefusedWhenRead) {
  EXPECT_NO_THROW(parse_scenario(single("10", "1e-3", "0.01"), "s.toml"));
  test::expect_has(
      refusal(single("1e7", "1e-3", "1e6")),
      {"s.toml:", "[output] t_end", "t_end / dt = 1e+10 steps", "the limit is 1e+09", "POINSOT_MAX_STEPS"});
  test::expect_has(refusal(single("10", "1e-3", "1e-7")),
                   {"t_end / sample_dt = 1e+08 samples", "the limit is 1e+07", "POINSOT_MAX_SAMPLES"});
  const std::string m =
      "[simulation]\ndt = 1e-9\nduration = 10\n[[bodies]]\nname = \"a\"\nshape = { type = \"sphere\", radius "
      "= "
      "1, mass = 1 }\n";
  POINSOT_EXPECT_THROWS_MESSAGE(parse_multibody_scenario(m, "m.toml"), InvalidInput,
                                "duration / dt = 1e+10 steps", "POINSOT_MAX_STEPS");
}

TEST(WorkLimits, OverridesAreCheckedToo) {
  Scenario sc = parse_scenario(single("10", "1e-3", "0.01"), "s.toml");
  ScenarioOverrides o;
  o.dt = 1e-12;
  POINSOT_EXPECT_THROWS_MESSAGE(apply_overrides(sc, o), InvalidInput, "--t-end/--dt", "1e+13 steps");
}

TEST(WorkLimits, TheEnvironmentRaisesTheLimits) {
  const ScopedEnv steps("POINSOT_MAX_STEPS", "1e11");
  const ScopedEnv samples("POINSOT_MAX_SAMPLES", "1e9");
  EXPECT_EQ(work_limits().max_steps, 1e11);
  EXPECT_EQ(work_limits().max_samples, 1e9);
  EXPECT_NO_THROW(parse_scenario(single("1e7", "1e-3", "1e6"), "s.toml"));
  const ScopedEnv bad("POINSOT_MAX_STEPS", "-3");  // not a positive number: the default stays
  EXPECT_EQ(work_limits().max_steps, 1e9);
}

}  // namespace
}  // namespace poinsot::io
