#pragma once
/// @file switching_structure.hpp (internal)
/// The switching structure of a minimum-time control read from a direct (collocated) solution: for per-axis
/// bounds the initial sign of each u_i and the times and axes of its sign changes (bang-bang), for a norm
/// bound the reversals of u = −ū σ/‖σ‖ where σ passes through 0. Used to seed the shooting method and the
/// phase-per-arc collocation.
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal::detail {

/// The fraction of u_max,i below which a direct sample of u_i lies inside its bound: a sample of a singular
/// arc or of a dip, not of a bang arc (the structure readers below and read_arc_structure).
constexpr double kInsideBound = 0.95;

/// The shortest singular arc the structure readers take, as a fraction of T: a stretch at least this long of
/// direct samples with |u_i| < kInsideBound u_max,i is a singular arc, a shorter one the collocation's
/// passage through a switch. On problem 4 of seed 2 of the benchmark's nonprincipal family a singular arc of
/// u2 lasts 4.1 % of T; read as part of a bang arc, it gave an extremal 1.2e-4 slower than the direct
/// optimum, which the verification rejected.
constexpr double kShortestSingularArc = 0.02;

/// The shortest stretch (fraction of T) of direct samples inside the bound that the shooting takes for a
/// singular arc once a bang-bang extremal has failed the minimum principle there (switching_sign_violations):
/// shorter stretches than kShortestSingularArc are mostly the collocation's passage through a switch, but a
/// σ_i that grazes 0 along a bang arc tells that such a stretch is a short singular arc. Problem 5 of seed 3
/// of the benchmark's nonprincipal family: u3 inside its bound from 1.1290 s to 1.1736 s (0.95 % of T); the
/// bang-bang extremal has u3 of σ3's sign at 6 samples (σ3 within 3.2e-6 of max |σ| of 0 from 1.12 s to
/// 1.21 s), and the extremal over a singular arc of u3 from 1.1288 s to 1.1722 s verifies, 1.2e-7 s faster.
constexpr double kShortestGrazedSingularArc = 0.005;

/// The dead zone of a bang-bang extremal's switching function, relative to max |σ_i| over the extremal: a
/// sample with |σ_i| below it does not count as u_i having σ_i's sign. It is above the round-off of σ at a
/// switch, where the shooting pins σ_i(t_s) = 0 (5e-14 relative on the benchmark's problems).
constexpr double kSwitchingSignDeadZone = 1e-9;

/// For each axis i, the samples of a bang-bang extremal where u_i has the sign of σ_i, |σ_i| above the dead
/// zone: where the control does not minimise H = … + σ·u (none for an extremal whose switches are σ's zeros).
Eigen::Vector3i switching_sign_violations(const IndirectSolution& s);

/// "u<axis + 1> is inside its bound from t = <t0> s to <t1> s": the start of every message about a stretch of
/// direct samples that may be a singular arc.
std::string inside_bound_message(int axis, double t0, double t1);

// Sign changes of u_i in the direct solution: the switching structure of a bang-bang control.
struct SwitchGuess {
  Vec3 initial_sign = Vec3::Ones();
  std::vector<double> times;  // s, in the order read (axis by axis), not sorted
  std::vector<int> axes;
  std::string singular;           // non-empty when u_i stays inside its bound over a stretch (singular arc)
  std::vector<double> reversals;  // norm bound: times where σ passes through 0 and u = −ū σ/‖σ‖ reverses
};

/// Norm bound, minimum time: consecutive saturated samples of the direct solution whose torques are more
/// than 90° apart mark a zero of σ (the torque reverses through it, as for a sphere's eigenaxis slew at T/2);
/// the time is the zero of the component along the earlier torque, linearly interpolated.
std::vector<double> read_reversals(const ReorientationProblem& p, const DirectSolution& d);

/// The time (s) of the first sign change of u_i between samples `from` and `to` of the direct solution: the
/// zero of its piecewise-linear interpolant; the time of `from` when u_i keeps its sign.
double torque_sign_change(const DirectSolution& d, int axis, std::size_t from, std::size_t to);

/// The shortest first or last bang arc (fraction of T) of a shot that did not converge, below which
/// without_vanishing_end_arcs takes it for an arc the extremal does not have. The shooting keeps every switch
/// inside (0, T), so Newton, driving such an arc's switch towards t = 0 (or T), stalls against that edge.
/// Problem 15 of seed 5 of the benchmark's nonprincipal family: u1's first arc shrinks with every mesh of the
/// direct method (0.060 s on the first, 0.0076 s on the tenth; T = 1.087 s), Newton takes its switch to
/// 1.1e-9 s and stalls at a residual of 9.5e-3; without that arc the shooting converges to an extremal that
/// verifies.
constexpr double kVanishingEndArc = 1e-4;

/// `sw` without the switches that the unconverged bang-bang shot `shot` (shot from `sw`) left closer than
/// kVanishingEndArc of its final time to t = 0 or T: for each axis, as many of its earliest (latest)
/// switches in `sw`; an axis whose first switch is dropped starts with the opposite sign. False (and `out`
/// unchanged) when there is none.
bool without_vanishing_end_arcs(const SwitchGuess& sw, const IndirectSolution& shot, SwitchGuess& out);

/// The longest first or last bang arc (fraction of T) of the direct solution's switching structure that the
/// shooting tries without when neither the shot from the structure nor without_vanishing_end_arcs' converged.
/// Newton does not always drive a spurious end arc's switch to the edge: from the direct solutions of the
/// problem above at mesh tolerances 1e-5, 3e-6 and 1e-6 it stalled at residuals of 4e-3 to 2e-2 with the
/// switch inside (at 1e-5: 0.040 s, 3.7 % of T); shot without the end arcs within 5 % of T it converges from
/// all three. An end arc the extremal does have leaves the retry unconverged, and the first shot's failure
/// stands.
constexpr double kShortEndArc = 0.05;

/// `sw` without each axis' first switch when it lies before kShortEndArc T and its last when after
/// (1 − kShortEndArc) T (T: the direct solution's final time); an axis whose first switch is dropped starts
/// with the opposite sign. False (and `out` unchanged) when there is none.
bool without_short_end_arcs(const SwitchGuess& sw, double T, SwitchGuess& out);

/// Samples first … last (inclusive) of the direct solution.
struct SampleRange {
  std::size_t first = 0, last = 0;
};

/// The maximal stretches of samples of u_axis inside its bound (|u_axis| < kInsideBound u_max,axis), each
/// from an inside sample to an inside sample, joined across runs of at most `max_gap` samples outside the
/// band and never across a sample for which `excluded(j)` is true (a boundary arc's). In time order.
template <class Excluded>
std::vector<SampleRange> inside_bound_stretches(const ReorientationProblem& p, const DirectSolution& d,
                                                int axis, int max_gap, const Excluded& excluded) {
  auto inside = [&](std::size_t j) {
    return std::abs(d.torque_body[j][axis]) < kInsideBound * p.torque_max[axis];
  };
  const std::size_t N = d.time.size();
  std::vector<SampleRange> stretches;
  for (std::size_t j = 0; j < N;) {
    if (excluded(j) || !inside(j)) {
      ++j;
      continue;
    }
    std::size_t last = j;
    int gap = 0;
    for (std::size_t k = j + 1; k < N && !excluded(k); ++k) {
      if (inside(k)) {
        last = k;
        gap = 0;
      } else if (++gap > max_gap) {
        break;
      }
    }
    stretches.push_back({j, last});
    j = last + 1;
  }
  return stretches;
}

/// Whether samples first … last of u_axis in the direct solution are a dip: inside kInsideBound of u_max,axis
/// (the caller's test), neither at t = 0 nor at T (0 < first ≤ last < N − 1), and of one sign from the sample
/// before them to the sample after them: u_axis leaves its bound towards 0 and returns to the same bound
/// without a switch. On an optimum that is a singular arc, or a pulse of the other sign, shorter than the
/// mesh resolves.
bool is_torque_dip(const DirectSolution& d, int axis, std::size_t first, std::size_t last);

/// `sw` with a pair of switches of its axis at each dip of the direct torque (each run of consecutive samples
/// inside kInsideBound of the bound that is_torque_dip accepts and that lasts less than kShortestSingularArc
/// of T): at c ± w/2, where c is the time weighted by the deficit ū_i − |u_i| over [t_first−1, t_last+1] and
/// w = ∫ (ū_i − |u_i|) dt / (2 ū_i) there, the width of the pulse of the other sign that makes up the impulse
/// the dip lacks. False (and `out` unchanged) when there is no dip.
bool with_switch_pairs_at_dips(const ReorientationProblem& p, const DirectSolution& d, const SwitchGuess& sw,
                               SwitchGuess& out);

/// Per-axis bounds: the sign changes of each u_i between saturated samples (|u_i| > u_max,i / 2), each at the
/// zero of the piecewise-linear interpolant; `singular` names an axis whose torque stays inside kInsideBound
/// of its bound for more than kShortestSingularArc of T.
SwitchGuess read_switch_guess(const ReorientationProblem& p, const DirectSolution& d);

}  // namespace poinsot::optimal::detail
