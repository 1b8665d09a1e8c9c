// Joint constraints: Jacobians and velocity-product terms against finite differences along a motion, loads
// against the virtual work of the multiplier.
#include "poinsot/multibody/constraints.hpp"

#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using poinsot::test::random_rotation;
using poinsot::test::random_vector;

// A body moving with constant v and ω_body: x(t) = x + t v, R(t) = R exp(t j(ω)); also its ẍ = 0, ω̇ = 0.
BodyState at(const BodyState& s, double t) {
  BodyState r = s;
  r.x_space = s.x_space + t * s.v_space;
  r.R_space_body = s.R_space_body * so3::exp(t * s.omega_body);
  return r;
}

std::vector<Joint> sample_joints() {
  System s;
  s.add_body_from_inertia("a", 1, Mat3::Identity());
  s.add_body_from_inertia("b", 1, Mat3::Identity());
  s.add_ball("ball", 0, Vec3(0.3, -0.2, 0.1), 1, Vec3(-0.1, 0.4, 0.2));
  s.add_hinge("hinge", 0, Vec3(0.1, 0.2, 0.3), Vec3(1, 2, 3), 1, Vec3(0.2, 0, -0.1), Vec3(-1, 0, 2));
  s.add_weld("weld", 0, Vec3(0, 0, 0.5), 1, Vec3(0.5, 0, 0), random_rotation());
  s.add_hinge("world hinge", 0, Vec3(0.1, 0.2, 0.3), Vec3(0, 0, 1), kWorld, Vec3(1, 1, 1), Vec3(0, 1, 0));
  s.add_universal("universal", 0, Vec3(0.2, -0.1, 0.3), Vec3(1, -1, 2), 1, Vec3(0.1, 0.3, 0), Vec3(2, 1, 0));
  s.add_universal("offset universal", 0, Vec3(0.2, -0.1, 0.3), Vec3(1, -1, 2), 1, Vec3(0.1, 0.3, 0),
                  Vec3(2, 1, 0), 0.7);
  s.add_universal("world offset universal", 0, Vec3(0.2, -0.1, 0.3), Vec3(1, -1, 2), kWorld,
                  Vec3(0.1, 0.3, 0), Vec3(2, 1, 0), -0.4);
  s.add_prismatic("prismatic", 0, Vec3(0.3, 0.1, -0.2), Vec3(1, 2, -1), 1, Vec3(-0.2, 0.1, 0.4),
                  random_rotation());
  s.add_prismatic("world prismatic", 0, Vec3(0.3, 0.1, -0.2), Vec3(0, 1, 1), kWorld, Vec3(1, 0, 2),
                  random_rotation());
  return s.joints();
}

TEST(Constraints, JacobianAndBiasMatchFiniteDifferences) {
  for (const Joint& joint : sample_joints()) {
    SCOPED_TRACE(joint.name);
    BodyState a, b;
    a.x_space = random_vector();
    a.R_space_body = random_rotation();
    a.v_space = random_vector();
    a.omega_body = random_vector(2.0);
    if (joint.body_b != kWorld) {
      b.x_space = random_vector();
      b.R_space_body = random_rotation();
      b.v_space = random_vector();
      b.omega_body = random_vector(2.0);
    }
    const double h = 1e-4;
    const auto g = [&](double t) { return JointVector(joint_value(joint, at(a, t), at(b, t))); };
    // Central differences: error O(h²) ≈ 1e-8 relative for these O(1) quantities.
    const JointVector g_dot_fd = (g(h) - g(-h)) / (2 * h);
    const JointVector g_ddot_fd = (g(h) - 2 * g(0) + g(-h)) / (h * h);
    JointJacobian Ga, Gb;
    joint_jacobians(joint, a, b, Ga, Gb);
    Vec6 va, vb;
    va << a.v_space, a.omega_body;
    vb << b.v_space, b.omega_body;
    const JointVector g_dot = Ga * va + Gb * vb;
    EXPECT_LT((g_dot - g_dot_fd).cwiseAbs().maxCoeff(), 1e-7);
    // With constant v and ω (zero accelerations), g̈ = γ. The second difference loses about 1e-8/h² ·eps:
    // tolerance 1e-5.
    EXPECT_LT((joint_bias(joint, a, b) - g_ddot_fd).cwiseAbs().maxCoeff(), 1e-5);
    EXPECT_GT(joint_bias(joint, a, b).cwiseAbs().maxCoeff(), 1e-2);  // not vacuous
  }
}

