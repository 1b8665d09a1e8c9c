// Mesh refinement of the two-link arm (minimal coordinates, the arm of examples/optimal/two_link_arm.toml):
// from 8 equal intervals, every interval whose local error exceeds the tolerance is split, against equal
// intervals of the same number (docs/optimal_control_multibody.md, "Mesh refinement"). Run:
// build/release/examples/example_refine_arm (seconds).
#include <algorithm>
#include <cstdio>
#include <numbers>

#include <Eigen/Geometry>

#include "poinsot/optimal/multibody_refinement.hpp"

namespace {

using namespace poinsot;
using namespace poinsot::optimal;

/// The arm's state at (θ1, θ2) at rest: rods of 1 m from the shoulder at the origin, about z.
multibody::State arm_state(double th1, double th2) {
  multibody::State s;
  s.bodies.resize(2);
  const Mat3 R1 = Eigen::AngleAxisd(th1, Vec3::UnitZ()).toRotationMatrix();
  const Mat3 R2 = Eigen::AngleAxisd(th1 + th2, Vec3::UnitZ()).toRotationMatrix();
  s.bodies[0].R_space_body = R1;
  s.bodies[0].x_space = R1 * Vec3(0.5, 0, 0);
  s.bodies[1].R_space_body = R2;
  s.bodies[1].x_space = R1 * Vec3(1.0, 0, 0) + R2 * Vec3(0.5, 0, 0);
  return s;
}

MultibodyProblem arm(int intervals) {
  MultibodyProblem p;
  const double r = 0.05, transverse = (3.0 * r * r + 1.0) / 12.0;
  const Mat3 J = Vec3(0.5 * r * r, transverse, transverse).asDiagonal();
  const int upper = p.system.add_body_from_inertia("upper", 1.0, J);
  const int fore = p.system.add_body_from_inertia("fore", 1.0, J);
  const int shoulder = p.system.add_hinge("shoulder", upper, Vec3(-0.5, 0, 0), Vec3::UnitZ(),
                                          multibody::kWorld, Vec3::Zero(), Vec3::UnitZ());
  const int elbow = p.system.add_hinge("elbow", fore, Vec3(-0.5, 0, 0), Vec3::UnitZ(), upper, Vec3(0.5, 0, 0),
                                       Vec3::UnitZ());
  p.system.set_gravity(Vec3(0.0, -9.81, 0.0));
  const double down = -0.5 * std::numbers::pi;
  p.initial_state = arm_state(down, 0.0);
  p.final_state = arm_state(down + 1.0, 0.5);
  p.final_time = 1.5;
  p.intervals = intervals;
  p.actuators = {{ActuatorKind::hinge_torque, shoulder, 50.0}, {ActuatorKind::hinge_torque, elbow, 50.0}};
  return p;
}

}  // namespace

int main() {
  MultibodyOptions o;
  o.coordinates = MultibodyCoordinates::minimal;
  for (const double tolerance : {1e-3, 1e-4}) {
    std::printf("tolerance %g rad:\n", tolerance);
    const MultibodyRefinement r = refine_multibody(arm(8), o, tolerance);
    for (const MultibodyRefinementRound& round : r.rounds)
      std::printf("  N = %3d: largest local error %.3e rad, cost %.10f N²·m²·s, %d Ipopt iterations, %s\n",
                  round.intervals, round.max_error, round.cost, round.nlp_iterations, round.status.c_str());
    const MultibodyReplay refined = replay_controls(r.problem, r.optimum, 64);
    const MultibodyProblem q = arm(r.problem.intervals);
    const MultibodyOptimum equal = solve_multibody(q, o);
    const std::vector<double> errors = interval_errors(q, equal);
    const MultibodyReplay uniform = replay_controls(q, equal, 64);
    std::printf("  refined, %d intervals: re-simulation misses the target by %.3e rad\n", r.problem.intervals,
                refined.attitude_error);
    std::printf("  equal, %d intervals: largest local error %.3e rad, cost %.10f, misses by %.3e rad\n",
                q.intervals, *std::max_element(errors.begin(), errors.end()), equal.cost,
                uniform.attitude_error);
  }
  return 0;
}
