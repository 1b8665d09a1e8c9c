// Model validation: each bad input throws InvalidInput with the field named.
#include "poinsot/multibody/model.hpp"

#include <cmath>
#include <functional>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

std::string error_of(const std::function<void()>& f) {
  return poinsot::test::message_of(f);
}

TEST(Model, BodiesAreValidated) {
  System s;
  EXPECT_NE(error_of([&] { s.add_body("a", -1, Mat3::Identity()); }).find("body 'a': mass"),
            std::string::npos);
  // A thin rod with no radius: J has a zero moment about the axis.
  EXPECT_NE(error_of([&] { s.add_body("rod", 1, Vec3(1, 0, 0).asDiagonal()); }).find("positive definite"),
            std::string::npos);
  // J violating the triangle inequality gives K with a negative eigenvalue.
  EXPECT_NE(error_of([&] {
              s.add_body_from_inertia("bad", 1, Vec3(1, 1, 5).asDiagonal());
            }).find("positive semi-definite"),
            std::string::npos);
  Mat3 asym = Mat3::Identity();
  asym(0, 1) = 0.5;
  EXPECT_NE(error_of([&] { s.add_body("asym", 1, asym); }).find("not symmetric"), std::string::npos);
  // A lamina (K singular, J positive definite) is accepted.
  EXPECT_EQ(s.add_body("plate", 1, Vec3(2, 1, 0).asDiagonal()), 0);
  EXPECT_LT((s.bodies()[0].inertia - Mat3(Vec3(1, 2, 3).asDiagonal())).norm(), 1e-15);
  EXPECT_NE(error_of([&] { s.add_body("plate", 1, Mat3::Identity()); }).find("already used"),
            std::string::npos);
  EXPECT_NE(error_of([&] { s.add_body("world", 1, Mat3::Identity()); }).find("reserved"), std::string::npos);
}

TEST(Model, JointsAndLoadsAreValidated) {
  System s;
  s.add_body("a", 1, Mat3::Identity());
  EXPECT_NE(error_of([&] { s.add_ball("j", 0, Vec3::Zero(), 0, Vec3::Zero()); }).find("to itself"),
            std::string::npos);
  EXPECT_NE(error_of([&] { s.add_ball("j", 3, Vec3::Zero(), kWorld, Vec3::Zero()); }).find("out of range"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              s.add_hinge("h", 0, Vec3::Zero(), Vec3::Zero(), kWorld, Vec3::Zero(), Vec3::UnitZ());
            }).find("axis a"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              s.add_weld("w", 0, Vec3::Zero(), kWorld, Vec3::Zero(), 2 * Mat3::Identity());
            }).find("not a rotation"),
            std::string::npos);
  EXPECT_NE(error_of([&] {
              s.add_spring({"s", 0, kWorld, Vec3::Zero(), Vec3::Zero(), -1, 0, 0});
            }).find("stiffness"),
            std::string::npos);
  s.add_hinge("h", 0, Vec3(1, 0, 0), Vec3(0, 0, 2), kWorld, Vec3::Zero(), Vec3(0, 0, 1));
  const Joint& h = s.joints()[0];
  EXPECT_EQ(h.rows(), 5);
  // The hinge's two vectors are unit and perpendicular to the axis and to each other.
  EXPECT_NEAR(h.p_a[0].dot(Vec3::UnitZ()), 0, 1e-16);
  EXPECT_NEAR(h.p_a[1].dot(Vec3::UnitZ()), 0, 1e-16);
  EXPECT_NEAR(h.p_a[0].dot(h.p_a[1]), 0, 1e-16);
  EXPECT_EQ(s.body_index("world"), kWorld);
  EXPECT_THROW(s.body_index("nobody"), InvalidInput);
  EXPECT_DOUBLE_EQ(s.length_scale(), std::sqrt(3.0));  // √(tr K / m) beats the lever arm 1 m
}

}  // namespace
}  // namespace poinsot::multibody
