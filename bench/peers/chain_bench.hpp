// The peer comparison: the same chain of ball-jointed rods (bench/rod_chain.hpp)
// stepped by poinsot's RATTLE and by each peer library, with the same counters measured the same way from
// each library's body poses. One adapter per library (chain_<library>.cpp), each a class with
//   explicit Adapter(int n);                  // build the chain of n links, released at rest (not timed)
//   void step();                              // one step of kChainDt (timed)
//   void reset();                             // back to the released state (not timed)
//   void poses(std::vector<BodyPose>& out);   // each link's pose and velocity (not timed)
// and run_chain<Adapter> below as its benchmark body.
// C++17 on purpose (chain_simbody.cpp is compiled as C++17): no poinsot header here.
#pragma once

#include <benchmark/benchmark.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "../chain_constants.hpp"

namespace poinsot::bench {

/// One link's kinematics in the space frame, as the library reports it.
struct BodyPose {
  Eigen::Vector3d x_space = Eigen::Vector3d::Zero();           ///< centre of mass, m
  Eigen::Matrix3d R_space_body = Eigen::Matrix3d::Identity();  ///< body → space; the rod lies along body x
  Eigen::Vector3d v_space = Eigen::Vector3d::Zero();           ///< velocity of the centre of mass, m/s
  Eigen::Vector3d omega_space = Eigen::Vector3d::Zero();       ///< angular velocity, space frame, rad/s
};

/// Total energy of the chain from the poses, J: Σ ½ m|v|² + ½ ωᵀ (R J Rᵀ) ω + m g z, with the rod's J about
/// its centre of mass diag(m r²/2, m(3r² + l²)/12, m(3r² + l²)/12) in the body frame (the same for every
/// library, so the energy errors compare the integrators, not the bookkeeping).
inline double chain_energy(const std::vector<BodyPose>& links) {
  const double m = kRodMass, l = kRodLength, r = kRodRadius;
  const Eigen::Vector3d J_body(m * r * r / 2.0, m * (3 * r * r + l * l) / 12.0,
                               m * (3 * r * r + l * l) / 12.0);
  double E = 0.0;
  for (const BodyPose& b : links) {
    const Eigen::Vector3d w_body = b.R_space_body.transpose() * b.omega_space;
    E += 0.5 * m * b.v_space.squaredNorm() + 0.5 * w_body.dot(J_body.cwiseProduct(w_body)) +
         m * kGravity * b.x_space.z();
  }
  return E;
}

/// Largest joint gap, m: the distance in the space frame between the two points a ball joint should hold
/// together (link 0's end (-l/2, 0, 0) and the world origin; link i's (-l/2, 0, 0) and link i-1's (+l/2, 0,
/// 0)).
inline double chain_joint_gap(const std::vector<BodyPose>& links) {
  const Eigen::Vector3d half(kRodLength / 2.0, 0, 0);
  double gap = 0.0;
  Eigen::Vector3d parent_end = Eigen::Vector3d::Zero();
  for (const BodyPose& b : links) {
    gap = std::max(gap, (b.x_space - b.R_space_body * half - parent_end).norm());
    parent_end = b.x_space + b.R_space_body * half;
  }
  return gap;
}

/// Height of the chain's free end (the last link's (+l/2, 0, 0)), m: after 1 s it tells whether the libraries
/// integrate the same model (for a short chain, where the motion is not yet chaotic).
inline double chain_tip_z(const std::vector<BodyPose>& links) {
  const BodyPose& b = links.back();
  return (b.x_space + b.R_space_body * Eigen::Vector3d(kRodLength / 2.0, 0, 0)).z();
}

/// The benchmark body: steps the chain of range(0) links from the released state; every 50 steps, outside the
/// timing, samples the energy error and the joint gap; every 5000 steps (5 s) restarts from the released
/// state, as bench_multibody.cpp does. Counters: energy_err_rel = max |E - E0| / (m g l N²/2), max_gap_m, and
/// tip_z_1s_m (chain_tip_z at t = 1 s of the first window).
template <class Adapter>
void run_chain(benchmark::State& bm) {
  const int n = static_cast<int>(bm.range(0));
  Adapter chain(n);
  std::vector<BodyPose> links;
  chain.poses(links);
  const double E0 = chain_energy(links);
  double max_dE = 0.0, max_gap = chain_joint_gap(links);
  long steps = 0;
  double tip_z = 0.0;
  for (auto _ : bm) {
    chain.step();
    ++steps;
    if (steps % 50 == 0) {  // sampled diagnostics, not timed
      bm.PauseTiming();
      chain.poses(links);
      max_dE = std::max(max_dE, std::abs(chain_energy(links) - E0));
      max_gap = std::max(max_gap, chain_joint_gap(links));
      if (steps == 1000) tip_z = chain_tip_z(links);
      if (steps % 5000 == 0) chain.reset();
      bm.ResumeTiming();
    }
  }
  bm.counters["energy_err_rel"] = max_dE / releasable_energy(n);
  bm.counters["max_gap_m"] = max_gap;
  bm.counters["tip_z_1s_m"] = tip_z;
  bm.SetComplexityN(n);
}

/// Steps of one benchmark run of the chain of n links: whole 5000-step windows (5 s, from the release to the
/// restart), so that every library's energy error and gap cover the same motion whatever its speed; more
/// windows for the small chains, whose 5000 steps take only milliseconds.
inline int chain_run_steps(int n) {
  return n <= 1 ? 20000 : n <= 4 ? 10000 : 5000;
}

/// Registers run_chain<Adapter> as "<name>/N/iterations:<chain_run_steps(N)>" for N = 1, 4, 16, 64, 256 up to
/// max_n, in µs per step. The iteration count is fixed (so --benchmark_min_time does not apply); one family
/// per N for that reason, and the growth exponent is fitted by bench_multibody_peers' reporter, not by BigO.
/// From N = single_run_from_n on, one repetition whatever --benchmark_repetitions says (for runs of minutes).
template <class Adapter>
void register_chain(const std::string& name, int max_n = 256, int single_run_from_n = 1 << 30) {
  for (int n = 1; n <= max_n; n *= 4) {
    auto* b = benchmark::RegisterBenchmark(name.c_str(), run_chain<Adapter>)
                  ->Arg(n)
                  ->Iterations(chain_run_steps(n))
                  ->Unit(benchmark::kMicrosecond);
    if (n >= single_run_from_n) b->Repetitions(1);
  }
}

// One registration function per library, defined in chain_<library>.cpp and called from main when the library
// was found (the compile definitions POINSOT_PEER_<LIBRARY>).
void register_poinsot();
void register_bullet();
void register_ode();
void register_mujoco();
void register_simbody();

}  // namespace poinsot::bench
