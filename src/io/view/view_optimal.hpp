#pragma once
/// @file view_optimal.hpp
/// view.html's data for the output folder of `poinsot optimize` (optimal_run.hpp, docs/optimal_control.md):
/// the body turned by the optimal torque, with the torque, its bounds, the target attitude, the control and
/// the switching functions. Internal to the io layer.

#include <string>

#include "poinsot/io/view/view_page.hpp"
#include "view_json.hpp"

namespace poinsot::io::detail {

/// True when `summary` is the summary.json of `poinsot optimize` (it has an `objective`).
bool is_optimal_summary(const ViewJson& summary);

/// The page's data (keys in docs/viewer.md) from `dir`: trajectory.csv (t, q, ω, u, L), control.csv,
/// costates.csv and summary.json, with the body, the bounds and the target from the scenario (--scenario, or
/// the one summary.json names). The frames carry the kinetic energy T = ½ ωᵀJω (J). Throws InvalidInput when
/// the scenario cannot be read or is not an [optimal_control] scenario, when a file or column is missing,
/// and when the frames exceed the page's budget.
ViewJson optimal_view_data(const std::string& dir, const ViewJson& summary, const ViewOptions& options);

}  // namespace poinsot::io::detail
