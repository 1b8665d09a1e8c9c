#pragma once
/// @file multibody_direct.hpp
/// Optimal motions of multibody systems by direct collocation (Hermite–Simpson, separated form; Betts 2010,
/// §4.6) and Ipopt with the exact Hessian, in two independent formulations of the same problem
/// (multibody_problem.hpp):
///
/// - `rotation_matrix`: the multibody layer's own equations in the coordinates (x, R) of every body, mass
///   matrix blockdiag(m I, K ⊗ I), with the joint reactions λ, the orthogonality multipliers Λ and the
///   projection multipliers of the stabilised index-2 form as NLP variables. Every equation is a polynomial
///   of degree ≤ 2 (linear in the accelerations and the multipliers, quadratic constraints), so the
///   derivatives are exact by construction (docs/optimal_control_multibody.md, "Multibody systems").
/// - `minimal`: hinge angles θ and ball-joint quaternions of a tree rooted at the world or at a floating base
///   (its attitude quaternion and angular velocity, the translation eliminated by the centre of mass at
///   rest), with the inverse dynamics of the recursive Newton–Euler algorithm as the path equation M(q) ν̇ +
///   c(q, ν) = B u (no mass matrix is inverted), derivatives exact by forward automatic differentiation of
///   second order.
///
/// Both minimise ∫ Σ u_i² dt at fixed T, or T + ε ∫ Σ u_i² dt with T free (the problem's objective;
/// hermite_simpson_nlp.hpp scales time as t = T τ), from the full initial state to the final state, on N
/// equal intervals, with the problem's rate bounds |q̇_j| ≤ r_j as inequality rows at every collocation point
/// but the first (θ̇ in minimal coordinates; n_a·ω_a − n_b·ω_b with ω = vee(RᵀV), bilinear, in rotation-matrix
/// ones). The naive initial guess is used unless MultibodyOptions::warm_start is given: every state
/// coordinate interpolated linearly between the two boundary states, every other variable zero; but in
/// rotation-matrix coordinates, where some body turns by more than 2π/3 (the straight line between two
/// rotations is not one, and across a half-turn it has rank 1 halfway), each body turned along its geodesic
/// R(s) = R₀ exp(s log(R₀ᵀR_f)) at s = t/T, its position, velocity and body rates interpolated linearly.
/// Where Ipopt fails it is restarted from the same guess with other settings, twice
/// (MultibodyOptimum::nlp_restarts). A result is `converged` only when Ipopt reports success and no body
/// turns by more than π/2 between neighbouring collocation points (an unresolved mesh, or in R-coordinates a
/// spurious half-turn jump of the stabilised form: docs/optimal_control_multibody.md, "The falling cat");
/// otherwise `status` says what happened and the last iterate is kept, never presented as an optimum.
#include <functional>
#include <string>
#include <vector>

#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/state.hpp"
#include "poinsot/optimal/direct_progress.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal {

enum class MultibodyCoordinates { rotation_matrix, minimal };

struct MultibodyOptimum;

struct MultibodyOptions {
  MultibodyCoordinates coordinates = MultibodyCoordinates::rotation_matrix;
  double nlp_tolerance = 1e-10;  ///< Ipopt's tol
  int max_nlp_iterations = 500;
  int print_level = 0;
  /// The initial guess: null for the naive one (below), or an optimum of the same problem on any mesh (not
  /// owned; e.g. a coarser mesh's): its states linearly interpolated between its collocation points, its
  /// controls by control_at, every other variable zero. With a free final time (minimum_time) it is read at
  /// the same fraction t/T of its own final time, which is also the guess of T.
  const MultibodyOptimum* warm_start = nullptr;
  /// Rotation-matrix coordinates: c > 0 bounds the stabilising variables S and μ of the stabilised index-2
  /// form by c/h at every point (h = T/N; for c < 0.6 no body can then cross a half-turn inside one interval
  /// without angular velocity, which the unbounded form allows at no cost), and a result whose
  /// stabilisation_step exceeds c/2 is reported as not converged (the bounds would shape it). 0: unbounded.
  double stabilisation_step = 0.0;
  /// MUMPS' scaling of Ipopt's KKT matrix (Ipopt's option mumps_scaling): 77, Ipopt's default, lets MUMPS
  /// choose; 0, none beyond Ipopt's own NLP scaling. Neither is better everywhere
  /// (docs/measurements/optimal_multibody.md, "The cost of the R-coordinate transcription"): in R-coordinates
  /// 0 takes the two-link arm at N = 32 and 64 in 25 Ipopt iterations instead of 61 and 292 and the reaction
  /// wheel in 15 to 17 instead of 32 to 119, but from the straight-line guess between the boundary matrices
  /// the unbounded falling cat takes 7.7 times the CPU time, and at N = 6 it ends 11 of the benchmark's 100
  /// random arm problems on a spurious jump (none with 77). Any of Ipopt's values -2, -1, 0, 1, 3, 4, 7,
  /// 8, 77.
  int mumps_scaling = 77;
  /// Called after every Ipopt iteration (mesh_iteration 1, this problem's intervals, restart 0; the terminal
  /// progress of `poinsot optimize`); empty: not called. It does not change the solution.
  std::function<void(const DirectProgress&)> progress;
};

