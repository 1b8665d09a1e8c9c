// The joint-type table, and the universal and prismatic joints against independent formulations: a slider
// on a fixed line (closed form), a bead on a rotating rod and a Cardan-hung link (their
// generalised-coordinate Lagrange equations, integrated by a scalar RK4 with a much smaller step). Positions
// converge at the integrators' orders, the joints hold to round-off, energy is conserved.
#include "poinsot/multibody/joint_types.hpp"

#include <cmath>
#include <functional>
#include <string>

#include <fmt/format.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "multibody_fixtures.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using test::kG;  // the fixtures' gravity, m/s²

Mat3 rot(const Vec3& axis, double angle) {
  return Eigen::AngleAxisd(angle, axis.normalized()).toRotationMatrix();
}

TEST(JointTypes, TableMatchesTheModel) {
  System s;
  s.add_body("a", 1, Mat3::Identity());
  s.add_ball("ball", 0, Vec3::Zero(), kWorld, Vec3::Zero());
  s.add_hinge("hinge", 0, Vec3::Zero(), Vec3::UnitZ(), kWorld, Vec3::Zero(), Vec3::UnitZ());
  s.add_weld("weld", 0, Vec3::Zero(), kWorld, Vec3::Zero(), Mat3::Identity());
  s.add_universal("universal", 0, Vec3::Zero(), Vec3::UnitX(), kWorld, Vec3::Zero(), Vec3::UnitY());
  s.add_prismatic("prismatic", 0, Vec3::Zero(), Vec3::UnitZ(), kWorld, Vec3::Zero(), Mat3::Identity());
  ASSERT_EQ(joint_types().size(), s.joints().size());
  for (const Joint& joint : s.joints()) {
    const JointTypeInfo& info = joint_type_info(joint.type);
    EXPECT_EQ(info.name, joint.name);
    EXPECT_EQ(info.rows, joint.rows()) << joint.name;
    EXPECT_EQ(find_joint_type(joint.name), &info);
  }
  EXPECT_EQ(find_joint_type("slider"), nullptr);
  EXPECT_EQ(joint_type_names(), "\"ball\", \"hinge\", \"weld\", \"universal\" or \"prismatic\"");
  EXPECT_THROW(s.add_prismatic("p", 0, Vec3::Zero(), Vec3::Zero(), kWorld, Vec3::Zero(), Mat3::Identity()),
               InvalidInput);
  EXPECT_THROW(s.add_universal("u", 0, Vec3::Zero(), Vec3::UnitX(), kWorld, Vec3::Zero(), Vec3::Zero()),
               InvalidInput);
}

/// The errors at h and h/2 in the test's XML record (--gtest_output=xml), for the docs' figures.
void record_errors(const std::string& method, double at_h, double at_half_h) {
  ::testing::Test::RecordProperty(method + "_error_h", fmt::format("{:.3e}", at_h));
  ::testing::Test::RecordProperty(method + "_error_h_half", fmt::format("{:.3e}", at_half_h));
}

/// Steps `integrator` from `start` to time T (a whole number of steps).
template <class Integrator>
State run(Integrator integrator, State start, double T) {
  const long n = std::lround(T / integrator.dt());
  for (long k = 0; k < n; ++k)
    integrator.step(start);
  return start;
}

// ---- A slider on a fixed inclined line, pulled by a spring along the line: m s̈ = m g·e − k (s + 1). ----

struct Slider {
  double m = 1.5, k = 40.0, s0 = 0.5, s_dot0 = 0.3;
  Vec3 e = Vec3(1, 0.5, -0.8).normalized();  // the line's direction, space frame
  Vec3 B = Vec3(0.3, -0.1, 0.2);             // a point of the line, space frame, m
  Vec3 A = Vec3(0.1, -0.2, 0.05);            // the joint point, body frame, from the centre of mass
  Mat3 R0 = rot(Vec3(1, 2, 3), 0.7);         // the body's fixed orientation
  System system;
  State start;

