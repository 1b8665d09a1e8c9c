#pragma once
/// @file simulation.hpp
/// The simulation driver: runs a model from a state to a final time with a chosen integrator, streams samples
/// at a chosen interval to an observer (no trajectory is held unless the observer keeps it), records the
/// worst relative errors of the invariants, locates the intermediate-axis flips, and stops with
/// ComputationFailed (time, step, cause) on a non-finite state or a failed step.

#include <functional>
#include <vector>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

struct SimulationOptions {
  double t_end = 10.0;       ///< s (> start time)
  double sample_dt = 0.01;   ///< s: the observer sees the state at t0, t0 + sample_dt, ..., and t_end
  bool locate_flips = true;  ///< find the sign changes of the intermediate-axis component of L_body
};

/// Worst relative errors over the samples and steps, against the initial values. A torque-free body under a
/// fixed-step method is advanced one sample interval (or breakpoint interval) at a time
/// (Integrator::advance): its energy error is then taken after every step, the others (from the attitude) at
/// the end of each interval.
struct InvariantErrors {
  double energy_rel_max = 0.0;     ///< max |E − E0| / |E0| (total energy with gravity)
  double L_space_rel_max = 0.0;    ///< max |L − L0| / |L0| (free body only; 0 with a torque)
  double L_norm_rel_max = 0.0;     ///< max ||L| − |L0|| / |L0|
  double orthogonality_max = 0.0;  ///< max ‖RᵀR − I‖_F
};

struct SimulationResult {
  State final_state;
  long long steps = 0;
  long long rejected_steps = 0;
  InvariantErrors errors;
  std::vector<double> flip_times;  ///< s, sign changes of the intermediate principal component of L_body
  double wall_time_s = 0.0;
  bool interrupted = false;  ///< the observer asked to stop (e.g. on SIGINT)
};

/// Receives each sample; returns false to stop the run early (the result is then marked interrupted).
using Observer = std::function<bool(const State& sample)>;

/// Runs the simulation. Throws InvalidInput for bad options and ComputationFailed on a failed step.
SimulationResult simulate(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                          const State& initial, Integrator& integrator, const SimulationOptions& options,
                          const Observer& observer = {});

}  // namespace poinsot::dynamics
