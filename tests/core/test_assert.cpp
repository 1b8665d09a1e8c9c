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
