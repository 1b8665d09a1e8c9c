#pragma once
/// @file direct_collocation.hpp
/// The direct method: the Hermite–Simpson transcription (separated form; Betts, Practical Methods for
/// Optimal Control, 2nd ed., §4.6) of a ReorientationProblem, solved by Ipopt with exact sparse first and
/// second derivatives (the dynamics are quadratic polynomials, so the Hessian of the Lagrangian is exact and
/// cheap), with mesh refinement driven by the error between the nodes.
///
/// States: the unit quaternion q (body → space) and ω (body frame), with ‖q‖ = 1 imposed at every node and
/// midpoint through an algebraic variable ν in q̇ = ½ q ⊗ (0, ω) + ν q (no Euler angles, no singularity).
///
/// Mesh error (Betts §4.7.1): on interval k the state is the cubic Hermite interpolant of (x, f) at the
/// nodes and the control the quadratic through node, midpoint, node; the error is
/// ε_k = max_i ∫_k |ẋ_i − f_i(x, u)| dt / (1 + max_t |x_i|), by 5-point Gauss–Legendre quadrature. Intervals
/// with ε_k > mesh_tolerance are split (into 2 to 5 pieces by the h⁴ law) and the NLP is solved again from
/// the interpolated previous solution, until max ε_k ≤ mesh_tolerance or the limits are reached.
///
/// Costates: λ(t_k + h_k/2) ≈ −y_{D,k}, the multipliers of the Simpson defects (the NLP Lagrangian is f +
/// yᵀg; minimum principle H = L + λᵀf). The body attitude costate is p_θ = ½ M(q)ᵀ λ_q (so that λ_qᵀq̇ =
/// p_θᵀω), p_ω = λ_ω.
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

struct CollocationOptions {
  int initial_intervals = 10;
  double mesh_tolerance = 1e-7;  ///< the largest accepted ε_k (relative)
  int max_mesh_iterations = 10;
  int max_intervals = 4000;
  double nlp_tolerance = 1e-10;  ///< Ipopt's tol (scaled KKT error)
  int max_nlp_iterations = 1000;
  int print_level = 0;  ///< Ipopt's print_level (0 = silent)
};

/// A collocated trajectory: samples at the nodes and midpoints (times ascending), costates at the interval
/// centres.
struct DirectSolution {
  bool converged = false;    ///< every NLP solved and the final mesh meets mesh_tolerance
  std::string status;        ///< "converged", or what failed (Ipopt's status, mesh error not met)
  double final_time = 0.0;   ///< s
  double cost = 0.0;         ///< the objective (s, N²·m²·s, or s)
  std::vector<double> time;  ///< s
  std::vector<Quat> attitude;
  std::vector<Vec3> omega_body;             ///< rad/s
  std::vector<Vec3> torque_body;            ///< N·m
  std::vector<double> node_time;            ///< s, the mesh nodes
  std::vector<double> costate_time;         ///< s, interval centres
  std::vector<Vec3> costate_attitude_body;  ///< p_θ (N·m·s: H_kin = p_θ·ω is dimensionless for min time
                                            ///< in the normalisation H = 1 + λᵀf)
  std::vector<Vec3> costate_omega;          ///< p_ω
  std::vector<double> mesh_error;           ///< ε_k on the final mesh
  double max_mesh_error = 0.0;
  int mesh_iterations = 0;
  int nlp_iterations = 0;  ///< Ipopt iterations, summed over the mesh iterations
};

/// Throws InvalidInput (one line naming the field) unless 2 ≤ initial_intervals ≤ max_intervals,
/// max_mesh_iterations ≥ 1, max_nlp_iterations ≥ 1 and both tolerances are finite and positive.
void validate(const CollocationOptions& options);

/// Solves `problem` by collocation. Throws InvalidInput for an invalid problem or options; a solver failure
/// is reported in `converged`/`status` with the best iterate kept.
DirectSolution solve_direct(const ReorientationProblem& problem, const CollocationOptions& options = {});

}  // namespace poinsot::optimal
