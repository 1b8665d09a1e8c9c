// A URDF arm in poinsot and in DART 6.12 (its URDF loader, libdart-utils-urdf-dev), in one process
// (docs/measurements/peers.md, "A URDF arm beside DART"). The model, tests/data/models/robots/arm5.urdf, has
// a base fixed to the world, four revolute joints about different axes in rotated joint frames, a prismatic
// wrist, full inertia tensors with products of inertia, and a massless tool frame; limits are not modelled by
// either.
//  1. the inertias DART built against poinsot's, body by body (mass, centre of mass in space, tensor about
//  the
//     centre of mass in the body frame);
//  2. the same initial state (joint rates drawn from a seeded generator, by joint name), 1 s under gravity:
//     poinsot's projected RK4 at dt = 1e-4 and 1e-5 against DART's forward dynamics integrated by the
//     classical RK4 in its joint coordinates at dt = 1e-5 (and at 2e-5 against 1e-5: the reference's own
//     error), as the largest difference of the bodies' centres of mass (m) and frames (rad);
//  3. energy over 10⁵ steps of dt = 1e-3 in zero gravity: poinsot RATTLE (orders 2 and 4), DART's own step
//     (semi-implicit Euler, World::step) and DART with the RK4 of step 2;
//  4. CPU time per step (Google Benchmark): poinsot RATTLE and RK4, DART's step and DART RK4, dt = 1e-3.
// Run: build/release/bench/peers/bench_robot_files_dart [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include <dart/dynamics/BodyNode.hpp>
#include <dart/dynamics/DegreeOfFreedom.hpp>
#include <dart/dynamics/Skeleton.hpp>
#include <dart/simulation/World.hpp>
#include <dart/utils/urdf/DartLoader.hpp>

#include "poinsot/io/robot/robot_system.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "robot_bench_poinsot.hpp"

#ifndef POINSOT_SOURCE_DIR
#define POINSOT_SOURCE_DIR "."
#endif

namespace {

using poinsot::Mat3;
using poinsot::Vec3;
namespace mb = poinsot::multibody;
namespace io = poinsot::io;
using dart::dynamics::SkeletonPtr;

const Vec3 kGravity(0.0, 0.0, -9.81);
/// The benchmarks start again from the initial state every this many steps (1 s of motion).
constexpr long kRestartSteps = 1000;

std::string arm_path() {
  return std::string(POINSOT_SOURCE_DIR) + "/tests/data/models/robots/arm5.urdf";
}

SkeletonPtr load_dart() {
  dart::utils::DartLoader::Options options;
  options.mDefaultRootJointType = dart::utils::DartLoader::RootJointType::FIXED;
  // A link without <inertial> has no mass, as URDF means it (DART's default is 1 kg and a unit tensor).
  options.mDefaultInertia = dart::dynamics::Inertia(0.0, Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero());
  dart::utils::DartLoader loader(options);
  SkeletonPtr skel = loader.parseSkeleton(dart::common::Uri::createFromPath(arm_path()));
  if (!skel) throw std::runtime_error("DART cannot load " + arm_path());
  skel->setGravity(kGravity);
  return skel;
}

/// Joint rates drawn by DART's degree-of-freedom names (uniform in ±2 rad/s or m/s; the prismatic wrist ±0.05
/// m/s), the same for both libraries.
std::map<std::string, double> draw_rates(const SkeletonPtr& skel) {
  std::mt19937_64 gen(20261129);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  std::map<std::string, double> rates;
  for (std::size_t k = 0; k < skel->getNumDofs(); ++k) {
    const dart::dynamics::DegreeOfFreedom* dof = skel->getDof(k);
    const double scale = dof->getJoint()->getType() == "PrismaticJoint" ? 0.025 : 1.0;
    rates[dof->getJoint()->getName()] = scale * u(gen);
  }
  return rates;
}

void set_dart_rates(const SkeletonPtr& skel, const std::map<std::string, double>& rates) {
  skel->resetPositions();
  skel->resetVelocities();
  for (std::size_t k = 0; k < skel->getNumDofs(); ++k)
    skel->getDof(k)->setVelocity(rates.at(skel->getDof(k)->getJoint()->getName()));
}

mb::Scenario poinsot_scenario(const std::map<std::string, double>& rates, const Vec3& gravity = kGravity) {
  io::RobotSystemOptions o;
  o.gravity = gravity;
  for (const auto& [name, rate] : rates)
    o.velocities[name] = {rate};
  return io::load_robot_scenario(arm_path(), o);
}

/// Per poinsot body, DART's body node of the same link.
std::vector<const dart::dynamics::BodyNode*> dart_bodies(const SkeletonPtr& skel, const mb::System& system) {
  std::vector<const dart::dynamics::BodyNode*> out;
  for (const mb::Body& b : system.bodies()) {
    const dart::dynamics::BodyNode* node = skel->getBodyNode(b.name);
    if (node == nullptr) throw std::runtime_error("DART has no body " + b.name);
    out.push_back(node);
  }
  return out;
}

/// One classical RK4 step of DART's forward dynamics in its joint coordinates (revolute and prismatic
/// joints: positions add).
void dart_rk4_step(const SkeletonPtr& skel, double h) {
  const Eigen::VectorXd q0 = skel->getPositions(), v0 = skel->getVelocities();
  const auto accel = [&](const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
    skel->setPositions(q);
    skel->setVelocities(v);
    skel->computeForwardDynamics();
    return Eigen::VectorXd(skel->getAccelerations());
  };
  const Eigen::VectorXd a1 = accel(q0, v0);
  const Eigen::VectorXd q2 = q0 + 0.5 * h * v0, v2 = v0 + 0.5 * h * a1;
  const Eigen::VectorXd a2 = accel(q2, v2);
  const Eigen::VectorXd q3 = q0 + 0.5 * h * v2, v3 = v0 + 0.5 * h * a2;
  const Eigen::VectorXd a3 = accel(q3, v3);
  const Eigen::VectorXd q4 = q0 + h * v3, v4 = v0 + h * a3;
  const Eigen::VectorXd a4 = accel(q4, v4);
  skel->setPositions(q0 + h / 6.0 * (v0 + 2.0 * v2 + 2.0 * v3 + v4));
  skel->setVelocities(v0 + h / 6.0 * (a1 + 2.0 * a2 + 2.0 * a3 + a4));
}

/// Largest position (m) and rotation (rad) differences of the bodies' centres of mass and frames.
std::pair<double, double> difference(const mb::State& s,
                                     const std::vector<const dart::dynamics::BodyNode*>& map) {
  double dx = 0.0, dr = 0.0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    dx = std::max(dx, (s.bodies[i].x_space - map[i]->getCOM()).norm());
    const Mat3 R = map[i]->getWorldTransform().linear();
    dr = std::max(dr, poinsot::so3::log(R.transpose() * s.bodies[i].R_space_body).norm());
  }
  return {dx, dr};
}

