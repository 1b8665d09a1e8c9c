#pragma once
// The poinsot side of the robot-file benches (robot_files_mujoco.cpp, robot_files_dart.cpp): the reference
// run of the projected RK4, RATTLE's energy and momentum drift over a long run, and the timed step loop. Each
// bench keeps its peer's side.
#include <algorithm>
#include <cmath>

#include <benchmark/benchmark.h>

#include "poinsot/multibody/observables.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/multibody/rattle.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::bench {

/// The state after `duration` s of the projected RK4 at step dt from the scenario's initial state.
inline multibody::State projected_rk4_run(const multibody::Scenario& sc, double dt, double duration = 1.0) {
  multibody::ProjectedRk4 rk4(sc.system, dt);
  multibody::State s = sc.initial;
  const long n = std::lround(duration / dt);
  for (long k = 0; k < n; ++k)
    rk4.step(s);
  return s;
}

/// RATTLE's drift over a run: max |E − E0| / max T over the run and over its first tenth, and the largest
/// changes of the linear momentum (kg·m/s) and of the angular momentum about the origin (kg·m²/s).
struct RattleDrift {
  double energy = 0.0;
  double energy_first_tenth = 0.0;
  double linear_momentum = 0.0;
  double angular_momentum = 0.0;
};

/// `steps` RATTLE steps of dt at `order` (2 or 4) from the scenario's initial state. Throws what RATTLE
/// throws.
inline RattleDrift rattle_drift(const multibody::Scenario& sc, int order, double dt, long steps) {
  multibody::RattleOptions options;
  options.order = order;
  multibody::Rattle rattle(sc.system, dt, options);
  multibody::State s = sc.initial;
  const double e0 = multibody::total_energy(sc.system, s);
  const Vec3 p0 = multibody::linear_momentum(sc.system, s);
  const Vec3 L0 = multibody::angular_momentum(sc.system, s);
  double de = 0.0, tmax = 0.0;
  RattleDrift out;
  for (long k = 0; k < steps; ++k) {
    rattle.step(s);
    de = std::max(de, std::abs(multibody::total_energy(sc.system, s) - e0));
    tmax = std::max(tmax, multibody::kinetic_energy(sc.system, s));
    if (k == steps / 10) out.energy_first_tenth = de / tmax;
    out.linear_momentum =
        std::max(out.linear_momentum, (multibody::linear_momentum(sc.system, s) - p0).norm());
    out.angular_momentum =
        std::max(out.angular_momentum, (multibody::angular_momentum(sc.system, s) - L0).norm());
  }
  out.energy = de / tmax;
  return out;
}

/// The timed loop of a poinsot step (RATTLE, or the projected RK4 with `rk4`) at 1e-3 s, started again from
/// the initial state every `restart_steps` steps.
inline void time_poinsot_steps(benchmark::State& state, const multibody::Scenario& sc, bool rk4,
                               long restart_steps) {
  multibody::State s = sc.initial;
  const auto run = [&](auto& integrator) {
    long k = 0;
    for (auto _ : state) {
      integrator.step(s);
      if (++k % restart_steps == 0) s = sc.initial;
    }
  };
  if (rk4) {
    multibody::ProjectedRk4 integrator(sc.system, 1e-3);
    run(integrator);
  } else {
    multibody::Rattle integrator(sc.system, 1e-3);
    run(integrator);
  }
  benchmark::DoNotOptimize(s.bodies[0].x_space);
}

}  // namespace poinsot::bench
