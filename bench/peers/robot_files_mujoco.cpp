// Robot files in poinsot and in MuJoCo 2.2, in one process (docs/measurements/peers.md, "Robot files beside
// MuJoCo"). For each MJCF model both can load — MuJoCo's own sample arm26.xml and humanoid.xml (in zero
// gravity), and the test models pendulum2.xml (a double pendulum under gravity) and joints.xml (a hinge, a
// slide, a ball, two hinges about one point, three hinges about one point, two hinges about different points,
// welds and a free body) — with MuJoCo's contacts, limits, passive forces (joint damping and springs) and
// actuators switched off, and poinsot's joint springs left out; and pendulum2.xml, springs.xml,
// universal_springs.xml (two sprung hinges of one body about one point, a universal joint in poinsot) and
// humanoid.xml (every hinge sprung and damped) with the joint springs and dampers on in both (steps 1 and 2
// only):
//  1. the inertias MuJoCo compiled against poinsot's, body by body (mass, centre of mass, tensor);
//  2. the same initial state (joint rates drawn from a seeded generator, by joint name), 1 s of motion:
//     poinsot's projected RK4 at dt = 1e-4 and 1e-5 against MuJoCo's RK4 at dt = 1e-5 (and MuJoCo's RK4 at
//     2e-5 against 1e-5: the reference's own error), as the largest difference of the bodies' positions (m)
//     and rotations (rad) after 1 s;
//  3. energy over 10⁵ steps of dt = 1e-3: poinsot RATTLE, MuJoCo RK4 and Euler;
//  4. CPU time per step (Google Benchmark): poinsot RATTLE and RK4, MuJoCo RK4 and Euler, dt = 1e-3.
// The benchmarks of step 4 start again from the initial state every second of motion (joints.xml's slider has
// no limit and leaves in a few seconds). Run: build/release/bench/peers/bench_robot_files_mujoco
// [--benchmark_repetitions=3]
#include <benchmark/benchmark.h>
#include <mujoco/mujoco.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "poinsot/io/robot/robot_model.hpp"
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

/// The benchmarks start again from the initial state every this many steps (1 s of motion).
constexpr long kRestartSteps = 1000;

struct Model {
  std::string name;
  std::string path;
  bool zero_gravity = false;
  /// Joint springs and dampers in both: MuJoCo's passive forces on, poinsot's joint springs modelled. Such a
  /// model is compared for its trajectories only (its energy is not conserved).
  bool passive = false;
};

std::vector<Model> models() {
  const std::string robots = std::string(POINSOT_SOURCE_DIR) + "/tests/data/models/robots/";
  std::vector<Model> out = {{"arm26", "/usr/share/mujoco/model/tendon_arm/arm26.xml"},
                            {"pendulum2", robots + "pendulum2.xml"},
                            {"joints", robots + "joints.xml"},
                            {"pendulum2, dampers on", robots + "pendulum2.xml", false, true},
                            {"springs", robots + "springs.xml", false, true},
                            {"universal springs", robots + "universal_springs.xml", false, true}};
  // MuJoCo's humanoid as it is: its ankles are two hinges about points 4 cm apart, a universal joint whose
  // axes do not meet in poinsot.
  const std::string humanoid = "/usr/share/mujoco/model/humanoid/humanoid.xml";
  if (std::ifstream(humanoid).good()) {
    out.push_back({"humanoid", humanoid, true});
    out.push_back({"humanoid, springs on", humanoid, true, true});
  }
  return out;
}