void compare_inertias() {
  const SkeletonPtr skel = load_dart();
  const mb::Scenario sc = io::load_robot_scenario(arm_path(), {});
  const auto map = dart_bodies(skel, sc.system);
  std::printf("\narm5: inertias, poinsot against DART, body by body (DART has %zu body nodes, %zu dofs)\n",
              skel->getNumBodyNodes(), skel->getNumDofs());
  std::printf("  %-10s %12s %12s %12s %12s\n", "body", "mass (kg)", "|dm| (kg)", "|dc| (m)", "|dJ| (kg m2)");
  for (std::size_t i = 0; i < map.size(); ++i) {
    const mb::Body& b = sc.system.bodies()[i];
    const dart::dynamics::Inertia& in = map[i]->getInertia();
    const double dm = std::abs(b.mass - in.getMass());
    const double dc = (sc.initial.bodies[i].x_space - map[i]->getCOM()).norm();
    // DART's moment is about the centre of mass in the body node's frame; poinsot's J in the body frame,
    // whose axes are the link's.
    const double dJ = (b.inertia - in.getMoment()).cwiseAbs().maxCoeff();
    std::printf("  %-10s %12.6g %12.3g %12.3g %12.3g\n", b.name.c_str(), b.mass, dm, dc, dJ);
  }
}