  Slider() {
    system.add_body("slider", m, Vec3(0.02, 0.05, 0.08).asDiagonal());
    system.add_prismatic("slide", 0, A, R0.transpose() * e, kWorld, B, R0);
    // Spring from the joint point to the world point 1 m behind B on the line (ℓ = s + 1 > 0, rest 0).
    Spring spring{"spring", 0, kWorld, A, B - e, k, 0.0, 0.0};
    system.add_spring(spring);
    system.set_gravity(Vec3(0, 0, -kG));
    start.bodies.resize(1);
    start.bodies[0].R_space_body = R0;
    start.bodies[0].x_space = B + s0 * e - R0 * A;
    start.bodies[0].v_space = s_dot0 * e;
    check_consistent(system, start);
  }
  /// The centre of mass at t in closed form.
  Vec3 exact_position(double t) const {
    const double w = std::sqrt(k / m);
    const double s_eq = m * Vec3(0, 0, -kG).dot(e) / k - 1.0;
    const double s = s_eq + (s0 - s_eq) * std::cos(w * t) + s_dot0 / w * std::sin(w * t);
    return B + s * e - R0 * A;
  }
};

TEST(PrismaticJoint, SliderMatchesTheClosedFormAtTheIntegratorsOrders) {
  const Slider sl;
  const double T = 2.0;
  const Vec3 x_exact = sl.exact_position(T);
  const auto error = [&](const State& s) { return (s.bodies[0].x_space - x_exact).norm(); };
  // RATTLE (order 2): the phase error of a harmonic oscillator, (ωh)²/24 per radian: over ωT = 10.3 rad with
  // amplitude 1.29 m, 3.7e-4 m at h = 5e-3.
  const State r1 = run(Rattle(sl.system, 1e-2), sl.start, T);
  const State r2 = run(Rattle(sl.system, 5e-3), sl.start, T);
  EXPECT_NEAR(error(r1) / error(r2), 4.0, 0.2) << error(r1) << " " << error(r2);
  EXPECT_LT(error(r2), 5e-4);
  record_errors("rattle", error(r1), error(r2));
  // Projected RK4 (order 4).
  const State k1 = run(ProjectedRk4(sl.system, 1e-2), sl.start, T);
  const State k2 = run(ProjectedRk4(sl.system, 5e-3), sl.start, T);
  EXPECT_NEAR(error(k1) / error(k2), 16.0, 1.6) << error(k1) << " " << error(k2);
  record_errors("rk4", error(k1), error(k2));
  for (const State* s : {&r2, &k2}) {
    // The rotation is locked: R stays R0, and the joint holds, to round-off (Newton to 1e-13).
    EXPECT_LT(so3::angle_between(s->bodies[0].R_space_body, sl.R0), 1e-13);
    const ConstraintViolation v = constraint_violation(sl.system, *s);
    EXPECT_LT(v.joint_gap, 1e-12);
    EXPECT_LT(v.joint_angle, 1e-13);
    EXPECT_LT(v.joint_velocity, 1e-12);
  }
  // RATTLE conserves the energy of this linear oscillator to O(h²) without drift: E ≈ 6 J, the error ~1e-5 J.
  const double E0 = total_energy(sl.system, sl.start);
  EXPECT_LT(std::abs(total_energy(sl.system, r2) - E0), 1e-4 * std::abs(E0));
}

TEST(PrismaticJoint, ReactionIsTheWeightAcrossTheLine) {
  // At any state the joint force balances the weight across the line (the spring acts along it), and the
  // body does not turn: ω̇ = 0.
  const Slider sl;
  const ExactMultipliers x = exact_multipliers(sl.system, sl.start);
  const Vec3 weight = sl.m * Vec3(0, 0, -kG);
  const Vec3 across = weight - weight.dot(sl.e) * sl.e;
  EXPECT_LT((x.joint_force_space[0] + across).norm(), 1e-13 * weight.norm());
  EXPECT_LT(x.omega_dot_body[0].norm(), 1e-12);
}

// ---- A bead on a rotating rod: rod hinged at its end about space z, a slider on it joined by a spring to
// a point of the rod. Coordinates θ (rod angle) and s (bead's distance from the pivot):
//   (I + J + m s²) θ̇ = const,   m s̈ = m s θ̇² + k (D − s − ℓ₀). ----

struct Bead {
  double M = 2.0, L = 2.0, r = 0.02, m = 0.5, k = 10.0, D = 3.0, rest = 2.5;
  double theta_dot0 = 1.5, s0 = 0.8, s_dot0 = 0.2;
  Mat3 K_bead = Vec3(0.001, 0.002, 0.003).asDiagonal();
  System system;
  State start;