mjModel* load_mujoco(const Model& md, int integrator, double dt) {
  char error[1000] = "";
  mjModel* m = mj_loadXML(md.path.c_str(), nullptr, error, sizeof error);
  if (m == nullptr) throw std::runtime_error("MuJoCo cannot load " + md.path + ": " + error);
  m->opt.disableflags |= mjDSBL_CONTACT | mjDSBL_LIMIT | mjDSBL_ACTUATION | mjDSBL_FRICTIONLOSS;
  if (!md.passive) m->opt.disableflags |= mjDSBL_PASSIVE;
  if (md.zero_gravity) m->opt.disableflags |= mjDSBL_GRAVITY;
  for (int i = 0; i < m->nv; ++i)
    m->dof_armature[i] = 0.0;  // MuJoCo's armature adds to the joint-space mass matrix: not a rigid body's
  m->opt.enableflags |= mjENBL_ENERGY;
  m->opt.integrator = integrator;
  m->opt.timestep = dt;
  return m;
}

/// Joint rates drawn by name (uniform in ±2 rad/s or m/s per coordinate), the same for both libraries.
struct Rates {
  std::map<std::string, std::vector<double>> by_joint;  // hinge, slide: 1; ball: 3
  Vec3 free_v = Vec3::Zero(), free_w = Vec3::Zero();
};

Rates draw_rates(const mjModel* m) {
  std::mt19937_64 gen(20261129);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  Rates r;
  for (int j = 0; j < m->njnt; ++j) {
    const char* name = mj_id2name(m, mjOBJ_JOINT, j);
    const int type = m->jnt_type[j];
    if (type == mjJNT_FREE) {
      r.free_v = Vec3(u(gen), u(gen), u(gen)) * 0.1;
      r.free_w = Vec3(u(gen), u(gen), u(gen));
      continue;
    }
    const int n = type == mjJNT_BALL ? 3 : 1;
    std::vector<double> v;
    for (int k = 0; k < n; ++k)
      v.push_back(u(gen));
    if (name != nullptr) r.by_joint[name] = v;
  }
  return r;
}

void set_mujoco_rates(const mjModel* m, mjData* d, const Rates& r) {
  for (int j = 0; j < m->njnt; ++j) {
    const int adr = m->jnt_dofadr[j];
    if (m->jnt_type[j] == mjJNT_FREE) {
      for (int k = 0; k < 3; ++k) {
        d->qvel[adr + k] = r.free_v[k];
        d->qvel[adr + 3 + k] = r.free_w[k];
      }
      continue;
    }
    const char* name = mj_id2name(m, mjOBJ_JOINT, j);
    const auto it = r.by_joint.find(name != nullptr ? name : "");
    if (it == r.by_joint.end()) continue;
    for (std::size_t k = 0; k < it->second.size(); ++k)
      d->qvel[adr + static_cast<int>(k)] = it->second[k];
  }
  mj_forward(m, d);
}

mb::Scenario poinsot_scenario(const Model& md, const Rates& r, bool has_free) {
  io::RobotSystemOptions o;
  o.joint_springs = md.passive;  // as MuJoCo's passive forces (load_mujoco)
  if (md.zero_gravity) o.gravity = Vec3::Zero();
  o.velocities = r.by_joint;
  if (has_free) {
    o.base_velocity = r.free_v;
    o.base_omega_body = r.free_w;
  }
  return io::load_robot_scenario(md.path, o);
}

/// Per poinsot body, the MuJoCo body with the same link (MJCF bodies in pre-order are MuJoCo's 1, 2, ...).
std::vector<int> mujoco_bodies(const std::string& path, const mb::System& system) {
  const io::RobotModel model = io::load_robot_model(path);
  std::vector<int> out;
  for (const mb::Body& b : system.bodies()) {
    int found = -1;
    for (std::size_t k = 0; k < model.links.size(); ++k)
      if (model.links[k].name == b.name) found = static_cast<int>(k) + 1;
    out.push_back(found);
  }
  return out;
}

Mat3 mat3(const mjtNum* x) {
  Mat3 R;
  R << x[0], x[1], x[2], x[3], x[4], x[5], x[6], x[7], x[8];
  return R;
}