void compare_trajectories() {
  const SkeletonPtr skel = load_dart();
  const auto rates = draw_rates(skel);
  const mb::Scenario sc = poinsot_scenario(rates);
  const auto map = dart_bodies(skel, sc.system);
  // The initial angular velocities agree?
  set_dart_rates(skel, rates);
  double dv0 = 0.0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const mb::BodyState& s = sc.initial.bodies[i];
    dv0 = std::max(dv0, (map[i]->getAngularVelocity() - s.R_space_body * s.omega_body).norm());
  }
  const auto dart_run = [&](double dt) {
    set_dart_rates(skel, rates);
    const long n = std::lround(1.0 / dt);
    for (long k = 0; k < n; ++k)
      dart_rk4_step(skel, dt);
    mb::State s = sc.initial;  // DART's poses, in a poinsot-shaped state
    for (std::size_t i = 0; i < map.size(); ++i) {
      s.bodies[i].x_space = map[i]->getCOM();
      s.bodies[i].R_space_body = map[i]->getWorldTransform().linear();
    }
    return s;
  };
  const mb::State half = dart_run(2e-5);
  dart_run(1e-5);  // the reference: the skeleton is left at its end
  const auto [x4, r4] = difference(poinsot::bench::projected_rk4_run(sc, 1e-4), map);
  const auto [x5, r5] = difference(poinsot::bench::projected_rk4_run(sc, 1e-5), map);
  const auto [xd, rd] = difference(half, map);
  std::printf(
      "\narm5: 1 s under gravity from the same state (initial angular velocities agree to %.2g rad/s)\n",
      dv0);
  std::printf(
      "  against DART RK4 dt=1e-5:  poinsot RK4 dt=1e-4: %.3g m, %.3g rad;  dt=1e-5: %.3g m, %.3g rad;"
      "  DART RK4 dt=2e-5: %.3g m, %.3g rad\n",
      x4, r4, x5, r5, xd, rd);
}

/// In zero gravity: under gravity the wrist's unlimited slide lets the finger fall without end, its potential
/// energy unbounded below, and the links' rates grow without bound.
void compare_energy() {
  const long steps = 100000;
  const double dt = 1e-3;
  const SkeletonPtr skel = load_dart();
  skel->setGravity(Vec3::Zero());
  const auto rates = draw_rates(skel);
  const mb::Scenario sc = poinsot_scenario(rates, Vec3::Zero());
  std::printf("\narm5: energy in zero gravity over 1e5 steps of dt = 1e-3, max |E - E0| / max(T)\n");
  for (const int order : {2, 4}) {
    try {
      const poinsot::bench::RattleDrift drift = poinsot::bench::rattle_drift(sc, order, dt, steps);
      std::printf("  poinsot RATTLE order %d: %.3g (first tenth of the run: %.3g)\n", order, drift.energy,
                  drift.energy_first_tenth);
    } catch (const std::exception& e) {
      std::printf("  poinsot RATTLE order %d: failed: %s\n", order, e.what());
    }
  }
  const auto dart_energy = [&](const char* label, auto&& step) {
    set_dart_rates(skel, rates);
    const double e0 = skel->computeKineticEnergy() + skel->computePotentialEnergy();
    double de = 0.0, tmax = 0.0, de_first = 0.0;
    for (long k = 0; k < steps; ++k) {
      step();
      const double T = skel->computeKineticEnergy();
      de = std::max(de, std::abs(T + skel->computePotentialEnergy() - e0));
      tmax = std::max(tmax, T);
      if (k == steps / 10) de_first = de / tmax;
    }
    std::printf("  DART %s: %.3g (first tenth: %.3g)\n", label, de / tmax, de_first);
  };
  auto world = std::make_shared<dart::simulation::World>();
  world->setGravity(Vec3::Zero());
  world->setTimeStep(dt);
  world->addSkeleton(skel);
  dart_energy("step (semi-implicit Euler)", [&] { world->step(); });
  dart_energy("RK4", [&] { dart_rk4_step(skel, dt); });
}

void BM_Poinsot(benchmark::State& state, bool rk4) {
  poinsot::bench::time_poinsot_steps(state, poinsot_scenario(draw_rates(load_dart())), rk4, kRestartSteps);
}

void BM_Dart(benchmark::State& state, bool rk4) {
  const SkeletonPtr skel = load_dart();
  const auto rates = draw_rates(skel);
  auto world = std::make_shared<dart::simulation::World>();
  world->setGravity(kGravity);
  world->setTimeStep(1e-3);
  world->addSkeleton(skel);
  set_dart_rates(skel, rates);
  long k = 0;
  for (auto _ : state) {
    if (rk4) {
      dart_rk4_step(skel, 1e-3);
    } else {
      world->step();
    }
    if (++k % kRestartSteps == 0) set_dart_rates(skel, rates);
  }
  benchmark::DoNotOptimize(skel->getPositions());
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  compare_inertias();
  compare_trajectories();
  compare_energy();
  benchmark::RegisterBenchmark("poinsot_rattle/arm5", BM_Poinsot, false);
  benchmark::RegisterBenchmark("poinsot_rk4/arm5", BM_Poinsot, true);
  benchmark::RegisterBenchmark("dart_step/arm5", BM_Dart, false);
  benchmark::RegisterBenchmark("dart_rk4/arm5", BM_Dart, true);
  std::printf("\n");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