  Bead() {
    system.add_body("rod", M, test::rod_poinsot(M, L, r));
    system.add_body("bead", m, K_bead);
    system.add_hinge("pivot", 0, Vec3(-L / 2, 0, 0), Vec3::UnitZ(), kWorld, Vec3::Zero(), Vec3::UnitZ());
    system.add_prismatic("slide", 1, Vec3::Zero(), Vec3::UnitX(), 0, Vec3(-L / 2, 0, 0), Mat3::Identity());
    system.add_spring({"spring", 1, 0, Vec3::Zero(), Vec3(D - L / 2, 0, 0), k, 0.0, rest});
    system.set_gravity(Vec3(0, 0, -kG));  // along the hinge: carried by the joints, no effect on θ and s
    start.bodies.resize(2);
    start.bodies[0].x_space = Vec3(L / 2, 0, 0);
    start.bodies[0].omega_body = Vec3(0, 0, theta_dot0);
    start.bodies[0].v_space = Vec3(0, theta_dot0 * L / 2, 0);
    start.bodies[1].x_space = Vec3(s0, 0, 0);
    start.bodies[1].omega_body = Vec3(0, 0, theta_dot0);
    start.bodies[1].v_space = Vec3(s_dot0, theta_dot0 * s0, 0);
    check_consistent(system, start);
  }
  /// (θ, s) at T by classical RK4 on the Lagrange equations with step h.
  Eigen::Vector4d lagrange(double T, double h) const {
    const double I = M * L * L / 12 + M * r * r / 4 + M * L * L / 4 + K_bead(0, 0) + K_bead(1, 1);
    const double m_ = m, k_ = k, D_ = D, rest_ = rest;
    auto f = [&](const Eigen::Vector4d& y) {  // y = (θ, θ̇, s, ṡ)
      const double s = y(2), s_dot = y(3), w = y(1);
      return Eigen::Vector4d(w, -2 * m_ * s * s_dot * w / (I + m_ * s * s), s_dot,
                             s * w * w + k_ / m_ * (D_ - s - rest_));
    };
    Eigen::Vector4d y(0, theta_dot0, s0, s_dot0);
    const long n = std::lround(T / h);
    for (long i = 0; i < n; ++i) {
      const Eigen::Vector4d k1 = f(y), k2 = f(y + h / 2 * k1), k3 = f(y + h / 2 * k2), k4 = f(y + h * k3);
      y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return y;
  }
};

TEST(PrismaticJoint, BeadOnRotatingRodMatchesLagrangesEquations) {
  const Bead bead;
  const double T = 2.0;
  // RK4 error ~(ωh)⁴: below 1e-13 (1e-12 with the sanitizers' 5 times larger step)
  const Eigen::Vector4d y = bead.lagrange(T, 1e-4 * test::slowdown());
  const Vec3 e(std::cos(y(0)), std::sin(y(0)), 0.0);
  const auto error = [&](const State& s) {
    return std::max((s.bodies[1].x_space - y(2) * e).norm(),
                    (s.bodies[0].R_space_body.col(0) - e).norm() * bead.L / 2);
  };
  const State r1 = run(Rattle(bead.system, 4e-3), bead.start, T);
  const State r2 = run(Rattle(bead.system, 2e-3), bead.start, T);
  EXPECT_NEAR(error(r1) / error(r2), 4.0, 0.3) << error(r1) << " " << error(r2);
  EXPECT_LT(error(r2), 1e-4);
  record_errors("rattle", error(r1), error(r2));
  const State k1 = run(ProjectedRk4(bead.system, 4e-3), bead.start, T);
  const State k2 = run(ProjectedRk4(bead.system, 2e-3), bead.start, T);
  EXPECT_NEAR(error(k1) / error(k2), 16.0, 2.0) << error(k1) << " " << error(k2);
  record_errors("rk4", error(k1), error(k2));
  for (const State* s : {&r2, &k2}) {
    const ConstraintViolation v = constraint_violation(bead.system, *s);
    EXPECT_LT(v.joint_gap, 1e-12);
    EXPECT_LT(v.joint_angle, 1e-12);
    EXPECT_LT(v.orthogonality, 1e-13);
  }
  // The bead's rotation stays locked to the rod's.
  EXPECT_LT(so3::angle_between(r2.bodies[0].R_space_body, r2.bodies[1].R_space_body), 1e-12);
  // Energy: RATTLE's error is O(h²) and bounded (E ≈ 5 J).
  const double E0 = total_energy(bead.system, bead.start);
  EXPECT_LT(std::abs(total_energy(bead.system, r2) - E0), 1e-5 * std::abs(E0));
  // The angular momentum about the hinge axis is conserved (no torque about z): to round-off by RATTLE.
  EXPECT_NEAR(angular_momentum(bead.system, r2).z(), angular_momentum(bead.system, bead.start).z(), 1e-11);
}

// ---- A link hung from a fixed point by a universal joint: the outer pin along space x, the inner one along
// the body's y. R = Rx(α) Ry(β), ω_body = E(β) (α̇, β̇) with E = [(cos β, 0, sin β), (0, 1, 0)] by columns;
// T = ½ q̇ᵀ Eᵀ J_p E q̇ (J_p about the pivot), V = m g (R c)_z. ----

/// A link hung from the world by a universal joint: R = Rx(α) Ry(β), the first hinge about the world's x
/// axis through the origin, the second about the link's y axis, through a point at the offset h from the
/// first axis along their common normal (h = 0: a Cardan joint). Its centre of mass is at
/// x = Rx(α) w(β), w = −h z + Ry(β) c.
struct CardanLink {
  double m = 1.2;
  Mat3 J = (Mat3() << 0.05, 0.004, 0.0, 0.004, 0.07, 0.002, 0.0, 0.002, 0.03).finished();
  Vec3 c = Vec3(0.05, 0.02, -0.6);  // centre of mass from the second hinge's point, body frame, m
  double h = 0.0;                   // axis offset, m
  Eigen::Vector2d q0{0.4, -0.3}, q_dot0{1.0, 0.5};
  System system;
  State start;