/// Largest position (m) and rotation (rad) differences of the bodies' centres of mass and frames.
std::pair<double, double> difference(const mb::State& s, const mjData* d, const std::vector<int>& map) {
  double dx = 0.0, dr = 0.0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const int b = map[i];
    const Vec3 x(d->xipos[3 * b], d->xipos[3 * b + 1], d->xipos[3 * b + 2]);
    dx = std::max(dx, (s.bodies[i].x_space - x).norm());
    const Mat3 R = mat3(d->xmat + 9 * b);
    dr = std::max(dr, poinsot::so3::log(R.transpose() * s.bodies[i].R_space_body).norm());
  }
  return {dx, dr};
}

void compare_inertias(const Model& md) {
  mjModel* m = load_mujoco(md, mjINT_RK4, 1e-3);
  const mb::Scenario sc = io::load_robot_scenario(md.path);
  const std::vector<int> map = mujoco_bodies(md.path, sc.system);
  std::printf("\n%s: inertias, poinsot against MuJoCo, body by body\n", md.name.c_str());
  std::printf("  %-22s %12s %12s %12s %12s\n", "body", "mass (kg)", "|dm| (kg)", "|dc| (m)", "|dJ| (kg m2)");
  for (std::size_t i = 0; i < map.size(); ++i) {
    const int b = map[i];
    const mb::Body& pb = sc.system.bodies()[i];
    const mjtNum* q = m->body_iquat + 4 * b;
    mjtNum Rm[9];
    mju_quat2Mat(Rm, q);
    const Mat3 R = mat3(Rm);
    const Vec3 d(m->body_inertia[3 * b], m->body_inertia[3 * b + 1], m->body_inertia[3 * b + 2]);
    const Mat3 J = R * d.asDiagonal() * R.transpose();
    // poinsot's centre of mass in the link frame: x − origin, from the initial state and MuJoCo's frame.
    mjData* dd = mj_makeData(m);
    mj_forward(m, dd);
    const Vec3 origin(dd->xpos[3 * b], dd->xpos[3 * b + 1], dd->xpos[3 * b + 2]);
    const Mat3 Rb = mat3(dd->xmat + 9 * b);
    const Vec3 c = Rb.transpose() * (sc.initial.bodies[i].x_space - origin);
    const Vec3 cm(m->body_ipos[3 * b], m->body_ipos[3 * b + 1], m->body_ipos[3 * b + 2]);
    mj_deleteData(dd);
    std::printf("  %-22s %12.6g %12.3g %12.3g %12.3g\n", pb.name.c_str(), pb.mass,
                std::abs(pb.mass - m->body_mass[b]), (c - cm).norm(), (pb.inertia - J).cwiseAbs().maxCoeff());
  }
  mj_deleteModel(m);
}

