#pragma once
/// @file optimal_wheel_output.hpp (internal)
/// How `poinsot optimize` reports reaction wheels (optimal_run.hpp): the report's lines, the columns of
/// trajectory.csv and control.csv, and summary.json's "reaction_wheels".
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "poinsot/io/run/optimal_run.hpp"

namespace poinsot::io::detail {

/// The report's description of the wheels (after the bounds) and, when the direct control was re-simulated,
/// what that re-simulation measured: peak and final wheel momenta, the bounds' largest relative excess, the
/// drift of the total angular momentum. Empty without wheels.
std::string wheel_lines(const OptimalRun& run);

/// The control columns: "u1,u2,u3" (wheel motor torques, N·m) with wheels, "ux,uy,uz" (body torque)
/// without; the wheel-momentum columns of trajectory.csv: ",h1,h2,h3" (N·m·s) with wheels, "" without.
std::string control_columns(const optimal::ReorientationProblem& problem);
std::string wheel_momentum_columns(const optimal::ReorientationProblem& problem);

/// ",h1,h2,h3" of sample k of a direct solution with wheels (N·m·s), "" without wheels.
std::string wheel_momentum_values(const optimal::DirectSolution& direct, std::size_t k);

/// Whether a direct solution's re-simulation `replay` meets every finite wheel-momentum bound of `problem` to
/// wheel_momentum_replay_tolerance (true without bounds): a condition of "converged (direct …)".
bool wheel_bounds_held(const optimal::ReorientationProblem& problem, const optimal::DirectReplay& replay);

/// summary.json's "reaction_wheels" (null without wheels): axes (rows), spin inertias, bounds, the initial,
/// final and peak momenta, the tightening of the bounds at the collocation points, the replay's excess and
/// the drift of L.
nlohmann::ordered_json wheels_json(const OptimalRun& run);

}  // namespace poinsot::io::detail
