// Spring-dampers on the coordinate of a hinge or a prismatic joint (model.hpp JointSpring, loads.cpp) against
// the damped oscillator's closed form, the integrators' convergence orders, the conservation of angular
// momentum under internal torques and of energy without damping.
#include <array>
#include <cmath>
#include <numbers>
#include <tuple>
#include <utility>
#include <vector>

#include "damped_oscillator.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/multibody/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::multibody {
namespace {

using ::poinsot::test::damped_oscillator;
using ::poinsot::test::expect_has;
using ::poinsot::test::message_of;

/// The largest |E − E₀| over `steps` RATTLE steps of `h` from `s` (advanced to the last), E₀ its energy at
/// the start.
double worst_energy_error(const System& system, State& s, double h, int steps) {
  const double e0 = total_energy(system, s);
  Rattle rattle(system, h);
  double worst = 0.0;
  for (int n = 0; n < steps; ++n) {
    rattle.step(s);
    worst = std::max(worst, std::abs(total_energy(system, s) - e0));
  }
  return worst;
}

Mat3 rot_z(double a) {
  return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix();
}

// Two bodies with their centres of mass at the hinge, about their common principal axis z, in zero gravity.
// The spring's zero is the relative rotation R_z(−0.05) and its rest position 0.1 rad, so it rests at a
// relative angle of 0.05 rad. The deflection δ = θ_a − θ_b − 0.05 obeys I δ̈ = −k δ − c δ̇ with 1/I = 1/I_a +
// 1/I_b for any δ in (−π, π) (the torque is linear in the angle), and the total angular momentum stays zero.
constexpr double kIa = 0.5, kIb = 0.25, kRest = 0.05;

struct HingedPair {
  System system;
  State initial;
  double omega = 0.0, zeta = 0.0;  ///< of the relative angle's oscillator
};

HingedPair hinged_pair(double k, double c, double delta0) {
  HingedPair p;
  p.system.add_body_from_inertia("a", 2.0, Vec3(0.3, 0.4, kIa).asDiagonal());
  p.system.add_body_from_inertia("b", 1.0, Vec3(0.1, 0.2, kIb).asDiagonal());
  JointSpring s;
  s.joint = p.system.add_hinge("h", 0, Vec3::Zero(), Vec3::UnitZ(), 1, Vec3::Zero(), Vec3::UnitZ());
  s.stiffness = k;
  s.damping = c;
  s.rest_position = 0.1;
  s.R_b_a_zero = rot_z(-0.05);
  p.system.add_joint_spring(s);
  p.initial.bodies.resize(2);
  p.initial.bodies[0].R_space_body = rot_z(kRest + delta0);
  const double I = 1.0 / (1.0 / kIa + 1.0 / kIb);
  p.omega = std::sqrt(k / I);
  p.zeta = c / (2.0 * std::sqrt(k * I));
  return p;
}

double deflection(const State& s) {
  const Mat3 S = s.bodies[1].R_space_body.transpose() * s.bodies[0].R_space_body;
  return std::atan2(S(1, 0), S(0, 0)) - kRest;
}

/// |δ(T) − closed form| after T = 3 s at step dt with the integrator `I`.
template <class Integrator>
double hinge_error(const HingedPair& p, double dt, double delta0, double* momentum = nullptr) {
  Integrator integrator(p.system, dt);
  State s = p.initial;
  const int steps = static_cast<int>(std::lround(3.0 / dt));
  for (int n = 0; n < steps; ++n)
    integrator.step(s);
  if (momentum != nullptr) *momentum = multibody::angular_momentum(p.system, s).norm();
  return std::abs(deflection(s) - damped_oscillator(delta0, p.omega, p.zeta, s.time));
}

TEST(JointSprings, HingedPairIsTheDampedOscillatorAtFourthOrderWithRk4) {
  // δ0 = 2.5 rad: far from small angles, where a spring linear in the angle keeps the closed form exact.
  const double delta0 = 2.5;
  const HingedPair p = hinged_pair(3.0, 0.2, delta0);
  const double e1 = hinge_error<ProjectedRk4>(p, 0.02, delta0);
  const double e2 = hinge_error<ProjectedRk4>(p, 0.01, delta0);
  // ω h ≈ 0.085 and 0.042: RK4's global error ~ (ωh)⁴ ωT/100 times the decayed amplitude (e^(−ζωT) ≈ 0.17),
  // about 1e-6 at the larger step (measured 1.16e-6); halving it divides the error by 2⁴ = 16 (the 12 to 20
  // band leaves room for the next order's term: measured 14.0).
  EXPECT_LT(e1, 2e-6);
  EXPECT_GT(e1 / e2, 12.0);
  EXPECT_LT(e1 / e2, 20.0);
}

TEST(JointSprings, HingedPairIsTheDampedOscillatorAtSecondOrderWithRattleAndKeepsZeroMomentum) {
  const double delta0 = 1.0;
  const HingedPair p = hinged_pair(3.0, 0.2, delta0);
  double L = 1.0;
  const double e1 = hinge_error<Rattle>(p, 0.01, delta0);
  const double e2 = hinge_error<Rattle>(p, 0.005, delta0, &L);
  // RATTLE's phase error (ωh)²ωT/24 ≈ 1e-3 rad at h = 0.01, times the decayed amplitude (≈ 0.17):
  // about 1.6e-4 (measured 1.15e-4); halving the step divides it by 4 (the dampers see extrapolated
  // velocities, which keeps the second order).
  EXPECT_LT(e1, 2e-4);
  EXPECT_GT(e1 / e2, 3.5);
  EXPECT_LT(e1 / e2, 4.5);
  // The spring's torques on a and b are equal and opposite: L stays 0 to round-off (|ω| ~ 10 rad/s, J ~ 0.5).
  EXPECT_LT(L, 1e-12);
}

TEST(JointSprings, WithoutDampingRattleKeepsTheEnergyOfTheSpringBounded) {
  const HingedPair p = hinged_pair(3.0, 0.0, 2.0);
  State s = p.initial;
  const double e0 = total_energy(p.system, s);
  // All the energy starts in the spring: ½ k δ0².
  EXPECT_NEAR(e0, 0.5 * 3.0 * 4.0, 1e-14);
  const double h = 0.01;
  const double worst = worst_energy_error(p.system, s, h, 20000);  // 200 s, about 130 periods
  // A symplectic method's energy error stays of order (ωh)² without drift: (ωh)² ≈ 1.8e-3 of e0.
  EXPECT_LT(worst / e0, (p.omega * h) * (p.omega * h));
}

TEST(JointSprings, SliderIsTheDampedOscillatorAlongItsAxis) {
  // A 2 kg body on a prismatic joint along space x, in zero gravity. The coordinate is 0.1 m (the offset)
  // when its point is at the world's point, the spring rests at −0.2 m: the deflection starts at 0.3 m.
  System system;
  system.add_body_from_inertia("cart", 2.0, Vec3(0.1, 0.1, 0.1).asDiagonal());
  JointSpring s;
  s.joint =
      system.add_prismatic("track", 0, Vec3::Zero(), Vec3::UnitX(), kWorld, Vec3(1, 0, 0), Mat3::Identity());
  s.stiffness = 5.0;
  s.damping = 0.4;
  s.rest_position = -0.2;
  s.offset = 0.1;
  system.add_joint_spring(s);
  State st;
  st.bodies.resize(1);
  st.bodies[0].x_space = Vec3(1, 0, 0);
  EXPECT_NEAR(total_energy(system, st), 0.5 * 5.0 * 0.09, 1e-15);
  ProjectedRk4 rk4(system, 1e-3);
  for (int n = 0; n < 2000; ++n)
    rk4.step(st);
  const double omega = std::sqrt(5.0 / 2.0), zeta = 0.4 / (2.0 * std::sqrt(5.0 * 2.0));
  // q = x − 1 + 0.1; RK4 at ωh = 1.6e-3 over 2 s: error ~ (ωh)⁴ ωT/100 ~ 2e-13 of the amplitude (measured
  // 1e-14, round-off).
  EXPECT_NEAR(st.bodies[0].x_space.x() - 1.0 + 0.1, -0.2 + damped_oscillator(0.3, omega, zeta, st.time),
              1e-12);
  EXPECT_LT(std::abs(st.bodies[0].x_space.y()) + std::abs(st.bodies[0].x_space.z()), 1e-14);
}

TEST(JointSprings, RefusesOtherJointsNegativeValuesAndAZeroOffTheAxis) {
  System s;
  s.add_body_from_inertia("a", 1.0, Mat3::Identity());
  const int weld = s.add_weld("w", 0, Vec3::Zero(), kWorld, Vec3::Zero(), Mat3::Identity());
  const int hinge = s.add_hinge("h", 0, Vec3::Zero(), Vec3::UnitZ(), kWorld, Vec3::Zero(), Vec3::UnitZ());
  JointSpring bad;
  bad.joint = weld;
  bad.stiffness = 1.0;
  expect_has(message_of([&] { s.add_joint_spring(bad); }),
             {"joint 'w': spring", "weld", "expected a hinge, a prismatic, a universal or a ball joint"});
  bad.joint = hinge;
  bad.coordinate = JointSpring::Coordinate::b;
  expect_has(message_of([&] { s.add_joint_spring(bad); }),
             {"joint 'h': spring", "coordinate \"b\" does not belong to a hinge joint"});
  bad.coordinate = JointSpring::Coordinate::a;
  bad.joint = 7;
  expect_has(message_of([&] { s.add_joint_spring(bad); }), {"joint 7 does not exist"});
  bad.joint = hinge;
  bad.damping = -1.0;
  expect_has(message_of([&] { s.add_joint_spring(bad); }), {"damping", "-1", "N·m·s/rad"});
  bad.damping = 0.0;
  bad.R_b_a_zero = Eigen::AngleAxisd(0.3, Vec3::UnitX()).toRotationMatrix();  // tilts the axis
  expect_has(message_of([&] { s.add_joint_spring(bad); }),
             {"zero rotation", "does not carry the axis of body a onto the axis of body b"});
  EXPECT_TRUE(s.joint_springs().empty());
  // A universal joint's zero must carry its axis a perpendicular to its axis b.
  const int cardan =
      s.add_universal("u", 0, Vec3::Zero(), Vec3::UnitX(), kWorld, Vec3::Zero(), Vec3::UnitY());
  bad.joint = cardan;
  bad.R_b_a_zero = rot_z(0.3);
  expect_has(message_of([&] { s.add_joint_spring(bad); }),
             {"joint 'u': spring", "does not carry the axis of body a perpendicular to the axis of body b"});
  bad.coordinate = JointSpring::Coordinate::first;
  expect_has(message_of([&] { s.add_joint_spring(bad); }),
             {"coordinate \"first\" does not belong to a universal joint; expected \"a\" or \"b\""});
  // A ball joint's three hinges: the second axis perpendicular to the others, the third not along the first.
  const int ball = s.add_ball("b", 0, Vec3::Zero(), kWorld, Vec3::Zero());
  bad.joint = ball;
  bad.R_b_a_zero = Mat3::Identity();
  bad.hinge_axes = {Vec3::UnitX(), Vec3::UnitZ(), Vec3::UnitY()};
  bad.coordinate = JointSpring::Coordinate::a;
  expect_has(
      message_of([&] { s.add_joint_spring(bad); }),
      {"coordinate \"a\" does not belong to a ball joint; expected \"first\", \"second\" or \"third\""});
  bad.coordinate = JointSpring::Coordinate::second;
  bad.hinge_axes = {Vec3::UnitX(), Vec3::UnitZ(), Vec3::UnitX()};
  expect_has(
      message_of([&] { s.add_joint_spring(bad); }),
      {"joint 'b': spring: hinge axes", "expected the second perpendicular to the first and the third"});
  bad.hinge_axes = {Vec3::UnitX(), Vec3(1, 0, 1), Vec3::UnitY()};
  expect_has(message_of([&] { s.add_joint_spring(bad); }), {"hinge axes", "not three hinges"});
  bad.hinge_axes = {Vec3::UnitX(), Vec3::Zero(), Vec3::UnitY()};
  expect_has(message_of([&] { s.add_joint_spring(bad); }), {"hinge axis 2", "is zero"});
  EXPECT_EQ(s.joint_springs().size(), 0u);
  // Axes need not be unit: they are normalised.
  bad.hinge_axes = {2.0 * Vec3::UnitX(), Vec3::UnitZ(), Vec3::UnitY()};
  s.add_joint_spring(bad);
  EXPECT_EQ(s.joint_springs()[0].hinge_axes[0], Vec3::UnitX());
}

// A universal joint between body a and the world, axis e_a = x of a, e_b = y of the world: its relative
// rotations are R = Rot(y, q_b) Rot(x, q_a) (two hinges in series, the world-side one first), read here
// from R's entries: q_a = atan2(−R₁₂, R₁₁), q_b = atan2(−R₂₀, R₀₀).
struct CardanPair {
  System system;
  int joint = 0;
};

CardanPair cardan(const Vec3& inertia, double k_a, double c_a, double rest_a, double k_b, double c_b,
                  double rest_b) {
  CardanPair p;
  p.system.add_body_from_inertia("a", 2.0, inertia.asDiagonal());
  p.joint = p.system.add_universal("u", 0, Vec3::Zero(), Vec3::UnitX(), kWorld, Vec3::Zero(), Vec3::UnitY());
  for (const auto& [coordinate, k, c, rest] : {std::tuple{JointSpring::Coordinate::a, k_a, c_a, rest_a},
                                               std::tuple{JointSpring::Coordinate::b, k_b, c_b, rest_b}}) {
    JointSpring s;
    s.joint = p.joint;
    s.coordinate = coordinate;
    s.stiffness = k;
    s.damping = c;
    s.rest_position = rest;
    p.system.add_joint_spring(s);
  }
  return p;
}

Mat3 cardan_rotation(double q_a, double q_b) {
  return Eigen::AngleAxisd(q_b, Vec3::UnitY()).toRotationMatrix() *
         Eigen::AngleAxisd(q_a, Vec3::UnitX()).toRotationMatrix();
}

TEST(JointSprings, UniversalJointAnglesAreThoseOfTwoHingesInSeries) {
  const CardanPair p = cardan(Vec3(0.3, 0.4, 0.5), 2.0, 0.0, 0.1, 3.0, 0.0, -0.2);
  State s;
  s.bodies.resize(1);
  for (const auto& [q_a, q_b] : {std::pair{0.0, 0.0}, std::pair{0.7, -1.2}, std::pair{-2.9, 2.5},
                                 std::pair{3.0, 0.4}, std::pair{-0.3, -3.1}}) {
    s.bodies[0].R_space_body = cardan_rotation(q_a, q_b);
    const double d_a = std::remainder(q_a - 0.1, 2.0 * std::numbers::pi);
    const double d_b = std::remainder(q_b + 0.2, 2.0 * std::numbers::pi);
    EXPECT_NEAR(potential_energy(p.system, s.bodies), 0.5 * 2.0 * d_a * d_a + 0.5 * 3.0 * d_b * d_b, 1e-13)
        << q_a << ", " << q_b;
  }
  // Dampers only: with ω = q̇_a e_a + q̇_b Rot(x, −q_a) y (body frame), the torque on a is
  // −c_a q̇_a e_a − c_b q̇_b Rot(x, −q_a) y.
  const CardanPair d = cardan(Vec3(0.3, 0.4, 0.5), 0.0, 0.7, 0.0, 0.0, 1.3, 0.0);
  const double q_a = 0.8, rate_a = -0.4, rate_b = 1.1;
  const Vec3 w = Eigen::AngleAxisd(-q_a, Vec3::UnitX()).toRotationMatrix() * Vec3::UnitY();
  s.bodies[0].R_space_body = cardan_rotation(q_a, -0.6);
  s.bodies[0].omega_body = rate_a * Vec3::UnitX() + rate_b * w;
  std::vector<BodyLoads> loads;
  applied_loads(d.system, s.bodies, loads);
  POINSOT_EXPECT_MATRIX_NEAR(loads[0].torque_body, Vec3(-0.7 * rate_a * Vec3::UnitX() - 1.3 * rate_b * w),
                             1e-15);
}

// A body on a universal joint at its centre of mass, its principal axes x, y along the joint's axes: at small
// angles the two angles are the damped oscillators I_x q̈_a = −k_a q_a − c_a q̇_a and I_y q̈_b = −k_b q_b −
// c_b q̇_b. Their coupling (gyroscopic and through Rot(x, q_a) y) is of the order of the amplitude squared: at
// 1e-3 rad, 1e-6 of it, 1e-9 rad (measured 1.7e-10 and 1.2e-10 rad); RK4 at ωh ≈ 3e-3 adds ~1e-13.
TEST(JointSprings, UniversalJointAtSmallAnglesIsTwoDampedOscillators) {
  const Vec3 inertia(0.3, 0.4, 0.5);
  const double k_a = 2.0, c_a = 0.1, k_b = 5.0, c_b = 0.3, a0 = 1e-3, b0 = -0.8e-3;
  const CardanPair p = cardan(inertia, k_a, c_a, 0.0, k_b, c_b, 0.0);
  State s;
  s.bodies.resize(1);
  s.bodies[0].R_space_body = cardan_rotation(a0, b0);
  ProjectedRk4 rk4(p.system, 1e-3);
  for (int n = 0; n < 3000; ++n)
    rk4.step(s);
  const Mat3& R = s.bodies[0].R_space_body;
  const double q_a = std::atan2(-R(1, 2), R(1, 1)), q_b = std::atan2(-R(2, 0), R(0, 0));
  const double expected_a =
      damped_oscillator(a0, std::sqrt(k_a / inertia.x()), c_a / (2.0 * std::sqrt(k_a * inertia.x())), s.time);
  const double expected_b =
      damped_oscillator(b0, std::sqrt(k_b / inertia.y()), c_b / (2.0 * std::sqrt(k_b * inertia.y())), s.time);
  EXPECT_NEAR(q_a, expected_a, 1e-9);
  EXPECT_NEAR(q_b, expected_b, 1e-9);
  EXPECT_GT(std::abs(expected_a), 1e-4);  // the oscillation is still there to compare
}

// Without dampers, at angles of a radian where the two angles are strongly coupled, RATTLE keeps the energy
// to (ωh)² without drift (measured 6.8e-5 of it, against 2.5e-4): the spring's torque is the gradient of its
// potential. A torque about another axis than w for the angle b breaks this at once.
TEST(JointSprings, UniversalJointSpringsAreConservative) {
  const CardanPair p = cardan(Vec3(0.3, 0.4, 0.5), 2.0, 0.0, 0.2, 3.0, 0.0, -0.1);
  State s;
  s.bodies.resize(1);
  s.bodies[0].R_space_body = cardan_rotation(1.1, -0.9);
  // A velocity the joint allows: q̇_a = 0.5 about e_a, q̇_b = −0.4 about Rot(x, −q_a) y.
  s.bodies[0].omega_body =
      0.5 * Vec3::UnitX() - 0.4 * (Eigen::AngleAxisd(-1.1, Vec3::UnitX()).toRotationMatrix() * Vec3::UnitY());
  const double e0 = total_energy(p.system, s);
  const double h = 0.005, omega = std::sqrt(3.0 / 0.3);
  const double worst = worst_energy_error(p.system, s, h, 20000);  // 100 s
  EXPECT_LT(worst / e0, (omega * h) * (omega * h));
}

// A body on a ball joint to the world that stands for three hinges in series, M = C₀ᵀR = Rot(e₁, q₁)
// Rot(e₂, q₂) Rot(e₃, q₃), with C₀ = Rot(z, 0.3) and axes of two kinds: a humanoid's hip (x, z, y: the third
// perpendicular to the first, λ = −π/2) and a third axis at 60° from the first (λ = −π/3).
struct HingeTriple {
  System system;
  Mat3 C0 = rot_z(0.3);
  std::array<Vec3, 3> axes;
};

HingeTriple hinge_triple(const std::array<Vec3, 3>& axes, const Vec3& k, const Vec3& c, const Vec3& rest) {
  HingeTriple t;
  t.axes = axes;
  t.system.add_body_from_inertia("a", 2.0, Vec3(0.3, 0.4, 0.5).asDiagonal());
  const int joint = t.system.add_ball("hip", 0, Vec3(0.1, -0.2, 0.05), kWorld, Vec3::Zero());
  const JointSpring::Coordinate order[3] = {JointSpring::Coordinate::first, JointSpring::Coordinate::second,
                                            JointSpring::Coordinate::third};
  for (int i = 0; i < 3; ++i) {
    JointSpring s;
    s.joint = joint;
    s.coordinate = order[i];
    s.stiffness = k(i);
    s.damping = c(i);
    s.rest_position = rest(i);
    s.R_b_a_zero = t.C0;
    s.hinge_axes = axes;
    t.system.add_joint_spring(s);
  }
  return t;
}

Mat3 hinges_in_series(const HingeTriple& t, const Vec3& q) {
  Mat3 R = t.C0;
  for (int i = 0; i < 3; ++i)
    R = R * Eigen::AngleAxisd(q(i), t.axes[static_cast<std::size_t>(i)]).toRotationMatrix();
  return R;
}

const std::array<std::array<Vec3, 3>, 2> kHingeAxes = {
    std::array<Vec3, 3>{Vec3::UnitX(), Vec3::UnitZ(), Vec3::UnitY()},
    std::array<Vec3, 3>{Vec3::UnitX(), Vec3::UnitZ(), Vec3(0.5, std::sqrt(0.75), 0.0)}};

TEST(JointSprings, BallJointAnglesAreThoseOfThreeHingesInSeries) {
  const Vec3 k(2.0, 3.0, 5.0), rest(0.1, -0.2, 0.3);
  for (const auto& axes : kHingeAxes) {
    const HingeTriple t = hinge_triple(axes, k, Vec3::Zero(), rest);
    State s;
    s.bodies.resize(1);
    // q₂ within both branches: [−π/2, π/2] for the hip, [−π/3, 2π/3] for the other.
    for (const Vec3& q : {Vec3(0, 0, 0), Vec3(0.7, -0.8, 0.4), Vec3(-2.9, 1.1, 2.5), Vec3(3.0, 0.4, -3.1),
                          Vec3(-0.3, -0.9, 1.7)}) {
      s.bodies[0].R_space_body = hinges_in_series(t, q);
      double V = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double d = std::remainder(q(i) - rest(i), 2.0 * std::numbers::pi);
        V += 0.5 * k(i) * d * d;
      }
      EXPECT_NEAR(potential_energy(t.system, s.bodies), V, 1e-12) << q.transpose();
    }
  }
}

