#pragma once
/// @file collocation_solution.hpp (internal)
/// What a solved Hermite–Simpson NLP (collocation_nlp.hpp, one phase or several) says: the interpolants of
/// an interval, the mesh error of every interval (direct_collocation.hpp defines ε_k) and the DirectSolution
/// with the costates read from the defect multipliers.
#include <vector>

#include "collocation_nlp.hpp"
#include "poinsot/optimal/direct_collocation.hpp"

namespace poinsot::optimal::detail {

/// The interpolants of one interval at s ∈ [0, 1]: state (cubic Hermite), its time derivative, and the
/// controls (quadratic through s = 0, ½, 1).
struct IntervalSample {
  Vec7 x, xdot;
  Vec4 v;
};

IntervalSample sample_interval(const CollocationNlp& nlp, const std::vector<double>& z, int k, double s);

/// ε_k for every interval (direct_collocation.hpp).
std::vector<double> mesh_errors(const CollocationNlp& nlp, const std::vector<double>& z);

/// The samples at every point, the nodes, the costates at the interval centres (from the Simpson-defect
/// multipliers y, when given) and the mesh errors. `converged` and `status` are left to the caller.
DirectSolution extract_solution(const CollocationNlp& nlp, const std::vector<double>& z,
                                const std::vector<double>& y);

}  // namespace poinsot::optimal::detail