  static Mat3 attitude(double alpha, double beta) {
    return rot(Vec3::UnitX(), alpha) * rot(Vec3::UnitY(), beta);
  }
  static Eigen::Matrix<double, 3, 2> E(double beta) {
    Eigen::Matrix<double, 3, 2> e;
    e << std::cos(beta), 0, 0, 1, std::sin(beta), 0;
    return e;
  }
  /// ∂x/∂(α, β) = Rx(α) A(β), A = [x × w, y × Ry c]; and ∂A/∂β.
  Eigen::Matrix<double, 3, 2> A(double beta) const {
    const Vec3 Ryc = rot(Vec3::UnitY(), beta) * c;
    Eigen::Matrix<double, 3, 2> a;
    a << Vec3::UnitX().cross(-h * Vec3::UnitZ() + Ryc), Vec3::UnitY().cross(Ryc);
    return a;
  }
  Eigen::Matrix<double, 3, 2> A_beta(double beta) const {
    const Vec3 d = Vec3::UnitY().cross(rot(Vec3::UnitY(), beta) * c);
    Eigen::Matrix<double, 3, 2> a;
    a << Vec3::UnitX().cross(d), Vec3::UnitY().cross(d);
    return a;
  }
  Vec3 position(double alpha, double beta) const {
    return rot(Vec3::UnitX(), alpha) * (-h * Vec3::UnitZ() + rot(Vec3::UnitY(), beta) * c);
  }
  explicit CardanLink(double axis_offset = 0.0) : h(axis_offset) {
    system.add_body_from_inertia("link", m, J);
    system.add_universal("cardan", 0, -c, Vec3::UnitY(), kWorld, Vec3::Zero(), Vec3::UnitX(), h);
    system.set_gravity(Vec3(0, 0, -kG));
    start.bodies.resize(1);
    BodyState& b = start.bodies[0];
    b.R_space_body = attitude(q0(0), q0(1));
    b.x_space = position(q0(0), q0(1));
    b.omega_body = E(q0(1)) * q_dot0;
    b.v_space = rot(Vec3::UnitX(), q0(0)) * A(q0(1)) * q_dot0;
    check_consistent(system, start);
  }
  /// (α, β, α̇, β̇) at T by classical RK4 on M(β) q̈ + Ṁ q̇ − ½ ∂(q̇ᵀMq̇)/∂q + ∇V = 0 with step h, where
  /// M = m AᵀA + EᵀJE.
  Eigen::Vector4d lagrange(double T, double step) const {
    auto f = [&](const Eigen::Vector4d& y) {
      const double beta = y(1);
      const Eigen::Vector2d qd = y.tail<2>();
      Eigen::Matrix<double, 3, 2> E_beta;
      E_beta << -std::sin(beta), 0, 0, 0, std::cos(beta), 0;
      const Eigen::Matrix<double, 3, 2> e = E(beta), a = A(beta), a_beta = A_beta(beta);
      const Eigen::Matrix2d Mq = m * a.transpose() * a + e.transpose() * J * e;
      const Eigen::Matrix2d M_beta = m * (a_beta.transpose() * a + a.transpose() * a_beta) +
                                     E_beta.transpose() * J * e + e.transpose() * J * E_beta;
      const Mat3 Rx = rot(Vec3::UnitX(), y(0));
      const Eigen::Vector2d grad_V(m * kG * (Rx * a.col(0)).z(), m * kG * (Rx * a.col(1)).z());
      const Eigen::Vector2d rhs =
          -M_beta * qd * qd(1) + Eigen::Vector2d(0, 0.5 * qd.dot(M_beta * qd)) - grad_V;
      Eigen::Vector4d d;
      d << qd, Mq.inverse() * rhs;
      return d;
    };
    Eigen::Vector4d y;
    y << q0, q_dot0;
    const long n = std::lround(T / step);
    for (long i = 0; i < n; ++i) {
      const Eigen::Vector4d k1 = f(y), k2 = f(y + step / 2 * k1), k3 = f(y + step / 2 * k2),
                            k4 = f(y + step * k3);
      y += step / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return y;
  }
};

/// RATTLE (order 2) and the projected RK4 (order 4) on the link against its Lagrange equations.
void expect_link_matches_lagranges_equations(const CardanLink& link) {
  const double T = 2.0;
  const Eigen::Vector4d y = link.lagrange(T, 1e-4 * test::slowdown());
  const Mat3 R_exact = CardanLink::attitude(y(0), y(1));
  const Vec3 x_exact = link.position(y(0), y(1));
  const Vec3 omega_exact = CardanLink::E(y(1)) * y.tail<2>();
  const auto error = [&](const State& s) {
    return std::max(so3::angle_between(s.bodies[0].R_space_body, R_exact),
                    (s.bodies[0].x_space - x_exact).norm() / link.c.norm());
  };
  const State r1 = run(Rattle(link.system, 4e-3), link.start, T);
  const State r2 = run(Rattle(link.system, 2e-3), link.start, T);
  EXPECT_NEAR(error(r1) / error(r2), 4.0, 0.3) << error(r1) << " " << error(r2);
  EXPECT_LT(error(r2), 1e-4);
  record_errors("rattle", error(r1), error(r2));
  const State k1 = run(ProjectedRk4(link.system, 4e-3), link.start, T);
  const State k2 = run(ProjectedRk4(link.system, 2e-3), link.start, T);
  EXPECT_NEAR(error(k1) / error(k2), 16.0, 2.0) << error(k1) << " " << error(k2);
  record_errors("rk4", error(k1), error(k2));
  EXPECT_LT((k2.bodies[0].omega_body - omega_exact).norm(), 1e-7);
  for (const State* s : {&r2, &k2}) {
    const ConstraintViolation v = constraint_violation(link.system, *s);
    EXPECT_LT(v.joint_gap, 1e-12);
    EXPECT_LT(v.joint_angle, 1e-12);
    EXPECT_LT(v.orthogonality, 1e-13);
  }
  const double E0 = total_energy(link.system, link.start);
  EXPECT_LT(std::abs(total_energy(link.system, r2) - E0), 1e-5 * std::abs(E0));
}

TEST(UniversalJoint, CardanLinkMatchesLagrangesEquations) {
  expect_link_matches_lagranges_equations(CardanLink());
}

TEST(UniversalJoint, LinkOnHingesAboutDifferentPointsMatchesLagrangesEquations) {
  // The second hinge 0.15 m from the first axis (a quarter of the link's length): two hinges in series, as
  // an ankle of MuJoCo's humanoid.
  expect_link_matches_lagranges_equations(CardanLink(0.15));
}

}  // namespace
}  // namespace poinsot::multibody