struct MultibodyOptimum {
  bool converged = false;  ///< Ipopt solved the NLP
  std::string status;      ///< "converged", or Ipopt's status in words
  int nlp_iterations = 0;  ///< Ipopt iterations, of every attempt
  /// Ipopt runs restarted from the same guess with other settings after a failure (at most two: the
  /// monotone barrier, then twice the iterations); a result Ipopt solved but the checks reject is not
  /// restarted.
  int nlp_restarts = 0;
  /// The objective: ∫ Σ u_i² dt (N²·m²·s), or T + ε ∫ Σ u_i² dt (s) for minimum_time (T = time.back()).
  double cost = 0.0;
  double wall_seconds = 0.0;              ///< building and solving the NLP
  std::vector<double> time;               ///< s, every collocation point (nodes and midpoints)
  std::vector<multibody::State> states;   ///< at every point
  std::vector<Eigen::VectorXd> controls;  ///< at every point, actuator order (N·m)
  /// Each body's Λ (body frame, J) and each joint's reaction at every point: in rotation-matrix coordinates
  /// the NLP's own variables (Λ, λ through multibody::joint_loads); in minimal coordinates those of the
  /// continuous equations at the point's state and controls (multibody::exact_multipliers).
  std::vector<multibody::Multipliers> multipliers;
  double max_constraint_error = 0.0;  ///< largest |row| of the NLP's constraints at the last iterate
  /// Rotation-matrix coordinates: the largest step the stabilising variables carry at any point, h|S_kl| of
  /// a body, h|μ| of a joint (MultibodyOptions::stabilisation_step); 0 in minimal coordinates. They vanish on
  /// the continuous problem's solution: a step comparable to a body's turn per interval is the transcription
  /// using them to move the body (docs/optimal_control_multibody.md, "The falling cat").
  double stabilisation_step = 0.0;
};

/// Throws InvalidInput for an invalid problem (validate), for a warm start whose points do not span [0, T]
/// or whose states have another number of bodies, and for `minimal` coordinates unless the system is
/// a tree of hinges and ball joints (each body the higher-indexed body of exactly one joint, its other body
/// the world or a body of lower index, or body 0 a floating base in no joint to the world, then with no
/// gravity and zero initial linear momentum) with only hinge and ball motors, no constant loads besides
/// gravity and no no-twist condition.
MultibodyOptimum solve_multibody(const MultibodyProblem& problem, const MultibodyOptions& options = {});

/// The control at time t (s): the quadratic through the node, midpoint and node values of its interval.
/// Throws InvalidInput for an optimum without points (not from solve_multibody).
Eigen::VectorXd control_at(const MultibodyOptimum& optimum, double t);

/// The re-simulation of an optimum's control history by the multibody projected RK4.
struct MultibodyReplay {
  multibody::State final_state;
  double attitude_error = 0.0;     ///< max over bodies of the angle between R(T) and the target (rad)
  double position_error = 0.0;     ///< max |x(T) − x_f| (m)
  double velocity_error = 0.0;     ///< max over bodies of |v − v_f| (m/s) and |ω − ω_f| (rad/s)
  double max_joint_gap = 0.0;      ///< over every step (m)
  double max_orthogonality = 0.0;  ///< max ‖RᵀR − I‖_F over every step
  /// Max over every step of |P(t) − P(0)| (kg·m/s) and |H(t) − H(0)| (kg·m²/s, about the origin): the
  /// change of the momenta, which a free-floating system with hinge motors only conserves.
  double max_momentum_change = 0.0;
  int steps = 0;
};

/// A free final hinge's body_a (multibody_problem.hpp) is compared up to its turn about the hinge: the axis's
/// direction, the joint point, the angular velocity in space and the velocity.
/// Integrates the initial state over [0, T] (T the optimum's final time, optimum.time.back()) with
/// `steps_per_interval` projected-RK4 steps per collocation interval, the controls held at their value at
/// each step's midpoint (a second-order approximation of the continuous control: the replay's error falls by
/// 4 when the steps are halved).
MultibodyReplay replay_controls(const MultibodyProblem& problem, const MultibodyOptimum& optimum,
                                int steps_per_interval = 64);

}  // namespace poinsot::optimal
