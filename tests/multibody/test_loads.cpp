// Applied loads against the gradient of the potential energy (finite differences) and Φ's skew part.
#include "poinsot/multibody/loads.hpp"

#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using poinsot::test::random_rotation;
using poinsot::test::random_vector;

TEST(Loads, ConservativeLoadsAreMinusTheGradientOfThePotential) {
  System s;
  s.add_body_from_inertia("a", 1.5, Vec3(0.1, 0.2, 0.25).asDiagonal());
  s.add_body_from_inertia("b", 0.5, Vec3(0.1, 0.1, 0.1).asDiagonal());
  s.set_gravity(Vec3(0.3, -1.0, -9.81));
  s.add_spring({"ab", 0, 1, Vec3(0.2, 0.1, 0), Vec3(-0.1, 0, 0.3), 40.0, 0.0, 0.5});
  s.add_spring({"aw", 0, kWorld, Vec3(0, -0.2, 0.1), Vec3(1, 2, 3), 15.0, 0.0, 1.0});
  s.add_force({1, Vec3(1, 2, -3), Vec3(0.1, 0.2, 0.3)});
  std::vector<BodyState> bodies(2);
  for (BodyState& b : bodies) {
    b.x_space = random_vector();
    b.R_space_body = random_rotation();
  }
  std::vector<BodyLoads> loads;
  applied_loads(s, bodies, loads);
  const double h = 1e-6;  // central differences: error O(h²) ≈ 1e-12 plus round-off V·eps/h ≈ 1e-9
  for (std::size_t i = 0; i < 2; ++i) {
    for (int k = 0; k < 3; ++k) {
      auto moved = [&](double t, bool rotate) {
        std::vector<BodyState> m = bodies;
        if (rotate) {
          m[i].R_space_body = bodies[i].R_space_body * so3::exp(t * Vec3::Unit(k));  // δR = R j(δθ)
        } else {
          m[i].x_space += t * Vec3::Unit(k);
        }
        return potential_energy(s, m);
      };
      EXPECT_NEAR(loads[i].force_space(k), -(moved(h, false) - moved(-h, false)) / (2 * h), 1e-7);
      EXPECT_NEAR(loads[i].torque_body(k), -(moved(h, true) - moved(-h, true)) / (2 * h), 1e-7);
    }
    EXPECT_LT((2 * so3::vee(loads[i].phi_body) - loads[i].torque_body).norm(), 1e-13);
  }
}

TEST(Loads, DamperOpposesTheRelativeVelocityAndTorquesFollowTheirFrame) {
  System s;
  s.add_body_from_inertia("a", 1.0, Mat3::Identity());
  s.add_spring({"d", 0, kWorld, Vec3::Zero(), Vec3::Zero(), 0.0, 3.0, 0.0});
  s.add_torque({0, Vec3(0, 0, 2), false});
  s.add_torque({0, Vec3(1, 0, 0), true});
  std::vector<BodyState> bodies(1);
  bodies[0].x_space = Vec3(2, 0, 0);
  bodies[0].v_space = Vec3(0.5, 0.7, 0);
  bodies[0].R_space_body = Eigen::AngleAxisd(0.5 * 3.141592653589793, Vec3::UnitX()).toRotationMatrix();
  std::vector<BodyLoads> loads;
  applied_loads(s, bodies, loads);
  // Along e = x̂ the length grows at 0.5 m/s: f = −c ℓ̇ e = (−1.5, 0, 0).
  EXPECT_LT((loads[0].force_space - Vec3(-1.5, 0, 0)).norm(), 1e-15);
  // Space torque (0,0,2) in the body rotated 90° about x is (0, 2, 0)·(−1)?: Rᵀ ẑ = (0, 1, 0) up to sign.
  const Vec3 expected = bodies[0].R_space_body.transpose() * Vec3(0, 0, 2) + Vec3(1, 0, 0);
  EXPECT_LT((loads[0].torque_body - expected).norm(), 1e-15);
}

}  // namespace
}  // namespace poinsot::multibody
