// The contract every multibody method of the registry (multibody/methods.hpp) must meet, run on each entry
// and each order it offers: a new method is tested here as soon as it has its entry. Its measured order
// equals the declared one; R stays a rotation to round-off and the joints closed to the method's tolerance; a
// method that declares momentum conservation conserves it on a free system; stepping allocates nothing; a
// rotated body frame gives the same motion; repeated runs are bit-identical.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "allocation_counter.hpp"
#include "multibody_fixtures.hpp"
#include "poinsot/multibody/methods.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody::test {
namespace {

struct Case {
  const MultibodyMethodInfo* info;
  int order;
};

std::vector<Case> cases() {
  std::vector<Case> out;
  for (const MultibodyMethodInfo& m : multibody_methods())
    for (int order = m.order; order <= m.max_order; order += 2)
      out.push_back({&m, order});
  return out;
}

/// A double pendulum of two rods (1 m, 1 kg) joined by ball joints, hung from the world, falling from the
/// horizontal with a twist; the second rod's body frame is rotated by Q (its K and anchor written in that
/// frame, its R and ω transformed accordingly: the same motion).
std::pair<System, State> double_pendulum(const Mat3& Q = Mat3::Identity()) {
  System s;
  const Mat3 K = rod_poinsot(1.0, 1.0, 0.05);
  s.add_body("a", 1.0, K);
  s.add_body("b", 1.0, Q * K * Q.transpose());
  s.add_ball("pivot", 0, Vec3(-0.5, 0, 0), kWorld, Vec3::Zero());
  s.add_ball("elbow", 1, Q * Vec3(-0.5, 0, 0), 0, Vec3(0.5, 0, 0));
  s.set_gravity(Vec3(0, 0, -kG));
  State st = rod_chain_state(2);
  st.bodies[0].omega_body = Vec3(0.3, 0.5, -1.0);
  st.bodies[1].omega_body = Vec3(-0.4, 1.0, 2.0);
  st.bodies[1].R_space_body = st.bodies[1].R_space_body * Q.transpose();
  st.bodies[1].omega_body = Q * st.bodies[1].omega_body;
  project_velocities(s, st);  // frame-independent: the kinetic-energy metric and the joints are
  return {s, st};
}

/// Two different bodies joined by a ball joint, nothing else: no gravity, no joint to the world, so the
/// linear and angular momentum are constants of the motion.
std::pair<System, State> free_pair() {
  System s;
  s.add_body_from_inertia("a", 2.0, Vec3(0.1, 0.2, 0.25).asDiagonal());
  s.add_body_from_inertia("b", 1.0, Vec3(0.05, 0.08, 0.11).asDiagonal());
  s.add_ball("ball", 0, Vec3(0.5, 0, 0), 1, Vec3(-0.5, 0.1, 0));
  State st;
  st.bodies.resize(2);
  st.bodies[1].x_space = Vec3(1.0, -0.1, 0);
  st.bodies[0].v_space = Vec3(0.1, 0.2, -0.3);
  st.bodies[0].omega_body = Vec3(1.0, -2.0, 0.5);
  st.bodies[1].omega_body = Vec3(-1.5, 0.7, 3.0);
  project_velocities(s, st);
  return {s, st};
}

class MethodContract : public ::testing::TestWithParam<Case> {
 protected:
  const MultibodyMethodInfo& info() const { return *GetParam().info; }
  std::unique_ptr<MultibodyIntegrator> make(const System& s, double dt) const {
    return info().make(s, dt, GetParam().order);
  }
  State run(const System& s, State st, double dt, int n) const {
    auto m = make(s, dt);
    for (int i = 0; i < n; ++i)
      m->step(st);
    return st;
  }
};

/// max over bodies of |Δx| (m) and max |ΔR|.
double difference(const State& a, const State& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    d = std::max(d, (a.bodies[i].x_space - b.bodies[i].x_space).cwiseAbs().maxCoeff());
    d = std::max(d, (a.bodies[i].R_space_body - b.bodies[i].R_space_body).cwiseAbs().maxCoeff());
  }
  return d;
}

TEST_P(MethodContract, IsItsRegistryEntry) {
  EXPECT_EQ(&multibody_method_info(info().method), &info());
  EXPECT_EQ(parse_multibody_method(info().name, "method"), info().method);
  EXPECT_STREQ(multibody_method_name(info().method), std::string(info().name).c_str());
  EXPECT_EQ(order_for_method(info().method, GetParam().order), GetParam().order);
  EXPECT_FALSE(info().description.empty());
}

// Self-convergence on [0, 0.4] s with n, 2n, 4n steps (no reference needed): the differences of successive
// runs shrink by 2^p. h = 0.02 s at n, hω ≈ 0.05: the asymptotic range, with the finest differences (≥ 1e-10)
// far above the Newton and projection tolerances (1e-13); ±0.3 for the next error term.
TEST_P(MethodContract, MeasuredOrderIsTheDeclaredOrder) {
  const auto [sys, s0] = double_pendulum();
  const int n = 20;
  const State a = run(sys, s0, 0.4 / n, n);
  const State b = run(sys, s0, 0.4 / (2 * n), 2 * n);
  const State c = run(sys, s0, 0.4 / (4 * n), 4 * n);
  const double e1 = difference(a, b);
  const double e2 = difference(b, c);
  EXPECT_GT(e2, 1e-11);
  EXPECT_NEAR(std::log2(e1 / e2), GetParam().order, 0.3) << "differences " << e1 << ", " << e2;
}