void compare_trajectories(const Model& md) {
  mjModel* m = load_mujoco(md, mjINT_RK4, 1e-5);
  bool has_free = false;
  for (int j = 0; j < m->njnt; ++j)
    has_free = has_free || m->jnt_type[j] == mjJNT_FREE;
  const Rates r = draw_rates(m);
  const mb::Scenario sc = poinsot_scenario(md, r, has_free);
  const std::vector<int> map = mujoco_bodies(md.path, sc.system);
  // MuJoCo's RK4 at 1e-5 and 2e-5 over 1 s.
  const auto mujoco_run = [&](double dt) {
    m->opt.timestep = dt;
    mjData* d = mj_makeData(m);
    set_mujoco_rates(m, d, r);
    const long n = std::lround(1.0 / dt);
    for (long k = 0; k < n; ++k)
      mj_step(m, d);
    mj_forward(m, d);
    return d;
  };
  mjData* ref = mujoco_run(1e-5);
  mjData* half = mujoco_run(2e-5);
  // Initial states agree?
  mjData* d0 = mj_makeData(m);
  set_mujoco_rates(m, d0, r);
  double dv0 = 0.0;
  for (std::size_t i = 0; i < map.size(); ++i) {
    mjtNum vel[6];
    mj_objectVelocity(m, d0, mjOBJ_BODY, map[i], vel, 0);  // at the body frame's origin, world axes
    const mb::BodyState& s = sc.initial.bodies[i];
    const Vec3 w = s.R_space_body * s.omega_body;
    dv0 = std::max(dv0, (Vec3(vel[0], vel[1], vel[2]) - w).norm());
  }
  const auto [x4, r4] = difference(poinsot::bench::projected_rk4_run(sc, 1e-4), ref, map);
  const auto [x5, r5] = difference(poinsot::bench::projected_rk4_run(sc, 1e-5), ref, map);
  // MuJoCo at 2e-5 against 1e-5: compare two mjData through a poinsot-shaped state.
  mb::State hs = sc.initial;
  for (std::size_t i = 0; i < map.size(); ++i) {
    const int b = map[i];
    hs.bodies[i].x_space = Vec3(half->xipos[3 * b], half->xipos[3 * b + 1], half->xipos[3 * b + 2]);
    hs.bodies[i].R_space_body = mat3(half->xmat + 9 * b);
  }
  const auto [xm, rm] = difference(hs, ref, map);
  std::printf("\n%s: 1 s from the same state (initial angular velocities agree to %.2g rad/s)\n",
              md.name.c_str(), dv0);
  std::printf(
      "  against MuJoCo RK4 dt=1e-5:  poinsot RK4 dt=1e-4: %.3g m, %.3g rad;  dt=1e-5: %.3g m, %.3g rad;"
      "  MuJoCo RK4 dt=2e-5: %.3g m, %.3g rad\n",
      x4, r4, x5, r5, xm, rm);
  mj_deleteData(ref);
  mj_deleteData(half);
  mj_deleteData(d0);
  mj_deleteModel(m);
}

void compare_energy(const Model& md) {
  const long steps = 100000;
  const double dt = 1e-3;
  mjModel* m = load_mujoco(md, mjINT_RK4, dt);
  bool has_free = false;
  for (int j = 0; j < m->njnt; ++j)
    has_free = has_free || m->jnt_type[j] == mjJNT_FREE;
  const Rates r = draw_rates(m);
  const mb::Scenario sc = poinsot_scenario(md, r, has_free);
  std::printf("\n%s: energy over 1e5 steps of dt = 1e-3, max |E - E0| / max(T)\n", md.name.c_str());
  const Vec3 p_start = mb::linear_momentum(sc.system, sc.initial);
  const Vec3 L_start = mb::angular_momentum(sc.system, sc.initial);
  for (const int order : {2, 4}) {
    try {
      const poinsot::bench::RattleDrift drift = poinsot::bench::rattle_drift(sc, order, dt, steps);
      std::printf("  poinsot RATTLE order %d: %.3g (first tenth of the run: %.3g)", order, drift.energy,
                  drift.energy_first_tenth);
      if (md.zero_gravity)
        std::printf("; |dp| %.2g of |p0| %.3g kg m/s, |dL| %.2g of |L0| %.3g kg m2/s", drift.linear_momentum,
                    p_start.norm(), drift.angular_momentum, L_start.norm());
      std::printf("\n");
    } catch (const std::exception& e) {
      std::printf("  poinsot RATTLE order %d: failed: %s\n", order, e.what());
    }
  }
  for (const int integrator : {mjINT_RK4, mjINT_EULER}) {
    m->opt.integrator = integrator;
    mjData* d = mj_makeData(m);
    set_mujoco_rates(m, d, r);
    mj_energyPos(m, d);
    mj_energyVel(m, d);
    const double e0 = d->energy[0] + d->energy[1];
    // The whole system's momenta: the world's subtree (body 0), linear m v_com, angular about the centre of
    // mass.
    const auto momenta = [&] {
      mj_subtreeVel(m, d);
      return std::pair<Vec3, Vec3>{
          m->body_subtreemass[0] * Vec3(d->subtree_linvel[0], d->subtree_linvel[1], d->subtree_linvel[2]),
          Vec3(d->subtree_angmom[0], d->subtree_angmom[1], d->subtree_angmom[2])};
    };
    const auto [p0, L0] = momenta();
    double de = 0.0, tmax = 0.0, dp = 0.0, dL = 0.0, de_first = 0.0;
    for (long k = 0; k < steps; ++k) {
      mj_step(m, d);
      mj_forward(m, d);
      mj_energyPos(m, d);
      mj_energyVel(m, d);
      de = std::max(de, std::abs(d->energy[0] + d->energy[1] - e0));
      tmax = std::max(tmax, d->energy[1]);
      if (k == steps / 10) de_first = de / tmax;
      if (md.zero_gravity) {
        const auto [p, L] = momenta();
        dp = std::max(dp, (p - p0).norm());
        dL = std::max(dL, (L - L0).norm());
      }
    }
    std::printf("  MuJoCo %s: %.3g (first tenth: %.3g)", integrator == mjINT_RK4 ? "RK4" : "Euler", de / tmax,
                de_first);
    if (md.zero_gravity)
      std::printf(
          "; |dp| %.2g of |p0| %.3g kg m/s, |dL| %.2g of |L0| %.3g kg m2/s (about the centre of mass)", dp,
          p0.norm(), dL, L0.norm());
    std::printf("\n");
    mj_deleteData(d);
  }
  mj_deleteModel(m);
}

