#pragma once
/// @file collocation_solution.hpp (internal)
/// What a solved Hermite–Simpson NLP (collocation_nlp.hpp, one phase or several) says: the interpolants of
/// an interval, the mesh error of every interval (direct_collocation.hpp defines ε_k) and the DirectSolution
/// with the costates read from the defect multipliers.
#include <algorithm>
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

/// How far the optimum of a refined mesh may rise above the previous mesh's, relative to it: the interpolated
/// start is that optimum, and refining moves the cost by about the mesh error (here at most ten times the
/// previous mesh's, and 1e-3). A larger rise is Ipopt leaving for another, worse local optimum (a keep-out
/// slew went from T = 4.3309 s at mesh error 1.5e-7 to 5.7371 s on the next mesh); such a solution is
/// refused, and Ipopt restarted from the same start with settings that keep it (restart_settings).
inline double allowed_cost_rise(const DirectSolution& previous) {
  return std::max(10.0 * previous.max_mesh_error, 1e-3);
}

}  // namespace poinsot::optimal::detail