TEST(Constraints, LoadsAreTheVirtualWorkOfTheMultiplier) {
  // For any velocities: λ·ġ = f_a·v_a + τ_a·Ω_a (space) − ... i.e. the power of the loads on both bodies,
  // where the force acts at the joint point. And Φ's skew part is half the body torque.
  for (const Joint& joint : sample_joints()) {
    SCOPED_TRACE(joint.name);
    BodyState a, b;
    a.x_space = random_vector();
    a.R_space_body = random_rotation();
    a.v_space = random_vector();
    a.omega_body = random_vector();
    if (joint.body_b != kWorld) {
      b.x_space = random_vector();
      b.R_space_body = random_rotation();
      b.v_space = random_vector();
      b.omega_body = random_vector();
    }
    JointVector lambda(joint.rows());
    for (int k = 0; k < joint.rows(); ++k)
      lambda(k) = poinsot::test::uniform(-1, 1);
    JointJacobian Ga, Gb;
    joint_jacobians(joint, a, b, Ga, Gb);
    Vec6 va, vb;
    va << a.v_space, a.omega_body;
    vb << b.v_space, b.omega_body;
    const double power = lambda.dot(Ga * va + Gb * vb);
    const JointLoads l = joint_loads(joint, a, b, lambda);
    const Vec3 Oa = a.R_space_body * a.omega_body, Ob = b.R_space_body * b.omega_body;
    const Vec3 pa_dot = a.v_space + Oa.cross(a.R_space_body * joint.point_a);
    // Body b receives the force at the point of space where it acts on a: its own point B (plus h n for
    // offset axes) for point rows, the current position of point A for the line rows of a sliding joint.
    const Vec3 arm_b = joint.sliding ? Vec3(a.x_space + a.R_space_body * joint.point_a - b.x_space)
                                     : Vec3(b.R_space_body * joint.point_b);
    // h n only for offset axes (as point_rows_value): a ball joint has no pin axes to cross, and 0 times
    // their unset values may be NaN.
    const Vec3 offset =
        joint.axis_offset != 0.0 ? Vec3(joint.axis_offset * cross_pin_normal(joint, a, b)) : Vec3::Zero();
    const Vec3 pb_dot = b.v_space + Ob.cross(joint.sliding ? arm_b : Vec3(arm_b + offset));
    const double loads_power = l.force_a_space.dot(pa_dot) - l.force_a_space.dot(pb_dot) +
                               l.torque_a_space.dot(Oa) - l.torque_a_space.dot(Ob);
    EXPECT_NEAR(power, loads_power, 1e-13);
    // Gᵀλ (the fixed-size path for point rows) is the product with the Jacobians.
    Vec6 gen_a = Vec6::Zero(), gen_b = Vec6::Zero();
    add_joint_generalized_forces(joint, Ga, Gb, lambda, gen_a, &gen_b);
    EXPECT_LT((gen_a - Ga.transpose() * lambda).norm(), 1e-14);
    EXPECT_LT((gen_b - Gb.transpose() * lambda).norm(), 1e-14);
    // ġ of joint_velocity is G v.
    EXPECT_LT((joint_velocity(joint, a, b) - (Ga * va + Gb * vb)).norm(), 1e-15);
    // Body torque from Φ: 2 vee(skew Φ_a) = G_θ,aᵀ λ.
    const Vec3 tau_a = Ga.rightCols<3>().transpose() * lambda;
    EXPECT_LT((2 * so3::vee(l.phi_a_body) - tau_a).norm(), 1e-14);
    if (joint.body_b != kWorld) {
      const Vec3 tau_b = Gb.rightCols<3>().transpose() * lambda;
      EXPECT_LT((2 * so3::vee(l.phi_b_body) - tau_b).norm(), 1e-14);
    }
  }
}

}  // namespace
}  // namespace poinsot::multibody
