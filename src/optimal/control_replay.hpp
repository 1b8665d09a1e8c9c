#pragma once
/// @file control_replay.hpp (internal)
/// The independent re-simulation of an indirect solution's control history (verification.hpp): the torque
/// replayed open loop through the dynamics layer's DOP853 (quaternion + Euler, rtol = atol = 1e-13), over the
/// whole horizon or over one shooting segment from its node, and the amplification of the open-loop replay.
///
/// The replayed torque: for bang-bang controls the constant torque of each arc with the exact switch times;
/// for smooth controls the torque table of the samples (dynamics::TabulatedTorque: jumps at repeated times,
/// local cubics between them), each of its pieces integrated on its own so that no stage sees the next one.
#include "poinsot/dynamics/state.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal::detail {

/// The replay's DOP853 rtol and atol: the smallest error the replay can be expected to commit per step.
inline constexpr double replay_tolerance = 1e-13;

/// Replays the torque of `s` from `start` (at start.time, s) to t_end (s) through DOP853 with the body's
/// torque-free dynamics plus the replayed torque; returns the state at t_end, with NaN attitude and rate
/// where DOP853 gives up (ComputationFailed: a non-finite start or motion), so that every comparison with it
/// fails.
dynamics::State replay_control(const ReorientationProblem& p, const IndirectSolution& s,
                               dynamics::State start, double t_end);

/// The open-loop replay's amplification: the largest singular value of the state-transition matrix Φ(T, 0)
/// of the motion under the fixed torque history, in the scaled coordinates (δθ, T δω) (rad, both: δθ the
/// body-frame attitude error R → R exp(j(δθ)), δω the rate error). The variational equations
///     δθ̇ = δω − ω × δθ,     J δω̇ = (j(Jω) − j(ω) J) δω
/// (the torque is a function of time only, so it does not enter them) are integrated with ω by
/// Runge–Kutta–Fehlberg 7(8) at rtol = atol = 1e-10, segment by segment from each node's ω (the indirect
/// solution's; t = 0: ω_0), and Φ(T, 0) is the product of the segments' matrices, so the figure belongs to
/// the optimal motion, not to the replay that has drifted away from it. An error δ committed near t = 0
/// reaches the target as ‖Φ‖ δ at most (to first order). NaN when the integration fails or Φ is not finite.
double replay_amplification(const ReorientationProblem& p, const IndirectSolution& s);

}  // namespace poinsot::optimal::detail
