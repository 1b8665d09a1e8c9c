#pragma once
/// @file slew_tracking.hpp
/// A planned slew replayed in closed loop on one (dispersed) body: the robustness of an optimal control
/// (the control.csv of `poinsot optimize`) through the ensemble (runner.hpp, docs/ensemble.md "Slew
/// robustness").
///
/// Reference. The planned torque u_ref(t) (N·m, body frame: a dynamics::TabulatedTorque, zero after its
/// last row) is replayed open loop on the nominal body from the nominal initial state; that motion
/// (q_ref(t), ω_ref(t)) is the reference the feedback tracks. It is integrated once, by the same fixed-step
/// RK4 as the samples on the half-step grid (step h/2), so that it is known at every stage time of the
/// samples' steps (t, t + h/2, t + h).
///
/// With SlewSpec::reference (the optimizer's trajectory.csv) the reference is instead the rows' motion,
/// interpolated at the stage times by cubic Hermite polynomials on each interval between rows, with the
/// derivatives q̇ = ½ q ⊗ (0, ω) and ω̇ = J₀⁻¹(u − ω × J₀ ω) of the rows (J₀ the nominal inertia, u the row's
/// torque; an interval's ends take its own side of a switch): error O(Δt⁴) for a row spacing Δt, q
/// normalised (the rows' signs made continuous first). Before the first row and after the last the reference
/// holds the end row.
///
/// Feedback law (body frame):
///     u = sat( u_ref(t) − K_p e_θ − K_d (ω − ω_ref(t)) ),
///     e_θ = 2 sgn(w) v   with (w, v) = q_ref(t)* ⊗ q  (Hamilton product, q body → space),
/// so that q = q_ref ⊗ δq with δq ≈ (1, e_θ/2): e_θ is the rotation vector (rad) that takes the reference
/// attitude to the sample's in the reference body frame, to first order; the sign makes the scalar part ≥ 0
/// (the shorter way round). ω and ω_ref are compared component by component (both body frame, rad/s).
/// K_p in N·m/rad, K_d in N·m·s/rad. sat is the torque limit: none, per axis (|u_i| ≤ u_max,i: each
/// component clipped) or on the norm (‖u‖ ≤ u_max: u scaled down). Every stage of every step evaluates
/// the law at its own (q, ω) (q as the stage has it: |q| = 1 on the motion, and the law is smooth off it,
/// so RK4 keeps its order).
///
/// Dynamics: q̇ = ½ q ⊗ (0, ω), J ω̇ = u − ω × J ω with the sample's full inertia J (body frame, about the
/// centre of mass), integrated by classical RK4 on a grid that has a node at every row time of the control
/// table (every jump and kink of u_ref) and steps h ≤ dt between them, so the torque is smooth within each
/// step and RK4 keeps its fourth order (global error O(h⁴)); q is brought back to unit norm after each step
/// (q ← q (3 − |q|²)/2, exact to rounding while |q|² − 1 is as small as one RK4 step makes it).
///
/// Outputs of one run (runner.hpp names them):
///   pointing_error        rad, the angle between the final attitude R(t_end) and the target R_f
///   rate_error            rad/s, ‖ω(t_end) − ω_f‖
///   peak_torque           N·m, the largest ‖u‖ on the motion: at every grid time t_k (u_ref(t_k⁺)) and at
///                         t_end (u_ref(t_end⁻)), not at RK4's predictor stages
///   peak_feedback_torque  N·m, the largest ‖u − u_ref‖ at the same times (the feedback after saturation;
///                         ~0 on the nominal body: the difference between its RK4 motion on steps h and
///                         the reference's on h/2, O(h⁴), times the gains)
///   peak_wheel_momentum   N·m·s, max over the grid times of ‖h_w‖, h_w(t) = R(t)ᵀ L_space(0) − J ω(t):
///                         the body-frame momentum reaction wheels would hold if the whole torque u came
///                         from them (internal torques conserve the total momentum R (J ω + h_w) = L(0),
///                         wheels at rest at t = 0; the wheels' own inertia is not modelled)
///   meets_requirement     1 when pointing_error ≤ the pointing requirement, else 0 (its mean over the
///                         samples is the share that meets it)
#include <cstdint>
#include <memory>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/tabulated_torque.hpp"

