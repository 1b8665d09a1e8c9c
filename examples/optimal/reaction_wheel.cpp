// A spacecraft slewed by its reaction wheel at minimum energy, solved as a multibody problem in
// rotation-matrix coordinates and compared with the single-body optimum of the same effective inertia.
//
// The bus (10 kg, J = diag(3, 4, 2) kg·m²) carries a flywheel (5 kg, J = diag(0.5, 0.5, 0.9) kg·m²) on a
// hinge about body z through both centres of mass; nothing else acts (free floating, no gravity), so the
// total angular momentum stays zero and the bus turns only by spinning the wheel the other way. The bus goes
// from rest to rest through 1 rad about z in 10 s, the wheel motor bounded by |u| ≤ 0.1 N·m; the wheel's
// final angle is left free. With H = 0 the bus obeys I_zz θ̈ = −u with I_zz = 2 kg·m², so the single body with
// the locked inertia less the wheel's axial part, J_bus + diag(0.5, 0.5, 0), driven about z, has the same
// optimum. Run: build/release/examples/example_reaction_wheel (a few minutes on a loaded machine).
#include <cstdio>

#include <Eigen/Geometry>

#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/multibody_direct.hpp"

int main() {
  using namespace poinsot;
  using namespace poinsot::optimal;
  MultibodyProblem p;
  const int bus = p.system.add_body_from_inertia("bus", 10.0, Vec3(3.0, 4.0, 2.0).asDiagonal());
  const int wheel = p.system.add_body_from_inertia("wheel", 5.0, Vec3(0.5, 0.5, 0.9).asDiagonal());
  const int axle =
      p.system.add_hinge("wheel axle", wheel, Vec3::Zero(), Vec3::UnitZ(), bus, Vec3::Zero(), Vec3::UnitZ());
  const Mat3 turned = Eigen::AngleAxisd(1.0, Vec3::UnitZ()).toRotationMatrix();
  p.initial_state.bodies.resize(2);
  p.final_state.bodies.resize(2);
  p.final_state.bodies[0].R_space_body = turned;
  p.final_state.bodies[1].R_space_body = turned;  // any angle about z: free_final_hinges leaves it free
  p.final_time = 10.0;
  p.intervals = 16;
  p.actuators = {{ActuatorKind::hinge_torque, axle, 0.1}};
  p.free_final_hinges = {axle};
  const MultibodyOptimum o = solve_multibody(p);
  if (!o.converged) {
    std::printf("multibody: %s\n", o.status.c_str());
    return 1;
  }
  const MultibodyReplay replay = replay_controls(p, o, 64);
  std::printf("multibody (R-coordinates, N = %d): cost %.10f N²·m²·s, %d Ipopt iterations\n", p.intervals,
              o.cost, o.nlp_iterations);
  std::printf("  re-simulated: bus attitude error %.2e rad, rates %.2e rad/s, momentum change %.2e\n",
              replay.attitude_error, replay.velocity_error, replay.max_momentum_change);
  ReorientationProblem single;
  single.inertia_body = Vec3(3.5, 4.5, 2.0).asDiagonal();
  single.torque_max = Vec3::Constant(0.1);
  single.attitude_final = Quat(turned);
  single.objective = Objective::minimum_energy;
  single.final_time = 10.0;
  CollocationOptions options;
  options.mesh_tolerance = 1e-9;
  const DirectSolution d = solve_direct(single, options);
  if (!d.converged) {
    std::printf("single body: %s\n", d.status.c_str());
    return 1;
  }
  std::printf("single body, effective inertia: cost %.10f N²·m²·s; relative difference %.2e\n", d.cost,
              o.cost / d.cost - 1.0);
  return 0;
}
