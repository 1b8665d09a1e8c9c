#pragma once
/// @file direct_replay.hpp
/// The independent re-simulation of a direct (collocation) solution's control: what decides "converged
/// (direct; minimum principle not verified: ...)" where the indirect method cannot verify the optimum
/// (io/run/optimal_run.hpp; docs/optimal_control.md, "Scenario files and `poinsot optimize`").
///
/// The replayed torque is the transcription's own control: on each interval the quadratic through the node,
/// midpoint and node values (Hermite–Simpson; a phase boundary's duplicated node starts the next interval),
/// integrated by the dynamics layer's DOP853 at rtol = atol = 1e-13, interval by interval so that no stage
/// sees the next interval's quadratic, from the problem's initial state to T. The errors at T are compared
/// with the target R_f, ω_f (with a free final attitude, with the direct solution's own R(T)): a collocation
/// solution reaches it to about its mesh error times the motion's amplification, so the replay measures
/// what the mesh error estimates, independently of the transcription.
///
/// With pointing constraints (problem.pointing) the replay is also the dense check of the cones between the
/// collocation points: its steps are at most a sixteenth of an interval, and every constraint's margin
/// (pointing_constraint.hpp) is evaluated at t = 0 and at 8 points of every step (the end of the step and the
/// cubic Hermite interpolant of the quaternion between its ends: PointingMargins::lower_along); `pointing`
/// holds the smallest margin of each and when it is reached. The cones of the problem given are checked (not
/// the widened ones a DirectSolution was solved with).
///
/// With reaction wheels the replay integrates the gyrostat itself: the bus J_b under −A u − ω × A h, with the
/// wheel momenta h(t) = h_0 + ∫ u dt integrated exactly from the quadratic control (not recovered from the
/// conserved total angular momentum, as the transcription does), so the conservation of L is a check.
#include <string>

#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/pointing_constraint.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

struct DirectReplay {
  double attitude_error = 0.0;  ///< rad: angle between the replayed R(T) and the target
  double rate_error = 0.0;      ///< rad/s: ‖ω(T) − ω_f‖
  double final_time = 0.0;      ///< s, the T replayed
  PointingMargins pointing;     ///< the smallest margin of every pointing constraint along the replay
  /// Reaction wheels (zero without): max_t |h_k(t)| (N·m·s) at the ends of the replay's steps (at most a
  /// sixteenth of an interval); max_t,k (|h_k| / h̄_k − 1) over the bounded wheels (≤ 0 where the bounds
  /// hold; −inf without bounds); h(T); and max_t ‖L(t) − L(0)‖ (N·m·s), the drift of the total angular
  /// momentum.
  Vec3 peak_wheel_momentum = Vec3::Zero();
  double wheel_momentum_excess = 0.0;
  Vec3 final_wheel_momentum = Vec3::Zero();
  double momentum_drift = 0.0;
  /// max(attitude_error, T · rate_error) (rad, the scaled coordinates (δθ, T δω) of verification.hpp); NaN
  /// when DOP853 gave up.
  double scaled_error() const;
};

/// The default target of the replay (rad, on scaled_error): the threshold of the verification's smooth
/// replay (VerificationTolerances::resimulated_attitude_smooth).
inline constexpr double direct_replay_tolerance = 1e-6;

/// The largest violation of a pointing constraint accepted on the dense replay (rad): the cones hold to this
/// between the collocation points (solve_direct widens them at the points until they do).
inline constexpr double pointing_replay_tolerance = 1e-9;

/// The largest relative excess of a wheel-momentum bound accepted on the dense replay (|h_k| ≤ h̄_k (1 +
/// this) between the collocation points; solve_direct tightens the bounds at the points until it holds).
inline constexpr double wheel_momentum_replay_tolerance = 1e-6;

/// Replays `direct`'s control (see above). Throws InvalidInput when `direct` has no samples or its samples
/// are not node, midpoint, node, ... in increasing time (a solve_direct or phased result).
DirectReplay replay_direct(const ReorientationProblem& problem, const DirectSolution& direct);

}  // namespace poinsot::optimal
