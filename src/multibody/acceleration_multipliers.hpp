// The multipliers of the continuous equations from a solved acceleration-level KKT system (private to the
// multibody layer: exact_multipliers() and ProjectedRk4 share it).
#pragma once

#include <vector>

#include <Eigen/Core>

#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/multipliers.hpp"

namespace poinsot::multibody::detail {

/// The right-hand side of the acceleration-level KKT system at `bodies`: `body[i]` = (f_i, τ_i − ω_i × J ω_i)
/// and `joint` = −γ (stacked by the solver's joint offsets), with the applied loads into `loads`. Allocates
/// nothing when the vectors have their sizes already.
void acceleration_rhs(const System& system, const std::vector<BodyState>& bodies, const KktSolver& solver,
                      std::vector<BodyLoads>& loads, std::vector<Vec6>& body, Eigen::VectorXd& joint);

/// From the solution of `[M Gᵀ; G 0][(a, ω̇); −λ] = [(f, τ − ω × Jω); −γ]` at `bodies` (`accelerations[i]` =
/// (a_i, ω̇_i), `minus_lambda` stacked by the solver's joint offsets) and the applied loads there: the joint
/// reactions (constraints.hpp joint_loads) and Λ = sym((j(ω)² + j(ω̇)) K − Φ) (multipliers.hpp).
ExactMultipliers multipliers_from_accelerations(const System& system, const std::vector<BodyState>& bodies,
                                                const std::vector<BodyLoads>& loads,
                                                const std::vector<Vec6>& accelerations,
                                                const Eigen::VectorXd& minus_lambda, const KktSolver& solver);

}  // namespace poinsot::multibody::detail
