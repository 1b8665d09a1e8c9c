#include "poinsot/core/check.hpp"

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot {
namespace {

using test::message_of;

TEST(Check, MessagesNameTheFieldTheValueAndWhatWasExpected) {
  EXPECT_EQ(message_of([] { require_positive("box: mass", -2.0, "kg"); }),
            "box: mass: got -2 kg, expected a finite number > 0");
  EXPECT_EQ(message_of([] { require_finite("omega_body", Vec3(1, NAN, 0)); }),
            "omega_body: got (1, nan, 0), expected finite numbers");
  EXPECT_EQ(message_of([] { require_non_negative("t", -1e-3); }),
            "t: got -0.001, expected a finite number >= 0");
}

TEST(Check, AcceptsValidValues) {
  EXPECT_NO_THROW(require_positive("x", 1e-300));
  EXPECT_NO_THROW(require_non_negative("x", 0.0));
  EXPECT_NO_THROW(require_finite("x", Mat3(Mat3::Identity())));
  EXPECT_THROW(require_positive("x", 0.0), InvalidInput);
  EXPECT_THROW(require_positive("x", INFINITY), InvalidInput);
  EXPECT_THROW(require_finite("x", Quat(NAN, 0, 0, 0)), InvalidInput);
}

TEST(Check, InvalidInputIsAPoinsotError) {
  EXPECT_THROW(require_positive("x", -1.0), Error);
}

}  // namespace
}  // namespace poinsot