// The springs' torque is the gradient of their potential (central differences of V along small rotations of
// the body, error O(δ²) ≈ 1e-10 of V's second derivatives ~ 10), and the dampers' generalized force on hinge
// j is −c_j q̇_j: the torque's power along the motion of hinge j alone (its ω by central differences of the
// rotation, error ~1e-10) is −c_j q̇_j.
TEST(JointSprings, BallJointSpringTorquesAreTheGradientsAndTheDampersActOnEachHinge) {
  const Vec3 q(0.6, -0.5, 1.2), rates(0.8, -1.3, 0.4), c(0.7, 1.1, 0.25);
  for (const auto& axes : kHingeAxes) {
    const HingeTriple springs = hinge_triple(axes, Vec3(2.0, 3.0, 5.0), Vec3::Zero(), Vec3(0.1, -0.2, 0.3));
    State s;
    s.bodies.resize(1);
    s.bodies[0].R_space_body = hinges_in_series(springs, q);
    std::vector<BodyLoads> loads;
    applied_loads(springs.system, s.bodies, loads);
    const double d = 1e-5;
    for (int i = 0; i < 3; ++i) {
      State plus = s, minus = s;
      plus.bodies[0].R_space_body =
          s.bodies[0].R_space_body * Eigen::AngleAxisd(d, Vec3::Unit(i)).toRotationMatrix();
      minus.bodies[0].R_space_body =
          s.bodies[0].R_space_body * Eigen::AngleAxisd(-d, Vec3::Unit(i)).toRotationMatrix();
      const double dV =
          (potential_energy(springs.system, plus.bodies) - potential_energy(springs.system, minus.bodies)) /
          (2 * d);
      EXPECT_NEAR(loads[0].torque_body(i), -dV, 1e-8);
    }
    // The body's angular velocity of each hinge's unit rate (body frame), by central differences.
    const HingeTriple dampers = hinge_triple(axes, Vec3::Zero(), c, Vec3::Zero());
    std::array<Vec3, 3> omega_of;
    for (int j = 0; j < 3; ++j) {
      const Mat3 Rdot = (hinges_in_series(dampers, q + d * Vec3::Unit(j)) -
                         hinges_in_series(dampers, q - d * Vec3::Unit(j))) /
                        (2 * d);
      const Mat3 W = hinges_in_series(dampers, q).transpose() * Rdot;
      omega_of[static_cast<std::size_t>(j)] = Vec3(W(2, 1), W(0, 2), W(1, 0));
    }
    s.bodies[0].R_space_body = hinges_in_series(dampers, q);
    s.bodies[0].omega_body = rates(0) * omega_of[0] + rates(1) * omega_of[1] + rates(2) * omega_of[2];
    applied_loads(dampers.system, s.bodies, loads);
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(loads[0].torque_body.dot(omega_of[static_cast<std::size_t>(j)]), -c(j) * rates(j), 1e-9);
  }
}

