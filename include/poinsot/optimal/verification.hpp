#pragma once
/// @file verification.hpp
/// The checks every optimal solution carries: the necessary conditions of the minimum principle along the
/// indirect solution, the agreement of the direct and indirect optima, and an independent re-simulation of
/// the control history through the dynamics layer's DOP853 (quaternion + Euler, rtol = atol = 1e-13).
/// A solution is reported as optimal only when every check passes; otherwise `failures` says which failed.
/// The direct solution must be one Ipopt solved (`converged` or `nlp_solved`); its mesh error may be above
/// the mesh tolerance, the indirect solution being checked on its own and the costs' agreement bounding it.
///
/// The re-simulation is done twice: open loop from t = 0 to T, and, with M > 1 shooting segments, split at
/// the nodes (each segment from its node's state to the next node's, the last to the target). Beside them the
/// open loop's amplification A = ‖Φ(T, 0)‖ (the state-transition matrix of the motion under the fixed
/// torque) says how much its early errors grow by T. With M = 1 the open-loop replay is checked. With M > 1
/// the split replay is checked, and the open-loop one too unless the split one passes and A times the split
/// replay's largest error (its local errors, at least the replay's tolerance 1e-13) exceeds the threshold:
/// then no replay with those errors could reach the target to the threshold open loop, whatever the
/// solution (an unstable motion: the racket's intermediate-axis spin over λT = 26.6 has A = 5.8e11), and
/// its errors are reported, not checked. Stable optima (A of order 1 to 1e3) keep the open-loop check.
#include <string>
#include <vector>

#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

/// The thresholds of the checks, each justified by the error of the method it checks.
struct VerificationTolerances {
  double hamiltonian = 1e-8;  ///< max |H − H̄| (and |H̄| for free T): shooting converged to 1e-12, RKF78 1e-13
  double control = 1e-9;  ///< H(u) − min H over the admissible set, relative to max ‖σ‖‖u*‖ (solution)
  double costate = 1e-9;               ///< drift of the space attitude costate R p_θ, relative
  double orthogonality = 1e-10;        ///< ‖RᵀR − I‖_F along the indirect solution
  double resimulated_attitude = 1e-9;  ///< rad, bang-bang controls (exact switch times)
  double resimulated_attitude_smooth =
      1e-6;  ///< rad, smooth controls replayed from their samples (local cubic)
  /// Relative difference of the costs: the direct mesh blurs the switches (6.5e-5 for Betts at a mesh error
  /// of 1e-5), while another extremal (the eigenaxis manoeuvre: 20 % for Betts) is far above it.
  double direct_indirect = 1e-3;
  /// Torque and rate bounds along the indirect samples, relative: RKF78 at 1e-13 holds ω_k on a boundary
  /// arc to about 1e-11 relative, and u is exactly at its bounds on bang arcs.
  double admissibility = 1e-9;
};

struct VerificationReport {
  bool passed = false;
  std::vector<std::string> failures;   ///< one line per failed check
  double hamiltonian_mean = 0.0;       ///< H̄ (0 for free final time)
  double hamiltonian_deviation = 0.0;  ///< max |H − H̄|
  double control_gap = 0.0;            ///< max relative H(u) − min_v H(v)
  double control_gap_time = 0.0;       ///< s, the sample of the largest gap
  int control_gap_axis = -1;  ///< per-axis bounds: the axis of the largest term of that gap; −1 otherwise
  /// The largest gap exceeds its tolerance where the other two rates ride their bound (boundary arcs of both)
  /// about principal axes: there σ = σ_i e_i, u_i first enters the fourth derivative of σ_i, a singular arc
  /// of u_i is of order two, and an extremal with finitely many switches of u_i cannot be its chattering
  /// approach.
  bool control_gap_where_order_two = false;
  int switching_sign_violations = 0;  ///< samples with u_i σ_i > 0 where |σ_i| is not negligible
  double costate_drift = 0.0;  ///< max ‖R p_θ − R_0 p_θ(0)‖ / max(‖p_θ(0)‖, max ‖p_ω‖/T)
  double orthogonality = 0.0;  ///< max ‖RᵀR − I‖_F
  double lambda_torque_error = 0.0;  ///< max ‖vee(Λ − Λᵀ) − u‖ / ū: the paper's Λ carries the torque
  double resimulated_attitude_error = 0.0;  ///< rad, angle between the re-simulated R(T) and R_f (free
                                            ///< final attitude: the indirect solution's R(T))
  double resimulated_rate_error = 0.0;      ///< rad/s, ‖ω(T) − ω_f‖
  /// ‖Φ(T, 0)‖₂ of the open-loop replay in (δθ, T δω): how much an error early in the replay grows by T.
  double replay_amplification = 0.0;
  /// False where M > 1, the split replay below passes, and replay_amplification × its largest error (at
  /// least 1e-13, the replay's tolerance) exceeds the threshold: no replay with those local errors can reach
  /// the target to the threshold open loop, so the open-loop errors above are reported and not checked.
  /// The replay split at the nodes is checked whenever M > 1.
  bool open_loop_replay_checked = true;
  int replay_segments = 1;  ///< M: the segments of the split replay (1: it is the open-loop replay)
  /// The replay split at the shooting nodes: each segment replayed from its node's state (the indirect
  /// solution's), largest over the segments of the angle to the next node's attitude (the last segment: to
  /// the target, as above) in rad, and of the rate error in rad/s. Equal to the open-loop errors for M = 1.
  double split_replay_attitude_error = 0.0;
  double split_replay_rate_error = 0.0;
  int split_replay_worst_segment = 1;       ///< 1 … M, the segment of the largest attitude error
  double direct_indirect_difference = 0.0;  ///< |J_direct − J_indirect| / |J_indirect|
  /// Admissibility along the indirect samples: the largest excess of the torque over its bound (relative to
  /// the bound; ≤ 0 when admissible) and of |ω_i| over the rate bound (relative to it; −1 without one).
  double torque_bound_excess = 0.0;
  double rate_bound_excess = -1.0;
  /// Active rate bounds: the smallest multiplier μ_k of the boundary arcs relative to the largest |μ| (must
  /// not be negative: μ ≥ 0 is the minimum principle's sign condition of the state constraint); 0 when none.
  double rate_multiplier_min = 0.0;
  /// Singular arcs: the generalised Legendre–Clebsch (Kelley) condition −∂σ̈_i/∂u_i = −2 σ·(J⁻¹e_i × e_i) ≥ 0
  /// of a minimum along a singular arc of axis i, at its smallest over the samples of the arcs, relative to
  /// 2‖σ‖‖J⁻¹e_i × e_i‖ (a cosine: must not be negative); 0 when there is none.
  double kelley_condition_min = 0.0;
  /// Pointing constraints (the shooting runs only where the direct solution stays clear of every cone): the
  /// smallest margin of each along the indirect solution (rad: its samples, and 64 points between each two on
  /// the cubic Hermite of the quaternion, PointingMargins::lower_along), which must be positive: an extremal
  /// of the problem without the cones that meets them is an extremal of the problem with them.
  PointingMargins pointing;
};

VerificationReport verify(const ReorientationProblem& problem, const DirectSolution& direct,
                          const IndirectSolution& indirect, const VerificationTolerances& tolerances = {});

}  // namespace poinsot::optimal
