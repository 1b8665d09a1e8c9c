#pragma once
// Internal to the io layer: the few lines on Λ (Vallée & Dumitriu 2002) in the report of a run, from the
// analysis layer's LambdaTracker (Λ = (j(ω)² + j(ω̇)) K along the samples, paper eq. 3.2).

#include <string>
#include <vector>

#include "poinsot/analysis/lambda_tracker.hpp"

namespace poinsot::io::detail {

/// A few report lines on Λ over a run: the initial eigenvalues, how they varied (constant for an axisymmetric
/// free body, by the paper's theorem; not for others), tr Λ + 2T, the largest eigenvalue (≤ 0: −Λ is positive
/// semi-definite), the closed form for axisymmetric bodies, and the constraint stress ∫σ dv = −R Λ Rᵀ at t0.
std::vector<std::string> lambda_lines(const analysis::LambdaProperties& p);

}  // namespace poinsot::io::detail
