// Reaction wheels as the actuators of a slew (reaction_wheels.hpp): the gyrostat's momentum bookkeeping, its
// optimal slews against closed forms (the single-axis minimum-energy slew, 12 I² Θ² / T³; the momentum-
// bounded diagonal slew of a spherical bus, accelerate–coast–brake), against the single body of the same
// bus inertia, and against the multibody model of the same spacecraft (bus and wheels on hinges): its optimum
// (one wheel) and the re-simulation of a gyrostat's 3-D optimal wheel torques on it (three wheels).
#include "poinsot/optimal/reaction_wheels.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "multibody_test_problems.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/direct_replay.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal {
namespace {

/// Three wheels on the body axes of a spacecraft whose bus (wheels' axial inertia removed) has the inertia
/// `bus`: the locked inertia is bus + diag(spin).
ReorientationProblem wheel_problem(const Mat3& bus, const Vec3& spin, double torque_max) {
  ReorientationProblem p;
  ReactionWheels w;
  w.spin_inertia = spin;
  p.inertia_body = bus + Mat3(spin.asDiagonal());
  p.torque_max = Vec3::Constant(torque_max);
  p.wheels = w;
  return p;
}

// h = A⁻¹(Rᵀ L − J_b ω) inverts L = R (J_b ω + A h) for random skewed axes, attitudes and states.
TEST(ReactionWheels, MomentumBookkeepingRoundTrips) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    ReactionWheels w;
    for (int k = 0; k < 3; ++k)
      w.axes_body.col(k) = (Vec3::Unit(k) + 0.3 * Vec3(n(rng), n(rng), n(rng))).normalized();
    w.spin_inertia = Vec3(0.1, 0.2, 0.3);
    Mat3 J;
    J << 3.0, 0.2, -0.1, 0.2, 2.5, 0.3, -0.1, 0.3, 2.0;
    const Quat q = Quat(n(rng), n(rng), n(rng), n(rng)).normalized();
    const Vec3 omega(n(rng), n(rng), n(rng)), h(n(rng), n(rng), n(rng));
    const Vec3 L = total_momentum_space(J, w, q, omega, h);
    EXPECT_LT((wheel_momentum(J, w, L, q, omega) - h).norm(), 1e-12 * (1.0 + h.norm()));
    // The wheels' relative spin: h_k = I_k (a_kᵀ ω + Ω_k).
    const Vec3 spin = wheel_speed(w, h, omega);
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(w.spin_inertia[k] * (w.axes_body.col(k).dot(omega) + spin[k]), h[k], 1e-13);
  }
}

// Rest to rest through Θ about z, L = 0: the bus obeys I θ̈ = −u_z (I = J_b,zz), so the minimum-energy wheel
// torque is u_z = −6 I Θ/T² (1 − 2t/T) and the cost 12 I² Θ² / T³ (the x and y wheels idle). The replay
// integrates the full gyrostat (wheel momenta from ∫u, not from L), so it checks the reduced transcription.
TEST(ReactionWheels, SingleAxisMinimumEnergyIsTheClosedForm) {
  const double I = 2.0, theta = 1.0, T = 10.0;
  ReorientationProblem p = wheel_problem(Vec3(3.0, 4.0, I).asDiagonal(), Vec3(0.2, 0.3, 0.9), 10.0);
  p.objective = Objective::minimum_energy;
  p.final_time = T;
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, Vec3::UnitZ()));
  CollocationOptions o;
  o.mesh_tolerance = 1e-9;
  const DirectSolution d = solve_direct(p, o);
  ASSERT_TRUE(d.converged) << d.status;
  // The mesh error 1e-9 bounds the cost's relative error to about that.
  EXPECT_NEAR(d.cost / (12.0 * I * I * theta * theta / (T * T * T)), 1.0, 1e-8);
  ASSERT_EQ(d.wheel_momentum.size(), d.time.size());
  for (std::size_t i = 0; i < d.time.size(); ++i) {
    const double t = d.time[i];
    EXPECT_NEAR(d.torque_body[i].z(), -6.0 * I * theta / (T * T) * (1.0 - 2.0 * t / T), 1e-6);
    EXPECT_NEAR(d.torque_body[i].head<2>().norm(), 0.0, 1e-8);
    // h_z = −I θ̇ with θ̇ = 6Θ/T² t (1 − t/T).
    EXPECT_NEAR(d.wheel_momentum[i].z(), -I * 6.0 * theta / (T * T) * t * (1.0 - t / T), 1e-6);
  }
  const DirectReplay r = replay_direct(p, d);
  EXPECT_LT(r.scaled_error(), 1e-6);
  EXPECT_LT(r.momentum_drift, 1e-11);  // DOP853 at 1e-13 conserves L to round-off over the slew
  EXPECT_LT(r.final_wheel_momentum.norm(), 1e-8);
  // No indirect method for the gyrostat: "not applied", named.
  const IndirectSolution s = solve_indirect(p, d);
  EXPECT_FALSE(s.converged);
  EXPECT_NE(s.status.find("reaction wheels"), std::string::npos) << s.status;
}

