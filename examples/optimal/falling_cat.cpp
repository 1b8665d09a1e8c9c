// The falling cat (Kane & Scher 1969), turned by a quarter turn: two identical axisymmetric halves joined at
// a point by a ball joint with three motors, free floating at zero angular momentum, rotate as a whole about
// their spine by changing shape, at minimum effort ∫|τ|²dt, in rotation-matrix coordinates.
//
// Each half is a cylinder (1 kg, 1 m, radius 0.2 m) along its body x, the waist at its +x end; the cat is
// bent into a V in the x–z plane, each half tilted by 0.5 rad from the spine (space x), centre of mass at the
// origin. Target: the same V turned by π/2 about x, at rest, after 1 s. (The half-turn meets a spurious
// solution of the stabilised R-coordinate form and is reported as not converged: docs/optimal_control.md.)
// Run: build/release/examples/example_falling_cat
#include <cmath>
#include <cstdio>
#include <numbers>

#include <Eigen/Geometry>

#include "poinsot/optimal/multibody_direct.hpp"

namespace {

poinsot::multibody::State bent(double alpha, const poinsot::Mat3& turn) {
  using poinsot::Mat3;
  using poinsot::Vec3;
  poinsot::multibody::State s;
  s.bodies.resize(2);
  const Mat3 Ra = Eigen::AngleAxisd(alpha, Vec3::UnitY()).toRotationMatrix();
  const Mat3 Rb = Eigen::AngleAxisd(std::numbers::pi, Vec3::UnitZ()).toRotationMatrix() * Ra;
  const Vec3 waist(0.0, 0.0, -0.5 * std::sin(alpha));
  s.bodies[0].R_space_body = turn * Ra;
  s.bodies[0].x_space = turn * (waist - Ra * Vec3(0.5, 0.0, 0.0));
  s.bodies[1].R_space_body = turn * Rb;
  s.bodies[1].x_space = turn * (waist - Rb * Vec3(0.5, 0.0, 0.0));
  return s;
}

}  // namespace

int main() {
  using namespace poinsot;
  using namespace poinsot::optimal;
  MultibodyProblem p;
  const Mat3 J = Vec3(0.5 * 0.04, (3.0 * 0.04 + 1.0) / 12.0, (3.0 * 0.04 + 1.0) / 12.0).asDiagonal();
  const int front = p.system.add_body_from_inertia("front", 1.0, J);
  const int back = p.system.add_body_from_inertia("back", 1.0, J);
  const int waist = p.system.add_ball("waist", front, Vec3(0.5, 0, 0), back, Vec3(0.5, 0, 0));
  p.initial_state = bent(0.5, Mat3::Identity());
  p.final_state = bent(0.5, Eigen::AngleAxisd(0.5 * std::numbers::pi, Vec3::UnitX()).toRotationMatrix());
  p.final_time = 1.0;
  p.intervals = 12;
  p.actuators = {{ActuatorKind::ball_torque, waist, 100.0}};
  const MultibodyOptimum o = solve_multibody(p);
  if (!o.converged) {
    std::printf("falling cat: %s\n", o.status.c_str());
    return 1;
  }
  const MultibodyReplay replay = replay_controls(p, o, 256);
  std::printf("falling cat (R-coordinates, N = %d): effort %.8f N²·m²·s, %d Ipopt iterations\n", p.intervals,
              o.cost, o.nlp_iterations);
  std::printf("  re-simulated: attitude error %.2e rad, joint gap %.2e m, momentum change %.2e\n",
              replay.attitude_error, replay.max_joint_gap, replay.max_momentum_change);
  return 0;
}