// 400 steps of 5 ms (2 s, the double pendulum swinging through the vertical): ‖RᵀR − I‖_F at round-off (a few
// tens of ulp: the Frobenius norm sums nine entries of a few ulp each, so up to 3 times their largest) and
// the joints closed to the methods' tolerance (1e-13 relative to the 1 m length scale, with margin).
TEST_P(MethodContract, KeepsRotationsAndJoints) {
  const auto [sys, s0] = double_pendulum();
  const State s = run(sys, s0, 0.005, 400 / test::slowdown());
  const ConstraintViolation v = constraint_violation(sys, s);
  if (info().preserves.orthogonality) {
    EXPECT_LT(v.orthogonality, 3e-14);
  }
  if (info().preserves.joints) {
    EXPECT_LT(v.joint_gap, 1e-12);
  }
}

// A free pair: RATTLE conserves P and L exactly up to its Newton tolerance, 1e-13 relative per step; 200
// steps of 10 ms give a bound of 1e-11 (|P| = 0.6 kg·m/s, |L| ≈ 0.6 kg·m²/s).
TEST_P(MethodContract, ConservesMomentumWhenDeclared) {
  if (!info().preserves.momentum) GTEST_SKIP() << info().name << " does not declare momentum conservation";
  const auto [sys, s0] = free_pair();
  const State s = run(sys, s0, 0.01, 200 / test::slowdown());
  const Vec3 P0 = linear_momentum(sys, s0);
  const Vec3 L0 = angular_momentum(sys, s0);
  POINSOT_EXPECT_MATRIX_REL_NEAR(linear_momentum(sys, s), P0, 1e-11);
  POINSOT_EXPECT_MATRIX_REL_NEAR(angular_momentum(sys, s), L0, 1e-11);
}

TEST_P(MethodContract, StepsWithoutAllocating) {
  const auto [sys, s0] = double_pendulum();
  auto m = make(sys, 0.005);
  State s = s0;
  m->step(s);  // the first step may size the work space
  const long long before = poinsot::test::allocation_count();
  for (int i = 0; i < 50; ++i)
    m->step(s);
  EXPECT_EQ(poinsot::test::allocation_count(), before);
}

// The second rod in a body frame rotated by Q: x the same, R_b = R Qᵀ, ω_b = Q ω at all times. Every method
// is equivariant under that change of frame; the runs agree to round-off amplified over 100 steps, and to the
// Newton and projection tolerances: 1e-11.
TEST_P(MethodContract, SameMotionInARotatedBodyFrame) {
  const Mat3 Q = so3::exp(Vec3(0.4, -0.7, 0.2));
  const auto [sys, s0] = double_pendulum();
  const auto [rot, r0] = double_pendulum(Q);
  const State p = run(sys, s0, 0.005, 100);
  const State q = run(rot, r0, 0.005, 100);
  for (std::size_t i = 0; i < 2; ++i) {
    POINSOT_EXPECT_MATRIX_NEAR(q.bodies[i].x_space, p.bodies[i].x_space, 1e-11);
  }
  POINSOT_EXPECT_MATRIX_NEAR(q.bodies[1].R_space_body, Mat3(p.bodies[1].R_space_body * Q.transpose()), 1e-11);
  POINSOT_EXPECT_MATRIX_NEAR(q.bodies[1].omega_body, Vec3(Q * p.bodies[1].omega_body), 1e-10);
}

TEST_P(MethodContract, RepeatedRunsAreBitIdentical) {
  const auto [sys, s0] = double_pendulum();
  const State a = run(sys, s0, 0.005, 50);
  const State b = run(sys, s0, 0.005, 50);
  EXPECT_EQ(a.time, b.time);
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    EXPECT_TRUE(a.bodies[i].x_space == b.bodies[i].x_space);
    EXPECT_TRUE(a.bodies[i].R_space_body == b.bodies[i].R_space_body);
    EXPECT_TRUE(a.bodies[i].v_space == b.bodies[i].v_space);
    EXPECT_TRUE(a.bodies[i].omega_body == b.bodies[i].omega_body);
  }
}

TEST(MultibodyMethods, UnknownNameListsEveryEntry) {
  POINSOT_EXPECT_THROWS_MESSAGE(
      parse_multibody_method("euler", "--method"), InvalidInput,
      "--method: got \"euler\", expected \"rattle\" (RATTLE, symplectic) or \"rk4\"");
  EXPECT_EQ(multibody_method_names(), "rattle, rk4");
  EXPECT_EQ(order_for_method(MultibodyMethod::projected_rk4, 2), 4);
  EXPECT_EQ(order_for_method(MultibodyMethod::rattle, 4), 4);
  EXPECT_EQ(multibody_methods().front().method, kDefaultMultibodyMethod);
}

INSTANTIATE_TEST_SUITE_P(Registry, MethodContract, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           return std::string(p.param.info->name) + "_order" + std::to_string(p.param.order);
                         });

}  // namespace
}  // namespace poinsot::multibody::test
