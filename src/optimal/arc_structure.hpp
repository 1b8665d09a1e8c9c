#pragma once
/// @file arc_structure.hpp (internal)
/// The arcs of a minimum-time control with per-axis torque bounds read from a direct (collocated) solution:
/// the initial sign of each u_i, its sign changes, the boundary arcs of an active rate bound and the singular
/// arcs, in order of time. Seeds the shooting over arcs (arc_shooting.hpp).
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"
#include "switching_structure.hpp"

namespace poinsot::optimal::detail {

/// One event of a control over bang, boundary and singular arcs: a sign change of u_axis, or the entry into
/// or the exit from a boundary arc where ω_axis = side · r, or from a singular arc where σ_axis ≡ 0.
struct ArcEvent {
  enum class Kind { sign_change, entry, exit };
  enum class Arc { boundary, singular };
  Kind kind = Kind::sign_change;
  Arc arc = Arc::boundary;  ///< entry and exit: the kind of arc
  int axis = 0;
  double side = 1.0;        ///< boundary entry and exit: s, the bound ω_axis = s r
  double time = 0.0;        ///< s, the guess
  double sign_after = 1.0;  ///< exit: the sign of u_axis after the exit
  int pair = -1;            ///< entry ↔ exit: the index of the other end of the arc
};

struct ArcStructure {
  Vec3 initial_sign = Vec3::Ones();
  std::vector<ArcEvent> events;  ///< ascending in time
  std::string refused;           ///< non-empty: why the structure is not one this solver handles
  /// The axis of a singular arc that the direct solution starts on (−1: none). An extremal cannot start on
  /// a singular arc (σ_i(0) = σ̇_i(0) = 0 are two conditions for the one unknown of its exit time), so the
  /// direct solution's stands for a bang arc too short for its mesh before the entry: read_arc_structure
  /// with `start_bang_sign` ±1 reads it so.
  int singular_at_start = -1;
  /// The axis of a singular arc that the direct solution ends on (−1: none): for the same count of
  /// conditions no extremal ends on one, and read_arc_structure with `end_bang_sign` ±1 reads it as left
  /// before a bang arc too short for the mesh.
  int singular_at_end = -1;
};

/// The largest |ω_i| of the direct solution, and whether it reaches the bound (to 1e-4 relative).
bool rate_bound_active(const ReorientationProblem& p, const DirectSolution& d, double& peak);

/// Reads the structure from the direct solution: a boundary arc of axis k is a stretch of at least two
/// samples with |ω_k| ≥ (1 − 1e-3) r (none where the rate bound is not active); a singular arc of axis k is a
/// stretch off its boundary arcs, longer than kShortestSingularArc of T, of samples with |u_k| < kInsideBound
/// u_max,k (gaps of up to three samples closer to the bound, the collocation's ringing on such arcs, are
/// bridged); the sign changes of u_k between samples outside its arcs where |u_k| > u_max,k / 2 are switches,
/// except one whose bracket contains an arc of the same axis (the arc takes its place: the sign after the
/// exit is the next saturated sample's). `refused` names a problem that is not minimum time with per-axis
/// bounds, a boundary arc that lasts to the final time, a singular arc of order two (about a principal axis,
/// where u_i does not enter σ̈_i, and sharing no sample with a singular arc of another axis), or a singular
/// arc that overlaps a boundary arc or reaches t = 0 or T (or both). With `start_bang_sign` ±1, a singular
/// arc that reaches t = 0 is read as entered at the direct solution's second sample, after a bang arc of u_i
/// with that sign; with `end_bang_sign` ±1, one that reaches T as left at the last sample but one, before a
/// bang arc of that sign. With `dips`, a shorter stretch inside the bound (one sample or more) is a singular
/// arc too where u_k keeps its sign from the sample before it to the sample after it (a dip towards 0 that
/// returns to the same bound: the collocation's stand-in for a singular arc shorter than its intervals); a
/// dip of one sample is read from the midpoint before it to the midpoint after it.
ArcStructure read_arc_structure(const ReorientationProblem& p, const DirectSolution& d,
                                double shortest_singular_arc = kShortestSingularArc,
                                double start_bang_sign = 0.0, double end_bang_sign = 0.0, bool dips = false);

/// Where the singular torque of a converged shot over `s` leaves its bound, the structure that keeps it
/// inside: `shot` is that extremal (its samples and singular_arcs), `times` its event times in the order of
/// s.events. A singular arc of u_i can only be entered or left where its torque ũ_i from σ̈_i = 0 lies in
/// [−ū_i, ū_i]; an extremal whose ũ_i is outside over [a, b] (relative excess above kSingularTorqueExcess)
/// has a bang arc of u_i = sign(ũ_i) ū_i there instead:
/// - at the arc's entry (a = t_entry), the entry moves to b, after a switch at t_entry where the bang arc
///   before had the other sign;
/// - at its exit (b = t_exit), the exit moves to a with that sign after it, and a switch at t_exit returns to
///   the sign that followed where that differs;
/// - inside it, an exit at a and a new entry at b.
/// The crossing times a and b are linearly interpolated between the samples. `out` gets the amended events
/// with those times as guesses (ascending, paired). False (and `out` unchanged) when every singular torque
/// lies within its bound, or one lies outside over a whole arc.
bool with_bounded_singular_torque(const ReorientationProblem& p, const ArcStructure& s,
                                  const std::vector<double>& times, const IndirectSolution& shot,
                                  ArcStructure& out);

/// The relative excess of a singular torque over its bound (|ũ_i| / ū_i − 1) that
/// with_bounded_singular_torque mends: well above the round-off of ũ (the verification's admissibility
/// tolerance is 1e-9), far below the excess of an extremal entered at the wrong side (problem 12 of seed 6 of
/// the benchmark's nonprincipal family: ũ1 = −1.48 ū1 at the entry, after a bang arc of +ū1).
constexpr double kSingularTorqueExcess = 1e-6;

}  // namespace poinsot::optimal::detail
