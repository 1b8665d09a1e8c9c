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
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_progress.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

struct DirectSolution;

struct CollocationOptions {
  int initial_intervals = 10;
  double mesh_tolerance = 1e-7;  ///< the largest accepted ε_k (relative)
  int max_mesh_iterations = 10;
  int max_intervals = 4000;
  double nlp_tolerance = 1e-10;  ///< Ipopt's tol (scaled KKT error)
  int max_nlp_iterations = 1000;
  int print_level = 0;  ///< Ipopt's print_level (0 = silent)
  /// How many initial guesses the first mesh is solved from where the guess has an eigenaxis (a final
  /// attitude to reach, other than the start's): the eigenaxis guess with its transverse bump turned about
  /// the eigenaxis by 360°/starts from one to the next (first_mesh_turn). The refinement continues from the
  /// start whose first-mesh optimum is lowest by more than kDistinctFirstMeshOptima (relative) than the
  /// earlier ones, so that starts that reach the same optimum keep the first. A direct method is local: from
  /// a spinning start the first guess can lie in the basin of an optimum several per cent above another one
  /// (measurements/optimal_control.md, "Several starts"). 1: the first guess only.
  int starts = 4;
  /// Called after every Ipopt iteration (a terminal progress line); empty: not called. Not part of the
  /// result.
  std::function<void(const DirectProgress&)> progress;
  /// Called with the solution of every mesh that Ipopt solved and whose mesh error is above mesh_tolerance,
  /// before that mesh is refined; returning a reason stops the refinement there (the solution is returned
  /// with converged false and the status "refinement stopped at mesh error … after N mesh iterations:
  /// <reason>"), std::nullopt refines on. Empty: the refinement runs to mesh_tolerance. The front ends stop
  /// it once the shooting from a mesh verifies the optimum (io::run_optimal).
  std::function<std::optional<std::string>(const DirectSolution&)> accept_mesh;
};

/// How far above its tolerance Ipopt may stop on an NLP where it stalls. On a near-singular KKT system (an
/// unstable motion over many turns, whose phase is a near-null direction) Ipopt's iterates can come within a
/// few times its tolerance and then wander at the level of the linear solver's rounding, never meeting it,
/// along a path that depends on the BLAS. An attempt that fails after an iterate met this factor times its
/// tolerance is run again with the same settings from the same start (the restarts of solve_direct and of
/// the multibody solves), which retraces its path, and is stopped at the first iterate that meets the factor.
/// 100 keeps a KKT error of 1e-8 for the default 1e-10, far below any mesh error that the direct solutions
/// are refined to; what the direct solution seeds (the shooting, the verification) does not rest on it.
inline constexpr double nlp_stall_tolerance_factor = 100.0;

/// The most starts of CollocationOptions::starts.
inline constexpr int kMaxStarts = 64;

/// How much lower (relative) a first-mesh optimum must be than those of the earlier starts for the
/// refinement to continue from it (CollocationOptions::starts): starts that reach the same optimum agree to
/// about Ipopt's tolerance (1e-10 on the scaled KKT error; 1e-8 relative in the cost on Betts' first mesh,
/// whose starts end on either side of a flat optimum), while the distinct local optima measured differ by
/// 0.7 % to 11 % (measurements/optimal_control.md, "Several starts").
inline constexpr double kDistinctFirstMeshOptima = 1e-6;

/// The turn (rad) of the transverse bump about the eigenaxis in the guess of start `start` of `starts`
/// (CollocationOptions::starts): 2π start/starts.
double first_mesh_turn(int start, int starts);

/// One first-mesh solve of CollocationOptions::starts.
struct FirstMeshStart {
  double turn = 0.0;    ///< rad: the guess's transverse bump turned about the eigenaxis (first_mesh_turn)
  bool solved = false;  ///< Ipopt solved the first mesh from this guess
  double cost = 0.0;    ///< the first mesh's optimum (its last iterate's cost when not solved)
  int nlp_iterations = 0;
};