// Only wheel 3 bounded (h̄ = 0.25 N·m·s, below the free slew's peak |h_z| = 1.5 I Θ/T = 0.3): the bound is
// active, imposed at the points (tightened if needed) and held on the replay between them; the cost rises
// above the free one.
TEST(ReactionWheels, OneBoundedWheelIsHeldBetweenThePoints) {
  const double I = 2.0, theta = 1.0, T = 10.0, hbar = 0.25;
  ReorientationProblem p = wheel_problem(Vec3(3.0, 4.0, I).asDiagonal(), Vec3(0.2, 0.3, 0.9), 10.0);
  p.objective = Objective::minimum_energy;
  p.final_time = T;
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, Vec3::UnitZ()));
  p.wheels->momentum_max =
      Vec3(std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(), hbar);
  ASSERT_TRUE(p.wheels->has_momentum_bound());
  const DirectSolution d = solve_direct(p);
  ASSERT_TRUE(d.converged) << d.status;
  EXPECT_GT(d.cost, 12.0 * I * I * theta * theta / (T * T * T) * 1.01);
  double peak = 0.0;
  for (const Vec3& h : d.wheel_momentum)
    peak = std::max(peak, std::abs(h.z()));
  EXPECT_LE(peak, hbar * (1.0 - d.wheel_momentum_margin) + 2e-8);
  EXPECT_GT(peak, hbar * (1.0 - d.wheel_momentum_margin) * (1.0 - 1e-6));
  const DirectReplay r = replay_direct(p, d);
  EXPECT_LT(r.scaled_error(), 1e-6);
  EXPECT_LE(r.wheel_momentum_excess, wheel_momentum_replay_tolerance);
}

// A spherical bus (J_b = j I) with wheels on its axes and L = 0 has h = −j ω, so |h_k| ≤ h̄ is the rate bound
// |ω_k| ≤ r = h̄/j. Slewed through Θ about the cube diagonal with |u_k| ≤ ū, by symmetry the three axes move
// alike: accelerate to r, coast, brake; T = Θ/(√3 r) + r j/ū (the coast exists: Θ/√3 > r² j/ū).
TEST(ReactionWheels, MomentumBoundedDiagonalSlewAcceleratesCoastsAndBrakes) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "about 1 s in release (mesh refinement to the junctions), a minute under ASan";
  const double j = 1.5, ubar = 0.8, hbar = 0.6, theta = 2.5;
  ReorientationProblem p = wheel_problem(j * Mat3::Identity(), Vec3::Constant(0.1), ubar);
  p.wheels->momentum_max = Vec3::Constant(hbar);
  p.attitude_final = Quat(Eigen::AngleAxisd(theta, Vec3::Ones().normalized()));
  CollocationOptions o;
  o.initial_intervals = 20;
  o.mesh_tolerance = 1e-7;
  const DirectSolution d = solve_direct(p, o);
  ASSERT_TRUE(d.converged) << d.status;
  // The bounds imposed at the points are h̄ (1 − ε) (ε: the tightening that keeps the replay within h̄
  // between the points), so the solved problem's closed form has r = h̄ (1 − ε)/j.
  const double eps = d.wheel_momentum_margin;
  EXPECT_LT(eps, 1e-3);
  const double r = hbar * (1.0 - eps) / j, T = theta / (std::sqrt(3.0) * r) + r * j / ubar;
  // The junctions (kinks of u) limit Hermite–Simpson to low order near them: the refined mesh puts T within
  // 1e-6 relative.
  EXPECT_NEAR(d.final_time / T, 1.0, 1e-6);
  double peak = 0.0;
  for (const Vec3& h : d.wheel_momentum)
    peak = std::max(peak, h.cwiseAbs().maxCoeff());
  EXPECT_LE(peak, hbar * (1.0 - eps) + 2e-8);          // Ipopt relaxes bounds by 1e-8 max(1, |bound|)
  EXPECT_GT(peak, hbar * (1.0 - eps) * (1.0 - 1e-6));  // active on the coast
  const DirectReplay replay = replay_direct(p, d);
  EXPECT_LT(replay.scaled_error(), 1e-5);
  EXPECT_LE(replay.wheel_momentum_excess, wheel_momentum_replay_tolerance);  // between the points too
}

