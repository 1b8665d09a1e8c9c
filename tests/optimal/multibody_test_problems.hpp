#pragma once
// Multibody optimal-control problems of the optimal/ tests: the planar two-link arm, one rod on a hinge, the
// spacecraft with a reaction wheel, the falling cat.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::testing {

/// `p` solved in the coordinates `c` with the default options.
inline MultibodyOptimum solve_in(const MultibodyProblem& p, MultibodyCoordinates c) {
  MultibodyOptions o;
  o.coordinates = c;
  return solve_multibody(p, o);
}

/// A solid cylinder of mass m, length ℓ and radius r along body x: J about its centre of mass (kg·m²).
inline Mat3 rod_inertia(double m, double length, double radius) {
  const double axial = 0.5 * m * radius * radius;
  const double transverse = m * (3.0 * radius * radius + length * length) / 12.0;
  return Vec3(axial, transverse, transverse).asDiagonal();
}

/// The arm's state at shoulder angle θ1, elbow angle θ2 (rad, about space z) and rates (rad/s): link 1 from
/// the origin along Rz(θ1) x, link 2 from its tip along Rz(θ1 + θ2) x, links of length 1 m.
inline multibody::State two_link_state(double th1, double th2, double w1 = 0.0, double w2 = 0.0) {
  multibody::State s;
  s.bodies.resize(2);
  const Mat3 R1 = Eigen::AngleAxisd(th1, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 R2 = Eigen::AngleAxisd(th1 + th2, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 z = Vec3::UnitZ();
  s.bodies[0].R_space_body = R1;
  s.bodies[0].x_space = R1 * Vec3(0.5, 0.0, 0.0);
  s.bodies[0].omega_body = w1 * z;
  s.bodies[0].v_space = (w1 * z).cross(s.bodies[0].x_space);
  s.bodies[1].R_space_body = R2;
  s.bodies[1].x_space = R1 * Vec3(1.0, 0.0, 0.0) + R2 * Vec3(0.5, 0.0, 0.0);
  s.bodies[1].omega_body = (w1 + w2) * z;
  s.bodies[1].v_space =
      (w1 * z).cross(R1 * Vec3(1.0, 0.0, 0.0)) + ((w1 + w2) * z).cross(R2 * Vec3(0.5, 0.0, 0.0));
  return s;
}

/// The two-link arm (two rods of 1 kg, 1 m, radius 5 cm on hinges about z, gravity −9.81 m/s² along y), both
/// hinges driven with |u| ≤ 50 N·m, rest hanging straight down (θ1 = −π/2, θ2 = 0) to rest at
/// (−π/2 + Δ1, Δ2) in T at minimum ∫(u1² + u2²)dt.
inline MultibodyProblem two_link_arm(double d1, double d2, double T, int intervals) {
  MultibodyProblem p;
  auto& sys = p.system;
  const int l1 = sys.add_body_from_inertia("upper", 1.0, rod_inertia(1.0, 1.0, 0.05));
  const int l2 = sys.add_body_from_inertia("fore", 1.0, rod_inertia(1.0, 1.0, 0.05));
  const int shoulder = sys.add_hinge("shoulder", l1, Vec3(-0.5, 0, 0), Vec3::UnitZ(), multibody::kWorld,
                                     Vec3::Zero(), Vec3::UnitZ());
  const int elbow =
      sys.add_hinge("elbow", l2, Vec3(-0.5, 0, 0), Vec3::UnitZ(), l1, Vec3(0.5, 0, 0), Vec3::UnitZ());
  sys.set_gravity(Vec3(0.0, -9.81, 0.0));
  const double down = -0.5 * std::numbers::pi;
  p.initial_state = two_link_state(down, 0.0);
  p.final_state = two_link_state(down + d1, d2);
  p.final_time = T;
  p.intervals = intervals;
  p.actuators = {{ActuatorKind::hinge_torque, shoulder, 50.0}, {ActuatorKind::hinge_torque, elbow, 50.0}};
  return p;
}

/// One rod of the arm alone on the shoulder hinge, gravity off: rest at 0 to rest at Θ about z in T. The
/// minimum of ∫u²dt for I θ̈ = u (I = J_zz + m (ℓ/2)² about the hinge) is u = 6IΘ/T² (1 − 2t/T),
/// θ = Θ (3s² − 2s³) with s = t/T, and the cost 12 I² Θ² / T³.
inline MultibodyProblem single_hinge(double theta, double T, int intervals) {
  MultibodyProblem p;
  const int rod = p.system.add_body_from_inertia("rod", 1.0, rod_inertia(1.0, 1.0, 0.05));
  const int hinge = p.system.add_hinge("hinge", rod, Vec3(-0.5, 0, 0), Vec3::UnitZ(), multibody::kWorld,
                                       Vec3::Zero(), Vec3::UnitZ());
  p.initial_state = two_link_state(0.0, 0.0);
  p.initial_state.bodies.resize(1);
  p.final_state = two_link_state(theta, 0.0);
  p.final_state.bodies.resize(1);
  p.final_time = T;
  p.intervals = intervals;
  p.actuators = {{ActuatorKind::hinge_torque, hinge, 50.0}};
  return p;
}
inline double single_hinge_inertia() {
  return rod_inertia(1.0, 1.0, 0.05)(2, 2) + 0.25;
}

/// The spacecraft with a reaction wheel: a bus (10 kg, J = diag(3, 4, 2) kg·m²) and a wheel (5 kg, J =
/// diag(0.5, 0.5, 0.9) kg·m², a flywheel of radius 0.6 m) on a hinge about body z through both centres of
/// mass, free floating, no gravity; the wheel motor |u| ≤ torque_max. Rest to rest: the bus turned by Θ about
/// z in T, the wheel's angle at T free (free_final_hinges). Total angular momentum zero throughout: the bus
/// alone carries the slew, I_bus,zz θ̈ = −u (the wheel's axial inertia turns the other way), so the effective
/// single body has the inertia J_bus + diag(0.5, 0.5, 0): the locked inertia without the wheel's axial part.
inline MultibodyProblem reaction_wheel(double theta, double T, double torque_max, int intervals) {
  MultibodyProblem p;
  auto& sys = p.system;
  const int bus = sys.add_body_from_inertia("bus", 10.0, Vec3(3.0, 4.0, 2.0).asDiagonal());
  const int wheel = sys.add_body_from_inertia("wheel", 5.0, Vec3(0.5, 0.5, 0.9).asDiagonal());
  const int hinge =
      sys.add_hinge("wheel axle", wheel, Vec3::Zero(), Vec3::UnitZ(), bus, Vec3::Zero(), Vec3::UnitZ());
  p.initial_state.bodies.resize(2);
  p.final_state.bodies.resize(2);
  for (auto& b : p.final_state.bodies)
    b.R_space_body = Eigen::AngleAxisd(theta, Vec3::UnitZ()).toRotationMatrix();
  p.final_time = T;
  p.intervals = intervals;
  p.actuators = {{ActuatorKind::hinge_torque, hinge, torque_max}};
  p.free_final_hinges = {hinge};
  return p;
}
inline Mat3 reaction_wheel_effective_inertia() {
  return Vec3(3.5, 4.5, 2.0).asDiagonal();
}

/// The bus and the wheel of reaction_wheel on a tilted hinge off both centres of mass: the wheel's axis
/// (0.6, 0, 0.8) passes through the bus point (0.4, 0.2, 0.1) and 0.15 m from the wheel's centre, so the
/// centres move as the bodies turn (the translation's elimination matters). At rest with R = I, free
/// floating, no gravity; one hinge motor, |u| ≤ 1 N·m; T = 4 s on 10 intervals.
inline MultibodyProblem offset_reaction_wheel() {
  MultibodyProblem p;
  auto& sys = p.system;
  const int bus = sys.add_body_from_inertia("bus", 10.0, Vec3(3.0, 4.0, 2.0).asDiagonal());
  const int wheel = sys.add_body_from_inertia("wheel", 5.0, Vec3(0.5, 0.5, 0.9).asDiagonal());
  const Vec3 axis(0.6, 0.0, 0.8);
  const Vec3 A = 0.15 * axis, B(0.4, 0.2, 0.1);
  const int hinge = sys.add_hinge("axle", wheel, A, axis, bus, B, axis);
  p.initial_state.bodies.resize(2);
  p.initial_state.bodies[1].x_space = B - A;
  p.final_state = p.initial_state;
  p.final_time = 4.0;
  p.intervals = 10;
  p.actuators = {{ActuatorKind::hinge_torque, hinge, 1.0}};
  return p;
}

/// The falling cat (Kane & Scher 1969): two identical axisymmetric halves (cylinders of 1 kg, 1 m, radius
/// 0.2 m along body x) joined at their +x ends by a ball joint with three motors (space-frame torques, |τ_i|
/// ≤ 100 N·m), free floating, no gravity, at rest with zero angular momentum. Bent into a V in the x–z plane,
/// each half tilted by α from the spine (space x), the joint below and the centre of mass at the origin; the
/// target is the same V turned over by 180° about the spine, at rest, in T.
inline multibody::State cat_state(double alpha, const Mat3& turn) {
  multibody::State s;
  s.bodies.resize(2);
  const Mat3 Ra = Eigen::AngleAxisd(alpha, Vec3::UnitY()).toRotationMatrix();
  const Mat3 Rb = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitZ()).toRotationMatrix() * Ra;
  const Vec3 joint(0.0, 0.0, -0.5 * std::sin(alpha));
  s.bodies[0].R_space_body = turn * Ra;
  s.bodies[0].x_space = turn * (joint - Ra * Vec3(0.5, 0.0, 0.0));
  s.bodies[1].R_space_body = turn * Rb;
  s.bodies[1].x_space = turn * (joint - Rb * Vec3(0.5, 0.0, 0.0));
  return s;
}
inline MultibodyProblem falling_cat(double alpha, double turn, double T, int intervals) {
  MultibodyProblem p;
  const int front = p.system.add_body_from_inertia("front", 1.0, rod_inertia(1.0, 1.0, 0.2));
  const int back = p.system.add_body_from_inertia("back", 1.0, rod_inertia(1.0, 1.0, 0.2));
  const int waist = p.system.add_ball("waist", front, Vec3(0.5, 0, 0), back, Vec3(0.5, 0, 0));
  p.initial_state = cat_state(alpha, Mat3::Identity());
  p.final_state = cat_state(alpha, Eigen::AngleAxisd(turn, Vec3::UnitX()).toRotationMatrix());
  p.final_time = T;
  p.intervals = intervals;
  p.actuators = {{ActuatorKind::ball_torque, waist, 100.0}};
  return p;
}
/// The bound on the stabilising variables' step for the falling cat (MultibodyOptions::stabilisation_step):
/// unbounded, the half turn from a guess that jumps ends on a spurious jump of cost ~1e-26.
inline constexpr double kCatStabilisationStep = 0.05;
/// Kane & Scher's no-twist condition on the cat's waist: the relative rotation R_aᵀR_b is C M with C the
/// straight cat's (a half-turn about body z: the halves face each other) and M a bend about an axis
/// perpendicular to the spine (body x).
inline NoTwist falling_cat_no_twist() {
  return {0, Vec3::UnitX(), Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitZ()).toRotationMatrix()};
}

/// An initial guess for falling_cat(α, turn, T, ·): the bent cat turned rigidly about the spine at the
/// constant rate turn/T (not a motion at zero angular momentum, but made of rotations that keep the joint),
/// on `intervals` equal intervals, with zero controls, as a MultibodyOptimum for
/// MultibodyOptions::warm_start.
inline MultibodyOptimum falling_cat_rigid_turn(double alpha, double turn, double T, int intervals) {
  MultibodyOptimum guess;
  const Vec3 omega_space(turn / T, 0.0, 0.0);
  for (int p = 0; p <= 2 * intervals; ++p) {
    const double t = T * p / (2.0 * intervals);
    multibody::State s = cat_state(alpha, Eigen::AngleAxisd(turn * t / T, Vec3::UnitX()).toRotationMatrix());
    s.time = t;
    for (multibody::BodyState& b : s.bodies) {
      b.omega_body = b.R_space_body.transpose() * omega_space;
      b.v_space = omega_space.cross(b.x_space);
    }
    guess.time.push_back(t);
    guess.states.push_back(s);
    guess.controls.push_back(Eigen::VectorXd::Zero(3));
  }
  return guess;
}

}  // namespace poinsot::optimal::testing
