// Torque models: gravity against the derivative of its potential (τ_i = −dV/dε for R exp(ε j(e_i))) and
// against the moment of the weight in space, constant torques in either frame, the callback, and errors.
#include "poinsot/dynamics/torque.hpp"

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::RigidBody;
using dynamics::TorqueModel;

TEST(Torque, GravityIsMinusTheGradientOfItsPotential) {
  const Vec3 d(0.02, -0.03, 0.1);
  const RigidBody top = RigidBody::from_principal_moments(Vec3(0.002, 0.002, 0.004)).with_pivot(1.3, d);
  const Vec3 g(0.5, -0.2, -9.81);
  const auto gravity = TorqueModel::gravity(top, g);
  dynamics::State s;
  s.R_space_body = so3::exp(Vec3(0.7, -0.4, 0.2));
  const Vec3 tau = gravity->torque_body(0.0, s.R_space_body, Vec3::Zero());
  const double eps = 1e-6;
  for (int i = 0; i < 3; ++i) {
    dynamics::State p = s, m = s;
    p.R_space_body = s.R_space_body * so3::exp(eps * Vec3::Unit(i));
    m.R_space_body = s.R_space_body * so3::exp(-eps * Vec3::Unit(i));
    const double dV =
        (dynamics::potential_energy(top, p, g) - dynamics::potential_energy(top, m, g)) / (2 * eps);
    EXPECT_NEAR(tau[i], -dV, 1e-9) << i;  // central difference, error ~eps²
  }
  // The moment about the pivot of the weight m g at the centre of mass, in space: (R d) × (m g).
  EXPECT_LT(max_abs_diff(Vec3(s.R_space_body * tau), Vec3((s.R_space_body * d).cross(1.3 * g))), 1e-15);
  EXPECT_TRUE(gravity->is_gravity());
  EXPECT_EQ(gravity->gravity_space(), g);
  EXPECT_FALSE(gravity->depends_on_omega());
}

TEST(Torque, ConstantTorquesInBodyAndSpace) {
  const Mat3 R = so3::exp(Vec3(0.1, 0.9, -0.3));
  const Vec3 t(0.3, -0.1, 0.2);
  EXPECT_EQ(TorqueModel::constant_body(t)->torque_body(1.0, R, Vec3(1, 2, 3)), t);
  EXPECT_LT(max_abs_diff(Vec3(R * TorqueModel::constant_space(t)->torque_body(1.0, R, Vec3(1, 2, 3))), t),
            1e-15);
  const auto none = TorqueModel::none();
  EXPECT_TRUE(none->is_zero());
  EXPECT_EQ(none->torque_body(0.0, R, Vec3(1, 2, 3)), Vec3::Zero());
  EXPECT_EQ(none->describe(), "none");
  EXPECT_FALSE(TorqueModel::constant_body(t)->is_zero());
}

TEST(Torque, CallbackReceivesTimeAttitudeAndAngularVelocity) {
  const auto cb = TorqueModel::callback(
      [](double time, const Mat3& R, const Vec3& w) { return Vec3(time * R(0, 0) * w.x(), 0, 0); }, true,
      "test");
  EXPECT_EQ(cb->torque_body(2.0, Mat3::Identity(), Vec3(3, 0, 0)), Vec3(6, 0, 0));
  EXPECT_TRUE(cb->depends_on_omega());
  EXPECT_EQ(cb->describe(), "test");
}

TEST(Torque, RejectsBadInput) {
  EXPECT_THROW(TorqueModel::gravity(RigidBody::from_principal_moments(Vec3(1, 2, 2)), Vec3(0, 0, -9.81)),
               InvalidInput);  // no pivot
  EXPECT_THROW(TorqueModel::callback(nullptr), InvalidInput);
  EXPECT_THROW(TorqueModel::constant_body(Vec3(0, std::nan(""), 0)), InvalidInput);
  EXPECT_THROW(TorqueModel::constant_space(Vec3(0, std::numeric_limits<double>::infinity(), 0)),
               InvalidInput);
}

}  // namespace
}  // namespace poinsot::test
