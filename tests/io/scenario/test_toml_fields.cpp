// Typed, located TOML access (src/io/scenario/toml_fields.cpp).
#include "../../../src/io/scenario/toml_fields.hpp"

#include <gtest/gtest.h>

#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io::detail {
namespace {

std::string message(const std::function<void()>& f) {
  return test::message_of(f);
}

TEST(TomlFields, NumbersVectorsAndMatricesWithTheirPlace) {
  const toml::table t = toml::parse(
      "a = 3\nb = 2.5\nv = [1, 2.5, -3]\nm = [[1, 2, 3], [4, 5, 6], [7, 8, 9]]\n"
      "s = \"x\"\nf = true\n");
  const Source src{"f.toml"};
  const Section s(src, &t, "sec", {"a", "b", "v", "m", "s", "f", "absent"});
  EXPECT_EQ(*s.number("a"), 3.0);
  EXPECT_EQ(*s.number("b"), 2.5);
  EXPECT_FALSE(s.number("absent"));
  EXPECT_EQ(*s.vec3("v"), Vec3(1, 2.5, -3));
  EXPECT_EQ((*s.mat3("m"))(1, 2), 6.0);
  EXPECT_EQ(*s.string("s"), "x");
  EXPECT_TRUE(*s.boolean("f"));
  EXPECT_EQ(message([&] { (void)s.number("s"); }), "f.toml:5:5: [sec] s: got \"x\", expected a number");
  EXPECT_EQ(message([&] { (void)s.vec3("m"); }).rfind("f.toml:4:5: [sec] m: got [[1, 2, 3]", 0), 0u);
  EXPECT_EQ(message([&] { (void)s.boolean("a"); }), "f.toml:1:5: [sec] a: got 3, expected true or false");
}

TEST(TomlFields, UnknownKeysAndExactlyOne) {
  const toml::table t = toml::parse("x = 1\ny = 2\n");
  const Source src{"g.toml"};
  EXPECT_EQ(message([&] {
              Section(src, &t, "sec", {"x", "z"});
            }),
            "g.toml:2:1: [sec] unknown key \"y\"; valid keys: x, z");
  const Section s(src, &t, "sec", {"x", "y", "z"});
  EXPECT_EQ(s.exactly_one({"x", "z"}, "the thing"), "x");
  EXPECT_EQ(message([&] {
              (void)s.exactly_one({"x", "y"}, "the thing");
            }),
            "g.toml:2:5: [sec] the thing is given 2 times (x and y); expected exactly one of x, y");
  EXPECT_NE(message([&] { (void)s.exactly_one({"z"}, "the other"); }).find("the other is missing"),
            std::string::npos);
}

}  // namespace
}  // namespace poinsot::io::detail
