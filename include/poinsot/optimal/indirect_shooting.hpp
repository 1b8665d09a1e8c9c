#pragma once
/// @file indirect_shooting.hpp
/// The indirect method: Pontryagin's minimum principle in the coordinates of Vallée & Dumitriu, the rotation
/// matrix R (RᵀR = I, body → space) and the body angular velocity ω, solved by shooting with Newton's method
/// from the costates of the direct solution (docs/optimal_control_theory.md derives every equation).
///
/// Hamiltonian (minimum principle, costates P ∈ ℝ³ˣ³ of R and p_ω of ω):
///     H = L(u) + ⟨P, R j(ω)⟩ + p_ωᵀ J⁻¹ (u − ω × Jω),   L = 0, ‖u‖², 1 + ε‖u‖² (per objective; for minimum
///     time the constant 1 is included, so H ≡ 0 on a free-final-time extremal, i.e. λᵀf ≡ −1).
/// ⟨P, R j(ω)⟩ = p_θᵀω with the body attitude costate p_θ = vee(RᵀP − PᵀR); the symmetric part of RᵀP is the
/// gauge left free by the orthogonality constraint and does not enter H.
/// Costate equations: Ṗ = −∂H/∂R = P j(ω) (so R p_θ, the space-frame attitude costate, is constant);
/// ṗ_ω = −p_θ + (j(ω)J − j(Jω))ᵀ J⁻¹ p_ω. Switching function σ = J⁻¹ p_ω; the minimising control is
/// u_i = −u_max,i sign σ_i (per-axis, minimum time), u = −ū σ/‖σ‖ (norm bound, minimum time), or the
/// projection of −σ/2 (energy), −σ/(2ε) (regularised) onto the bounds.
/// Boundary conditions: R(T) = R_f (3 equations: vee(R_fᵀR − RᵀR_f)/2 = 0), ω(T) = ω_f, and for a free final
/// time the transversality condition H(T) = 0 (H is autonomous, hence constant). With a free final
/// attitude the attitude conditions are replaced by p_θ(T) = 0.
///
/// Bang-bang controls (per-axis bounds, minimum time): the switching structure (the initial sign of each u_i
/// and the order of its sign changes) is read from the direct solution's torques, and the switching times
/// are unknowns of the Newton iteration with the conditions σ_i(t_s) = 0, so the switches are exact.
/// With a free final attitude p_θ ≡ 0 (R p_θ constant, p_θ(T) = 0) is imposed, not solved for.
/// Shooting: over M segments (ShootingOptions::shooting_nodes; M = 1 is single
/// shooting), each split at the switches inside it and integrated by Runge–Kutta–Fehlberg 7(8) at
/// rtol = atol = integration_tolerance; at an interior node the attitude is three coordinates on SO(3) about
/// the guess, R = R̄ exp(j(δ)), and the attitude costate the body vector p_θ (gauge P = ½ R j(p_θ)), so that
/// RᵀR = I holds by construction; continuity of (R, ω, p_θ, p_ω) is imposed at each node. The Jacobian is by
/// central differences, block sparse (a node's columns re-integrate its own segment only), factorised by
/// Eigen's SparseLU; the Newton step is damped by a backtracking line search on the residual's max norm
/// (where it does not halve the residual, rank-revealing steps, singular values below 1e-8, 1e-10 and 1e-12
/// of the largest left out, are tried beside it and the best one kept). When Newton stalls within 100× the
/// tolerance it is resumed with a tenfold tighter integration; a residual that then still stalls within 10×
/// the tolerance is the round-off floor of the residual and is accepted as converged (the status says so).
/// Norm bound, minimum time: where the direct solution's torque turns by more than 90° between consecutive
/// saturated samples, σ passes through 0 and u = −ū σ/‖σ‖ reverses (the eigenaxis slew of a sphere at T/2).
/// Each such reversal time is an unknown with the condition σ(t_k)·ŝ = 0, ŝ the direction of σ at the start
/// of the arc ending there; on each arc the control is continued through σ = 0 without flipping, so the
/// conditions are smooth. This assumes σ turns by less than 90° along an arc (exact for a sphere). The output
/// samples of a norm-bound torque are refined where it turns fast (σ passing near 0), those of a smooth
/// torque (the other objectives, or one held on a boundary or singular arc) where it curves. Active rate
/// bounds and singular arcs (|u_i| strictly inside its bound over a stretch of the direct solution: σ_i ≡ 0,
/// u_i from σ̈_i = 0), for minimum time with per-axis bounds: boundary and singular arcs with their entry and
/// exit times as unknowns (arc_shooting.hpp, single shooting; under the other objectives and bounds an active
/// rate bound is reported "not applied").
#include <functional>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

