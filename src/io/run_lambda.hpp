#pragma once
// Internal to the io layer: the few lines on Λ (Vallée & Dumitriu 2002) in the report of a run.

#include "poinsot/io/run.hpp"
#include "poinsot/io/scenario.hpp"

namespace poinsot::io::detail {

/// Fills summary.lambda0 and summary.lambda_lines from the initial state of the scenario.
void lambda_report(const Scenario& scenario, RunSummary& summary);

}  // namespace poinsot::io::detail