namespace poinsot::ensemble {

/// The torque limit of the feedback law.
enum class SlewTorqueLimit { none, per_axis, norm };
/// "none", "per_axis", "norm".
const char* to_string(SlewTorqueLimit limit);

/// A planned motion given by rows (the trajectory.csv of `poinsot optimize`): times (s, non-decreasing; two
/// rows at one time are a switch of the torque), attitudes (body → space), body rates (rad/s) and torques
/// (N·m, body frame).
struct ReferenceRows {
  std::vector<double> time;
  std::vector<Quat> attitude;
  std::vector<Vec3> omega;
  std::vector<Vec3> torque;
};

/// What a slew-tracking ensemble replays and how.
struct SlewSpec {
  std::shared_ptr<const dynamics::TabulatedTorque> control;  ///< u_ref(t), N·m, body frame
  Mat3 target_attitude = Mat3::Identity();                   ///< R_f, body → space
  Vec3 target_omega = Vec3::Zero();                          ///< ω_f, rad/s, body frame
  double kp = 0.0;                                           ///< N·m/rad
  double kd = 0.0;                                           ///< N·m·s/rad
  SlewTorqueLimit limit = SlewTorqueLimit::none;
  Vec3 torque_max = Vec3::Zero();     ///< N·m: per axis, or the norm bound in every component
  double pointing_requirement = 0.0;  ///< rad
  double t_end = 0.0;                 ///< s, the end of the replay
  double dt = 1e-3;                   ///< s, the largest step
  /// The reference (q_ref, ω_ref) from the plan's own rows instead of the plan replayed on the nominal
  /// body (see the file comment), when not empty.
  ReferenceRows reference;
};

/// One closed-loop replay's outputs (see the file comment).
struct SlewOutcome {
  dynamics::State final_state;
  double pointing_error = 0.0;
  double rate_error = 0.0;
  double peak_torque = 0.0;
  double peak_feedback_torque = 0.0;
  double peak_wheel_momentum = 0.0;
  bool meets_requirement = false;
};

/// The most steps a replay may take (t_end / dt and the table's rows together).
inline constexpr std::int64_t kMaxSlewSteps = 100'000'000;

class SlewTracking {
 public:
  /// Builds the step grid and the reference from the nominal body (inertia about its centre of mass, body
  /// frame, kg·m²) and initial state. Throws InvalidInput, one line naming the field, for: no control,
  /// reference rows of unequal lengths, fewer than two, not finite or not in time order,
  /// negative or non-finite gains, a limit with a torque_max component ≤ 0 (or non-finite), a negative
  /// pointing requirement, t_end or dt ≤ 0, more than kMaxSlewSteps steps, a target that is not a
  /// rotation, a non-finite target rate.
  SlewTracking(SlewSpec spec, const Mat3& nominal_inertia, const dynamics::State& nominal_initial);

  /// The closed-loop replay of one body (inertia about its centre of mass, body frame) from `initial`.
  /// Thread-safe (const, no shared mutable state); the result depends only on its arguments.
  SlewOutcome run(const Mat3& inertia, const dynamics::State& initial) const;

  /// Steps per replay.
  std::int64_t step_count() const { return static_cast<std::int64_t>(step_h_.size()); }
  const SlewSpec& spec() const { return spec_; }
  /// The reference at the ends of the steps: q_ref, ω_ref at t_k (k = 0 … steps).
  Quat reference_attitude(std::int64_t k) const { return q_ref_[2 * static_cast<std::size_t>(k)]; }
  Vec3 reference_omega(std::int64_t k) const { return w_ref_[2 * static_cast<std::size_t>(k)]; }
  double step_time(std::int64_t k) const { return step_t_[static_cast<std::size_t>(k)]; }

 private:
  SlewSpec spec_;
  Quat q_target_;
  std::vector<double> step_t_;  ///< t_k, k = 0 … steps (t_steps = t_end)
  std::vector<double> step_h_;  ///< h_k = t_(k+1) − t_k
  std::vector<Vec3> u_ref_;     ///< 3 per step: u_ref at t_k⁺, t_k + h/2, t_(k+1)⁻
  std::vector<Quat> q_ref_;     ///< 2 steps + 1: at t_k and t_k + h_k/2
  std::vector<Vec3> w_ref_;     ///< likewise
};

}  // namespace poinsot::ensemble
