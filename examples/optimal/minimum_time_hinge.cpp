// Minimum time for a rod on a motor hinge (gravity off), rest to rest through Θ = 1 rad with |u| ≤ 1 N·m, in
// both multibody transcriptions with a free final time, against the bang-bang time T* = 2 √(Θ I / ū): the
// table of docs/optimal_control_multibody.md, "Minimum time". The rod: 1 kg, 1 m, radius 5 cm along body x,
// hinged at its end about z (I = J_zz + m (ℓ/2)² about the hinge). Run:
// build/release/examples/example_minimum_time_hinge
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

#include "poinsot/optimal/multibody_direct.hpp"

int main() {
  using namespace poinsot;
  using namespace poinsot::optimal;
  const double radius = 0.05, theta = 1.0, torque = 1.0;
  const double transverse = (3.0 * radius * radius + 1.0) / 12.0;
  const double I = transverse + 0.25;
  const double T_star = 2.0 * std::sqrt(theta * I / torque);
  std::printf("rod on a hinge, Θ = %g rad, |u| ≤ %g N·m: T* = %.9f s\n", theta, torque, T_star);
  std::printf("%-16s %4s %10s %12s %14s\n", "coordinates", "N", "iterations", "T - T* (s)", "replay (rad)");
  for (const auto coordinates : {MultibodyCoordinates::minimal, MultibodyCoordinates::rotation_matrix}) {
    for (const int n : {7, 8, 15, 16, 31, 32}) {
      MultibodyProblem p;
      const int rod = p.system.add_body_from_inertia(
          "rod", 1.0, Vec3(0.5 * radius * radius, transverse, transverse).asDiagonal());
      const int hinge = p.system.add_hinge("hinge", rod, Vec3(-0.5, 0, 0), Vec3::UnitZ(), multibody::kWorld,
                                           Vec3::Zero(), Vec3::UnitZ());
      p.initial_state.bodies.resize(1);
      p.initial_state.bodies[0].x_space = Vec3(0.5, 0, 0);
      const Mat3 R = Eigen::AngleAxisd(theta, Vec3::UnitZ()).toRotationMatrix();
      p.final_state.bodies.resize(1);
      p.final_state.bodies[0].R_space_body = R;
      p.final_state.bodies[0].x_space = R * Vec3(0.5, 0, 0);
      p.objective = MultibodyObjective::minimum_time;
      p.final_time = 1.0;  // the guess
      p.final_time_min = 0.1;
      p.final_time_max = 10.0;
      p.intervals = n;
      p.actuators = {{ActuatorKind::hinge_torque, hinge, torque}};
      MultibodyOptions options;
      options.coordinates = coordinates;
      const MultibodyOptimum o = solve_multibody(p, options);
      if (!o.converged) {
        std::printf("N = %d: %s\n", n, o.status.c_str());
        return 1;
      }
      const MultibodyReplay replay = replay_controls(p, o, 64);
      std::printf("%-16s %4d %10d %12.3e %14.2e\n",
                  coordinates == MultibodyCoordinates::minimal ? "minimal" : "rotation_matrix", n,
                  o.nlp_iterations, o.time.back() - T_star, replay.attitude_error);
    }
  }
  return 0;
}