// Without dampers, at angles of a radian, RATTLE keeps the energy to (ωh)² without drift (the spring is
// conservative); at the hinges' gimbal lock the loads throw.
TEST(JointSprings, BallJointSpringsAreConservativeAndRefuseTheGimbalLock) {
  const HingeTriple t = hinge_triple(kHingeAxes[0], Vec3(2.0, 3.0, 1.0), Vec3::Zero(), Vec3(0.2, -0.1, 0.3));
  State s;
  s.bodies.resize(1);
  s.bodies[0].R_space_body = hinges_in_series(t, Vec3(1.1, -0.6, 0.8));
  s.bodies[0].x_space = -s.bodies[0].R_space_body * Vec3(0.1, -0.2, 0.05);
  s.bodies[0].omega_body = Vec3(0.5, -0.4, 0.3);
  project_velocities(t.system, s);
  const double e0 = total_energy(t.system, s);
  const double h = 0.005, omega = std::sqrt(3.0 / 0.3);
  const double worst = worst_energy_error(t.system, s, h, 20000);  // 100 s
  EXPECT_LT(worst / e0, (omega * h) * (omega * h));
  s.bodies[0].R_space_body = hinges_in_series(t, Vec3(0.3, std::numbers::pi / 2, -0.2));
  std::vector<BodyLoads> loads;
  expect_has(message_of<ComputationFailed>([&] { applied_loads(t.system, s.bodies, loads); }),
             {"multibody joint 'hip': the spring on its first hinge", "gimbal lock"});
}

}  // namespace
}  // namespace poinsot::multibody