struct ShootingOptions {
  double tolerance = 1e-12;  ///< on the scaled residual (max norm)
  int max_iterations = 40;
  double integration_tolerance = 1e-13;  ///< RKF78 rtol and atol
  /// Output samples on each arc (ends included), before those of a smooth or norm-bound torque are refined.
  int samples_per_arc = 64;
  /// M, the number of shooting segments (1 … 1000; nodes at mT/M, each moved by less than half a segment to
  /// keep a quarter segment from the guessed switches and reversals): 1 is single shooting; with M > 1 the
  /// state and costates at the M − 1 interior nodes are unknowns too, started from the direct solution, and
  /// the continuity of (R, ω, p_θ, p_ω) at each node is a Newton equation (multiple shooting).
  int shooting_nodes = 1;
  /// Called after every Newton iteration with the scaled residual's max norm (the terminal progress of
  /// `poinsot optimize`); empty: not called. It does not change the solution.
  std::function<void(double residual)> on_newton_iteration;
};

/// A time interval on which the torque is constant (bang-bang solutions).
struct ControlArc {
  double t_begin = 0.0, t_end = 0.0;  ///< s
  Vec3 torque_body = Vec3::Zero();    ///< N·m
};

/// A boundary arc of an active rate bound: ω_axis = side · rate_max on [t_entry, t_exit] (s).
struct RateBoundArc {
  int axis = 0;       ///< body axis 0, 1, 2
  double side = 1.0;  ///< +1: the upper bound, −1: the lower one
  double t_entry = 0.0, t_exit = 0.0;
};

/// A singular arc: σ_axis ≡ 0 on [t_entry, t_exit] (s), u_axis inside its bound, fixed by σ̈_axis = 0.
struct SingularArc {
  int axis = 0;  ///< body axis 0, 1, 2
  double t_entry = 0.0, t_exit = 0.0;
};

struct IndirectSolution {
  bool converged = false;
  std::string status;  ///< "converged" or what failed
  bool bang_bang = false;
  double final_time = 0.0;  ///< s
  double cost = 0.0;
  double residual = 0.0;  ///< scaled shooting residual (max norm)
  int iterations = 0;
  Vec3 costate_attitude_initial = Vec3::Zero();  ///< p_θ(0)
  Vec3 costate_omega_initial = Vec3::Zero();     ///< p_ω(0)
  std::vector<double> switch_times;              ///< s, ascending (bang-bang)
  std::vector<int> switch_axes;                  ///< body axis 0, 1, 2 of each switch; −1: a reversal
  std::vector<ControlArc> arcs;                  ///< bang-bang arcs, in order

  // Samples (arc ends included, so each switch appears twice, once per side).
  std::vector<double> time;
  std::vector<Mat3> attitude;               ///< R (body → space)
  std::vector<Vec3> omega_body;             ///< rad/s
  std::vector<Vec3> torque_body;            ///< N·m
  std::vector<Mat3> costate_attitude;       ///< P
  std::vector<Vec3> costate_attitude_body;  ///< p_θ = vee(RᵀP − PᵀR)
  std::vector<Vec3> costate_omega;          ///< p_ω
  std::vector<Vec3> switching_function;     ///< σ = J⁻¹ p_ω
  std::vector<double> hamiltonian;          ///< H (0 on a free-time extremal)
  /// Active rate bounds: the boundary arcs, and at each sample the multipliers μ_k ≥ 0 of the adjoined
  /// constraints s_k ω_k − r ≤ 0 (units of ṗ_ω; 0 off the arcs). Empty where no rate bound is active.
  std::vector<RateBoundArc> rate_bound_arcs;
  std::vector<Vec3> rate_bound_multiplier;
  /// Singular arcs (per-axis minimum time), in order of entry; empty where the control is bang-bang.
  std::vector<SingularArc> singular_arcs;

  // Multiple shooting: the interior nodes t_1 … t_{M−1} and the state there, the Newton unknowns that start
  // the segments after the first (empty for single shooting). At convergence the end of segment m − 1 meets
  // node m to the shooting's tolerance; the verification replays each segment from its node.
  std::vector<double> node_time;      ///< s, ascending in (0, T)
  std::vector<Mat3> node_attitude;    ///< R at each node (body → space)
  std::vector<Vec3> node_omega_body;  ///< rad/s
};

/// Shoots from the direct solution's costates (and, for M > 1, its states at the nodes, or the forward
/// re-seeding where its residual is smaller: the nodes integrated from the exact initial state with the
/// switching vector carried through the space frame, λ = R σ fitted to the direct estimates; when Newton has
/// not converged after 10 iterations, re-seeded that way from the iterate's own nodes every 3 iterations,
/// the best iterate kept; docs/optimal_control_theory.md, section 3). Throws InvalidInput
/// for an invalid problem, a direct solution without costates, or shooting_nodes outside 1 … 1000; failures
/// are reported in converged/status with the last iterate.
IndirectSolution solve_indirect(const ReorientationProblem& problem, const DirectSolution& direct,
                                const ShootingOptions& options = {});

/// The control minimising H for the costate p_ω (see above; per-axis minimum time takes sign(0) = +).
Vec3 minimising_control(const ReorientationProblem& problem, const Vec3& costate_omega);

}  // namespace poinsot::optimal