// The multibody model of reaction_wheel (bus and one wheel on a hinge about z, |u| ≤ 0.1 N·m, 1 rad in 10 s)
// against the gyrostat of the same spacecraft with three wheels, the x and y wheels idle by symmetry: the
// same optimum (the single body J_bus + diag(0.5, 0.5, 0) solved with body torques is a third formulation),
// the multibody one within its transcription's error at N = 32 (measured 4.6e-6 relative).
TEST(ReactionWheels, MatchTheMultibodyWheelModelAndTheSingleBody) {
  if (::poinsot::test::sanitized())
    GTEST_SKIP() << "about 2 s in release (the multibody solve at N = 32), minutes under ASan";
  ReorientationProblem p =
      wheel_problem(testing::reaction_wheel_effective_inertia(), Vec3(0.1, 0.1, 0.9), 0.1);
  p.objective = Objective::minimum_energy;
  p.final_time = 10.0;
  p.attitude_final = Quat(Eigen::AngleAxisd(1.0, Vec3::UnitZ()));
  CollocationOptions o;
  o.mesh_tolerance = 1e-9;
  const DirectSolution gyrostat = solve_direct(p, o);
  ASSERT_TRUE(gyrostat.converged) << gyrostat.status;
  ReorientationProblem single = p;
  single.wheels.reset();
  single.inertia_body = testing::reaction_wheel_effective_inertia();
  const DirectSolution body = solve_direct(single, o);
  ASSERT_TRUE(body.converged) << body.status;
  EXPECT_NEAR(gyrostat.cost / body.cost, 1.0, 1e-8);  // both to the mesh tolerance 1e-9
  const MultibodyOptimum m =
      testing::solve_in(testing::reaction_wheel(1.0, 10.0, 0.1, 32), MultibodyCoordinates::minimal);
  ASSERT_TRUE(m.converged) << m.status;
  EXPECT_NEAR(m.cost / gyrostat.cost, 1.0, 1e-5);
  EXPECT_GT(std::abs(m.cost / gyrostat.cost - 1.0), 1e-7);  // the multibody transcription's own error
}

// A 3-D slew with a bias momentum (h_0 ≠ 0, so L ≠ 0 and the bus feels ω × Rᵀ L) on skewed wheels, solved
// as a gyrostat, then its wheel torques applied to the multibody model of the same spacecraft (a bus and
// three wheel bodies on hinges through the centre of mass) and integrated by the projected RK4 with the
// controls held at each step's midpoint (second order): the bus reaches the target to that integrator's
// error, which falls by 4 when its steps are halved, and the wheels end with the gyrostat's momenta.
TEST(ReactionWheels, ThreeDimensionalSlewReplaysOnTheMultibodyModel) {
  if (::poinsot::test::sanitized()) GTEST_SKIP() << "about 1 s in release, a minute under ASan";
  Mat3 J_bus;
  J_bus << 3.0, 0.1, 0.0, 0.1, 4.0, 0.2, 0.0, 0.2, 2.0;
  ReactionWheels w;
  w.axes_body.col(0) = Vec3(1.0, 0.1, 0.0).normalized();
  w.axes_body.col(1) = Vec3(0.0, 1.0, 0.2).normalized();
  w.axes_body.col(2) = Vec3(0.1, 0.0, 1.0).normalized();
  w.spin_inertia = Vec3(0.05, 0.06, 0.07);
  w.momentum_initial = Vec3(0.3, -0.2, 0.5);
  const double transverse = 0.04, wheel_mass = 1.0;  // a disc: axial ≤ 2 transverse
  Mat3 J_locked = J_bus;
  std::vector<Mat3> J_wheel(3);
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = w.axes_body.col(k);
    J_wheel[k] = w.spin_inertia[k] * a * a.transpose() + transverse * (Mat3::Identity() - a * a.transpose());
    J_locked += J_wheel[k];
  }
  ReorientationProblem p;
  p.inertia_body = J_locked;
  p.wheels = w;
  p.torque_max = Vec3::Constant(0.2);
  p.objective = Objective::minimum_energy;
  p.final_time = 12.0;
  p.attitude_final = Quat(Eigen::AngleAxisd(1.2, Vec3(1.0, -2.0, 2.0).normalized()));
  ASSERT_NO_THROW(validate(p));
  CollocationOptions o;
  o.mesh_tolerance = 1e-9;
  const DirectSolution d = solve_direct(p, o);
  ASSERT_TRUE(d.converged) << d.status;
  const DirectReplay replay = replay_direct(p, d);
  EXPECT_LT(replay.scaled_error(), 1e-6);
  EXPECT_LT(replay.momentum_drift, 1e-11);

  MultibodyProblem mb;
  const int bus = mb.system.add_body_from_inertia("bus", 20.0, J_bus);
  mb.initial_state.bodies.resize(4);
  mb.final_state.bodies.resize(4);
  const Mat3 Rf = p.attitude_final.toRotationMatrix();
  mb.final_state.bodies[0].R_space_body = Rf;
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = w.axes_body.col(k);
    const std::string name = "wheel " + std::to_string(k + 1);
    const int wheel = mb.system.add_body_from_inertia(name, wheel_mass, J_wheel[k]);
    const int hinge = mb.system.add_hinge(name + " axle", wheel, Vec3::Zero(), a, bus, Vec3::Zero(), a);
    mb.actuators.push_back({ActuatorKind::hinge_torque, hinge, 0.2});
    mb.free_final_hinges.push_back(hinge);
    // The wheel frame starts aligned with the bus's; its spin Ω_k = h_k/I_k − a_kᵀω about a_k.
    mb.initial_state.bodies[static_cast<std::size_t>(wheel)].omega_body =
        wheel_speed(w, w.momentum_initial, Vec3::Zero())[k] * a;
    mb.final_state.bodies[static_cast<std::size_t>(wheel)].R_space_body = Rf;
    mb.final_state.bodies[static_cast<std::size_t>(wheel)].omega_body =
        wheel_speed(w, replay.final_wheel_momentum, Vec3::Zero())[k] * a;
  }
  mb.final_time = p.final_time;
  mb.intervals = static_cast<int>(d.node_time.size()) - 1;
  MultibodyOptimum controls;
  controls.time = d.time;
  for (const Vec3& u : d.torque_body)
    controls.controls.emplace_back(Eigen::VectorXd(u));
  // The replay's errors: second order in the step for the held controls (bus attitude and rates), fourth
  // order for the momentum (RK4 on the wheels' fast spin).
  double previous = 0.0, previous_momentum = 0.0;
  for (const int steps : {32, 64}) {
    const MultibodyReplay mr = replay_controls(mb, controls, steps);
    const double error = std::max(mr.attitude_error, p.final_time * mr.velocity_error);
    if (previous > 0.0) {
      EXPECT_LT(error, 5e-6) << steps << " steps per interval";
      EXPECT_GT(previous / error, 3.0);
      EXPECT_LT(previous / error, 5.0);
      EXPECT_GT(previous_momentum / mr.max_momentum_change, 10.0);
      EXPECT_LT(mr.max_momentum_change, 1e-8);
    }
    previous = error;
    previous_momentum = mr.max_momentum_change;
  }
}

