#pragma once
/// @file optimal_pointing_output.hpp (internal)
/// How `poinsot optimize` reports pointing constraints (optimal_run.hpp): the report's margin lines, the
/// angle columns of trajectory.csv and summary.json's "pointing" array.
#include <cstddef>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "poinsot/io/run/optimal_run.hpp"

namespace poinsot::io::detail {

/// "TITLE: keep_out "sun" smallest margin m rad at t = … s; …\n", one entry per cone of `problem`.
std::string pointing_lines(std::string_view title, const optimal::ReorientationProblem& problem,
                           const optimal::PointingMargins& margins);

/// The trajectory.csv column of cone `index`: angle_keep_out_1, angle_keep_in_2, ... (rad), numbered per kind
/// in the file's order as the scenario keys are.
std::string pointing_column(const optimal::ReorientationProblem& problem, std::size_t index);

/// summary.json's "pointing": per cone its name, kind, column, vectors, half-angle (rad), the direct
/// optimum's widening and largest multiplier, and the smallest margin with its time on the direct
/// re-simulation and along the verified indirect solution (null where not run).
nlohmann::ordered_json pointing_json(const OptimalRun& run);

}  // namespace poinsot::io::detail
