// Tests of error.hpp: every message is one line, whatever the text it quotes.
#include "poinsot/core/error.hpp"

#include <string>

#include <gtest/gtest.h>

namespace poinsot {
namespace {

TEST(Error, LineBreaksInTheMessageBecomeSpaces) {
  const InvalidInput bad("shape: got \"a\nb\r\nc\", expected box");
  EXPECT_EQ(std::string(bad.what()), "shape: got \"a b  c\", expected box");
  const ComputationFailed failed("step\n");
  EXPECT_EQ(std::string(failed.what()), "step ");
  EXPECT_EQ(std::string(Error("one line").what()), "one line");
}

}  // namespace
}  // namespace poinsot
