#pragma once
/// @file multibody_refinement.hpp
/// Mesh refinement for the multibody transcriptions (multibody_direct.hpp): the intervals where the
/// collocated motion departs most from the motion its own control produces are split, by the rule of every
/// collocation mesh (2 to 5 equal pieces, more the further the error is above the tolerance: the error of
/// Hermite–Simpson falls as h⁴), and the problem is solved again from the previous optimum, until every
/// interval's error is below a tolerance.
///
/// The error of interval k (interval_errors): the optimum's state at node k integrated over [t_k, t_k+1] by
/// the multibody projected RK4 (`steps` steps, the control by control_at at each step's midpoint) against
/// the optimum's state at node k + 1: the largest over bodies of the attitude angle (rad), |Δx|/L, h_k |Δω|
/// and h_k |Δv|/L (L the system's length scale, h_k the interval): the transcription's local error, in
/// radians. A free final hinge's body is compared as the other bodies are (its angle is a state like any).
#include <vector>

#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal {

/// The local error of every interval of `optimum` (see the file comment), interval order.
std::vector<double> interval_errors(const MultibodyProblem& problem, const MultibodyOptimum& optimum,
                                    int steps = 16);

/// `problem` with every interval whose error (`errors`, interval order, as interval_errors gives them)
/// exceeds `tolerance` split by the rule of every collocation mesh (2 to 5 equal pieces), its mesh given as
/// fractions (MultibodyProblem::mesh, summing to 1) and its intervals counted again.
MultibodyProblem with_refined_mesh(MultibodyProblem problem, const std::vector<double>& errors,
                                   double tolerance);

struct MultibodyRefinementRound {
  int intervals = 0;
  double max_error = 0.0;  ///< the largest interval error (rad)
  double cost = 0.0;
  int nlp_iterations = 0;
  std::string status;  ///< the solver's
};

struct MultibodyRefinement {
  MultibodyProblem problem;  ///< with the last round's mesh (for replay_controls)
  MultibodyOptimum optimum;  ///< the last round's
  std::vector<MultibodyRefinementRound> rounds;
  bool tolerance_met = false;  ///< the last round converged with every interval error ≤ tolerance
};

/// Solves `problem` on its mesh, then, while some interval's error exceeds `tolerance` (rad, > 0) and fewer
/// than `max_rounds` refinements were made, splits every such interval and solves again from the
/// previous optimum (MultibodyOptions::warm_start is replaced). Stops at a round that does not converge, or
/// before a mesh beyond 2000 intervals. Throws InvalidInput for an invalid problem (validate), tolerance ≤ 0
/// or max_rounds < 0.
MultibodyRefinement refine_multibody(MultibodyProblem problem, MultibodyOptions options, double tolerance,
                                     int max_rounds = 6);

}  // namespace poinsot::optimal