/// A collocated trajectory: samples at the nodes and midpoints (times ascending), costates at the interval
/// centres.
struct DirectSolution {
  bool converged = false;  ///< every NLP solved and the final mesh meets mesh_tolerance
  /// Ipopt solved the NLP whose solution this is (a KKT point of its mesh), even where the mesh error is
  /// still above the tolerance; false when the samples are an iterate Ipopt stopped on.
  bool nlp_solved = false;
  std::string status;        ///< "converged", or what failed (Ipopt's status, mesh error not met)
  double final_time = 0.0;   ///< s
  double cost = 0.0;         ///< the objective (s, N²·m²·s, or s)
  std::vector<double> time;  ///< s
  std::vector<Quat> attitude;
  std::vector<Vec3> omega_body;  ///< rad/s
  /// The control (N·m): the body torque (body frame), or with reaction wheels the wheels' motor torques u_k
  /// (component k for wheel k).
  std::vector<Vec3> torque_body;
  /// With reaction wheels, the wheel momenta h_k (N·m·s) at every sample; empty otherwise.
  std::vector<Vec3> wheel_momentum;
  std::vector<double> node_time;            ///< s, the mesh nodes
  std::vector<double> costate_time;         ///< s, interval centres
  std::vector<Vec3> costate_attitude_body;  ///< p_θ (N·m·s: H_kin = p_θ·ω is dimensionless for min time
                                            ///< in the normalisation H = 1 + λᵀf)
  std::vector<Vec3> costate_omega;          ///< p_ω
  std::vector<double> mesh_error;           ///< ε_k on the final mesh
  /// Pointing constraints (problem.pointing): the NLP multiplier of constraint c's row at every sample,
  /// [c][sample], signed so that it is ≥ 0 where the constraint is active (Ipopt's multiplier of the keep-out
  /// row sᵀRb ≤ cos θ, minus that of the keep-in row) and 0 off the active set; 0 at the first sample of
  /// each phase, where no row is imposed. Units: those of the cost per unit of cosine (it is the change of
  /// the cost when the row's bound moves); a discrete measure, so it scales with the intervals' lengths.
  std::vector<std::vector<double>> pointing_multiplier;
  /// The widening δ (rad) of the cones imposed at the collocation points (θ + δ keep-out, θ − δ keep-in),
  /// so that the control re-simulated between the points meets the cones themselves (solve_direct); 0 when
  /// none was needed.
  double pointing_widening = 0.0;
  /// The relative tightening ε of the wheel-momentum bounds imposed at the collocation points (h̄ (1 − ε)),
  /// so that the re-simulated control meets the bounds themselves (solve_direct); 0 when none was needed.
  double wheel_momentum_margin = 0.0;
  double max_mesh_error = 0.0;
  int mesh_iterations = 0;
  int nlp_iterations = 0;  ///< Ipopt iterations, summed over the mesh iterations
  int nlp_restarts = 0;    ///< Ipopt runs restarted with other settings after a failure (see solve_direct)
  /// Meshes whose NLP solution is the first iterate within nlp_stall_tolerance_factor times nlp_tolerance of
  /// an Ipopt run that stalled above it (see solve_direct).
  int nlp_stalled = 0;
  /// The first mesh's solves from the starts' guesses (CollocationOptions::starts), in order; empty where
  /// only the first guess was tried (starts = 1, or a guess without an eigenaxis). Their Ipopt iterations
  /// are in nlp_iterations.
  std::vector<FirstMeshStart> first_mesh_starts;
  int chosen_start = 0;  ///< the index in first_mesh_starts that the refinement continued from
};

/// Throws InvalidInput (one line naming the field) unless 2 ≤ initial_intervals ≤ max_intervals,
/// max_mesh_iterations ≥ 1, max_nlp_iterations ≥ 1, 1 ≤ starts ≤ kMaxStarts and both tolerances are finite
/// and positive.
void validate(const CollocationOptions& options);

/// Solves `problem` by collocation. Throws InvalidInput for an invalid problem or options; a solver failure
/// is reported in `converged`/`status` with the best iterate kept.
///
/// The first mesh is solved from CollocationOptions::starts guesses (each with the restarts below), and the
/// refinement continues from the lowest optimum among them (first_mesh_starts, chosen_start); where none
/// was solved, from the first start's last iterate, as with one guess.
///
/// Where Ipopt fails on a mesh it is restarted from the same start (the guess, or the previous mesh's
/// solution interpolated) with other settings before the method gives up: first the monotone barrier from
/// μ = 1e-4 with the start kept where it is (bound_push 1e-9: the start is near a solution, the default
/// μ = 0.1 and push 1e-2 move it away), then the adaptive barrier with the same start options and twice the
/// iterations. An attempt that fails after an iterate came within nlp_stall_tolerance_factor times Ipopt's
/// tolerance (Ipopt
/// stalled at the level of its linear solver's rounding, as on the tumbling racket's first mesh) is run once
/// more with the same settings from the same start, which retraces its path, and is stopped at the first
/// such iterate (`nlp_stalled` counts such meshes). When every attempt fails on a refined mesh, the previous
/// mesh's solution (Ipopt solved it: `nlp_solved`) is the result, and the status says what failed.
DirectSolution solve_direct(const ReorientationProblem& problem, const CollocationOptions& options = {});

/// Continues the mesh refinement of `previous` (a solve_direct result for the same problem: its mesh and
/// samples start the NLP, ν = 0) under `options` (typically a smaller mesh_tolerance); the iteration counts
/// add to the previous ones. Throws InvalidInput as solve_direct, or when `previous` has no mesh.
DirectSolution continue_direct(const ReorientationProblem& problem, const DirectSolution& previous,
                               const CollocationOptions& options);

/// Whether a pointing constraint is active on `direct` (a solution of `problem`): "the keep_out \"sun\" cone
/// is active (...)" for the first constraint whose smallest margin over the samples, beyond the widening of
/// the cones, is below 1e-6 rad (an interior-point solution keeps an inactive constraint's margin orders of
/// magnitude above that, and an active one at the widened edge to its tolerance); empty when none is.
std::string active_pointing_constraint(const ReorientationProblem& problem, const DirectSolution& direct);

}  // namespace poinsot::optimal
