// POINSOT_ASSERT: aborts with the condition and the message where assertions are on (debug and sanitizer
// builds), and does not even evaluate its condition where they are off (release).
#include "poinsot/core/assert.hpp"

#include <gtest/gtest.h>

namespace poinsot {
namespace {

TEST(Assert, PassingConditionDoesNothing) {
  int evaluated = 0;
  POINSOT_ASSERT(++evaluated == 1, "evaluated once when on");
  EXPECT_EQ(evaluated, POINSOT_ASSERTS_ENABLED ? 1 : 0);
}

// The failure handler, in every build: the CI's sanitizer tree links this file compiled for release, where
// the macro below is off, against a library whose assertions are on.
TEST(AssertDeathTest, HandlerAbortsWithTheConditionAndItsMessage) {
  EXPECT_DEATH(detail::assertion_failed("index < size", "body index in range", "kkt_solver.cpp", 42),
               "poinsot: internal error: kkt_solver.cpp:42: index < size \\(body index in range\\)");
}

#if POINSOT_ASSERTS_ENABLED
TEST(AssertDeathTest, FailingConditionAbortsWithItsMessage) {
  const int index = 7;
  const int size = 3;
  EXPECT_DEATH(POINSOT_ASSERT(index < size, "body index in range"),
               "poinsot: internal error: .*test_assert.cpp:[0-9]+: index < size \\(body index in range\\)");
}
#else
TEST(Assert, FailingConditionIsNotEvaluatedInRelease) {
  int evaluated = 0;
  POINSOT_ASSERT(++evaluated < 0, "never evaluated");
  EXPECT_EQ(evaluated, 0);
}
#endif

}  // namespace
}  // namespace poinsot