void BM_Poinsot(benchmark::State& state, Model md, bool rk4) {
  mjModel* m = load_mujoco(md, mjINT_RK4, 1e-3);
  bool has_free = false;
  for (int j = 0; j < m->njnt; ++j)
    has_free = has_free || m->jnt_type[j] == mjJNT_FREE;
  const Rates r = draw_rates(m);
  mj_deleteModel(m);
  // Released again every kRestartSteps, as in the runs of step 3.
  poinsot::bench::time_poinsot_steps(state, poinsot_scenario(md, r, has_free), rk4, kRestartSteps);
}

void BM_Mujoco(benchmark::State& state, Model md, int integrator) {
  mjModel* m = load_mujoco(md, integrator, 1e-3);
  const Rates r = draw_rates(m);
  mjData* d = mj_makeData(m);
  set_mujoco_rates(m, d, r);
  long k = 0;
  for (auto _ : state) {
    mj_step(m, d);
    if (++k % kRestartSteps == 0) {
      mj_resetData(m, d);
      set_mujoco_rates(m, d, r);
    }
  }
  benchmark::DoNotOptimize(d->qpos[0]);
  mj_deleteData(d);
  mj_deleteModel(m);
}

/// MuJoCo's warnings (an unstable step, a near-singular inertia) on stderr, instead of its default handler's
/// MUJOCO_LOG.TXT in the working folder.
void print_mujoco_warning(const char* message) {
  std::fprintf(stderr, "MuJoCo warning: %s\n", message);
}

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  mju_user_warning = print_mujoco_warning;
  const std::vector<Model> all = models();
  for (const Model& md : all) {
    try {
      compare_inertias(md);
      compare_trajectories(md);
      if (!md.passive) compare_energy(md);
    } catch (const std::exception& e) {
      std::printf("%s: %s\n", md.name.c_str(), e.what());
      continue;
    }
    if (md.passive) continue;
    benchmark::RegisterBenchmark(("poinsot_rattle/" + md.name).c_str(), BM_Poinsot, md, false);
    benchmark::RegisterBenchmark(("poinsot_rk4/" + md.name).c_str(), BM_Poinsot, md, true);
    benchmark::RegisterBenchmark(("mujoco_rk4/" + md.name).c_str(), BM_Mujoco, md, int{mjINT_RK4});
    benchmark::RegisterBenchmark(("mujoco_euler/" + md.name).c_str(), BM_Mujoco, md, int{mjINT_EULER});
  }
  std::printf("\n");
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
