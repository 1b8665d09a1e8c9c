#pragma once
/// @file phased_collocation.hpp
/// The direct method with one phase per arc: once the switching structure of a minimum-time control is
/// known, the problem is transcribed again (Hermite–Simpson, collocation_nlp.hpp with phases) with one phase
/// per arc between switches. Each phase has its own uniform mesh and its own duration Δ_a, an NLP variable,
/// so the switch times t_a = Σ_{b≤a} Δ_b are unknowns and every switch falls exactly on a mesh node; the
/// state is continuous across it (7 continuity rows) while the control may jump. On a bang arc the control
/// is fixed at its bound (per-axis bounds: u_i = ±u_max,i as the structure says; norm bound: ±ū along a body
/// axis). Arcs with a free control are not used: a jump of u between two collocation points is invisible to
/// the transcription, so with u free on an arc the discrete optimum moves a switch off the phase boundary
/// (measured on the norm-bound sphere: the reversal off by about half an interval, T too short by O(h)).
/// Ipopt runs with bound_relax_factor = 0: its default relaxation of the bounds by 1e-8 left t* of the
/// norm-bound sphere 1.7e-8 short at any mesh. No switch is blurred
/// over a mesh interval, so t* and the switch times converge at the method's order h⁴ on smooth arcs, not at
/// the O(h) of a switch inside an interval.
///
/// The structure is read from the direct solution (the same reading that seeds the shooting method) or
/// taken from the indirect solution; the re-solve starts from the direct solution's samples, interpolated.
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

/// The arcs of a minimum-time control: the times between them and the torque bounds on each.
struct SwitchingStructure {
  std::vector<double> switch_times;  ///< s, strictly ascending: the first guesses of the phase boundaries
  /// Per arc (switch_times.size() + 1 of each), body frame, N·m: the bounds of u on that arc; a component
  /// with lower = upper is fixed (a bang arc).
  std::vector<Vec3> torque_lower, torque_upper;
};

/// The structure of a minimum-time direct solution. Per-axis bounds: the sign changes of each u_i (as for
/// the shooting method; switches of different axes closer than 1e-9 T are refused), every arc bang on every
/// axis. Norm bound: the reversals of u = −ū σ/‖σ‖ (where σ passes through 0), each arc fixed at ±ū along
/// the body axis its saturated torques (‖u‖ > ū/2) stay within 1e-4 rad of.
/// Throws InvalidInput for another objective, an empty direct solution, an arc the direct solution shows
/// inside its bounds (a singular arc), or a norm-bound arc whose torque does not stay along a body axis.
SwitchingStructure read_switching_structure(const ReorientationProblem& problem,
                                            const DirectSolution& direct);

/// The structure of a converged minimum-time indirect solution: its switch times, and on each arc its torque
/// (per-axis: the bang values; norm bound: fixed along a body axis, as above).
/// Throws InvalidInput for another objective, an indirect solution that did not converge, or a norm-bound
/// arc whose torque does not stay along a body axis.
SwitchingStructure read_switching_structure(const ReorientationProblem& problem,
                                            const IndirectSolution& indirect);

struct PhasedOptions {
  int intervals_per_arc = 8;     ///< uniform Hermite–Simpson intervals on every arc
  double nlp_tolerance = 1e-12;  ///< Ipopt's tol (scaled KKT error)
  int max_nlp_iterations = 500;
  int print_level = 0;  ///< Ipopt's print_level (0 = silent)
};

struct PhasedSolution {
  bool converged = false;  ///< Ipopt solved the phased NLP
  std::string status;      ///< "converged", or Ipopt's status
  /// The collocated solution on all phases (time, states, torques, costates, mesh errors); a switch time
  /// appears twice in `time`, once per side, with the torque of that side. `solution.converged` = converged.
  DirectSolution solution;
  std::vector<double> switch_times;  ///< s: the phase boundaries Σ_{b≤a} Δ_b
  int nlp_iterations = 0;
};

/// Solves the phased NLP from `guess` (a direct solution of the same problem, interpolated onto the phases).
/// Throws InvalidInput (one line naming the field) for a problem that is not minimum time, an empty guess,
/// a structure whose sizes disagree or whose times are not strictly ascending inside (0, guess.final_time),
/// or intervals_per_arc < 1, max_nlp_iterations < 1, a tolerance that is not finite and positive.
PhasedSolution solve_direct_phased(const ReorientationProblem& problem, const DirectSolution& guess,
                                   const SwitchingStructure& structure, const PhasedOptions& options = {});

}  // namespace poinsot::optimal