// Bad wheels: one line naming the key.
TEST(ReactionWheels, BadInputIsOneLineNamingTheKey) {
  const auto expect_refused = [](const ReorientationProblem& p, const std::string& key,
                                 const std::string& what) {
    try {
      validate(p);
      ADD_FAILURE() << "accepted: " << what;
    } catch (const InvalidInput& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(key), std::string::npos) << m;
      EXPECT_NE(m.find(what), std::string::npos) << m;
      EXPECT_EQ(m.find('\n'), std::string::npos) << m;
    }
  };
  const ReorientationProblem good = wheel_problem(Vec3(3.0, 4.0, 2.0).asDiagonal(), Vec3(0.1, 0.1, 0.1), 0.1);
  ASSERT_NO_THROW(validate(good));
  ReorientationProblem p = good;
  p.wheels->axes_body.col(1).setZero();
  expect_refused(p, "optimal_control.reaction_wheels.axes[2]", "nonzero axis");
  p = good;
  p.wheels->axes_body.col(2) = p.wheels->axes_body.col(0);
  expect_refused(p, "optimal_control.reaction_wheels.axes", "independent");
  p = good;
  p.wheels->spin_inertia[0] = 3.5;  // more than the spacecraft's own moment about x
  expect_refused(p, "optimal_control.reaction_wheels.spin_inertia", "positive definite");
  p = good;
  p.bound = TorqueBound::norm;
  expect_refused(p, "optimal_control.torque_bound", "per_axis");
  // A spinning start ending at rest: the body's momentum J_b ω_0 must end in the wheels.
  p = good;
  p.omega_initial = Vec3(0.0, 0.0, 0.5);  // L = 1 N·m·s about z
  p.wheels->momentum_max = Vec3::Constant(0.8);
  expect_refused(p, "optimal_control.reaction_wheels.momentum_max", "final state");
  p.wheels->momentum_max = Vec3::Constant(1.2);
  EXPECT_NO_THROW(validate(p));
  p.wheels->momentum_initial = Vec3(0.0, 0.0, 1.5);
  expect_refused(p, "optimal_control.reaction_wheels.momentum_max", "initial");
}

}  // namespace
}  // namespace poinsot::optimal
