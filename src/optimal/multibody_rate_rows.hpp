#pragma once
/// @file multibody_rate_rows.hpp (internal)
/// The hinge rates q̇ of a problem's rate bounds (multibody_problem.hpp, RateBound) as functions of one
/// collocation point's variables, one row per bound, for PathInequalityNlp:
///
/// - minimal coordinates: q̇ = ±θ̇_i, the rate of the link i hung from the hinge (linear);
/// - rotation-matrix coordinates: q̇ = n_a·ω_a − n_b·ω_b with ω = vee(½(M − Mᵀ)), M = RᵀV (= j(ω) where the
///   point's rows hold RᵀR = I and RᵀV + VᵀR = 0), and n_a, n_b the hinge axis in each body's frame (R_a n_a
///   = R_b n_b on the joint): bilinear in R and V, so the rows keep the transcription's degree ≤ 2.
///
/// In rotation-matrix coordinates the rows of the problem's no-twist conditions (NoTwist: s·vee(M − Mᵀ),
/// M = Cᵀ R_aᵀ R_b, bilinear in R_a and R_b) follow the rate rows, one per condition, held at 0.
#include "multibody_minimal_model.hpp"
#include "multibody_rotation_model.hpp"
#include "poinsot/optimal/multibody_problem.hpp"
#include "point_functions.hpp"

namespace poinsot::optimal::detail {

/// Minimal coordinates: ±θ̇ of the joint's higher-indexed body (multibody_minimal_model.hpp).
QuadraticFunctions minimal_rate_rows(const MultibodyProblem& problem, const MultibodyMinimalModel& model);
QuadraticFunctions rotation_rate_rows(const MultibodyProblem& problem, const MultibodyRotationModel& model);

}  // namespace poinsot::optimal::detail
