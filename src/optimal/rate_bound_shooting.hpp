#pragma once
/// @file rate_bound_shooting.hpp (internal)
/// The indirect method for minimum time with per-axis torque bounds |u_i| ≤ u_max,i and an active rate bound
/// |ω_i| ≤ r (docs/measurements/optimal_shooting.md, section 3, "Active rate bounds"): single shooting over
/// arcs that are either bang-bang or boundary arcs on which one or more rates ride the bound, ω_k = s_k r
/// (s_k = ±1).
///
/// The rate bound c_k = s_k ω_k − r ≤ 0 is a first-order state constraint (ċ_k = s_k ω̇_k holds u). It is
/// adjoined directly: 𝓛 = H + Σ μ_k c_k with μ_k ≥ 0, zero off the boundary arcs, so that on an arc holding
/// the set A of axes
///     ṗ_ω = −p_θ + (j(ω)J − j(Jω))ᵀ σ − Σ_{k∈A} μ_k s_k e_k,      σ = J⁻¹ p_ω,
/// and u minimises H over the box. The held components u_A cannot be at their bounds (they keep ω̇_A = 0),
/// so σ_A ≡ 0 along the arc: (J⁻¹ u)_A = (J⁻¹ (ω × Jω))_A fixes u_A from the bang components u_k = −u_max,k
/// sign σ_k (k ∉ A), and σ̇_A = 0 fixes μ: (J⁻¹)_AA (μ s)_A = (J⁻¹ g)_A with g = −p_θ + (j(ω)J − j(Jω))ᵀ σ.
/// At entry and exit the costates are continuous: a jump ζ ≥ 0 of p_ω along −s_k e_k would need σ_k of the
/// sign that drives ω_k away from the bound just before entry (or beyond it just after exit), so ζ = 0 and
/// σ_k passes through 0 at both junctions. H (= 𝓛 on the arc, where c = 0) stays constant and 0.
///
/// Unknowns: p_θ(0), p_ω(0), T, and the time of every event: the sign changes of the bang components
/// (σ_i(t_s) = 0), and per boundary arc its entry and exit. Rows: the final conditions of
/// indirect_shooting.hpp (R(T) = R_f or p_θ(0) = 0 for a free final attitude, ω(T) = ω_f, H(T) = 0), per
/// switch σ_i(t_s) ū_i, per arc ω_k(entry) − s_k r (times T) and σ_k(entry) ū_k: a square system. The exit
/// has no row of its own: the final conditions decide it. The structure (initial signs, switches, arcs and
/// the sign after each exit) is read from the direct solution; the multipliers μ_k ≥ 0, the bounds on u_A and
/// |ω| ≤ r off the arcs are checked by the verification (verification.hpp) on the samples.
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal::detail {

/// One event of a rate-bounded bang-bang control: a sign change of u_axis, or the entry into or the exit
/// from a boundary arc where ω_axis = side · r.
struct RateBoundEvent {
  enum class Kind { sign_change, entry, exit };
  Kind kind = Kind::sign_change;
  int axis = 0;
  double side = 1.0;        ///< entry and exit: s, the bound ω_axis = s r
  double time = 0.0;        ///< s, the guess
  double sign_after = 1.0;  ///< exit: the sign of u_axis after the exit
  int pair = -1;            ///< entry ↔ exit: the index of the other end of the arc
};

struct RateBoundStructure {
  Vec3 initial_sign = Vec3::Ones();
  std::vector<RateBoundEvent> events;  ///< ascending in time
  std::string refused;                 ///< non-empty: why the structure is not one this solver handles
};

/// The largest |ω_i| of the direct solution, and whether it reaches the bound (to 1e-4 relative).
bool rate_bound_active(const ReorientationProblem& p, const DirectSolution& d, double& peak);

/// Reads the structure from the direct solution: a boundary arc of axis k is a stretch of at least two
/// samples with |ω_k| ≥ (1 − 1e-3) r; the sign changes of u_k between samples outside its arcs where
/// |u_k| > u_max,k / 2 are switches, except one whose bracket contains an arc of the same axis (the arc
/// takes its place: the sign after the exit is the next saturated sample's). `refused` names a stretch where
/// u_k is inside its bound off every arc (a singular arc) or a problem that is not minimum time with
/// per-axis bounds.
RateBoundStructure read_rate_bound_structure(const ReorientationProblem& p, const DirectSolution& d);

/// Shoots from the direct solution's costates and the structure above (Newton's method with a
/// central-difference Jacobian and a backtracking line search on the residual's max norm, RKF78 at
/// options.integration_tolerance, to options.tolerance; when it stalls within 100× the tolerance, polished
/// once with a tenfold tighter integration, and accepted at a round-off floor within 10×, as
/// solve_indirect). Fills the solution's samples, its events (switch_times, switch_axes) and rate_bound_arcs.
/// Single shooting only (options.shooting_nodes is not used: these horizons are short).
IndirectSolution solve_rate_bounded(const ReorientationProblem& p, const DirectSolution& d,
                                    const ShootingOptions& options);

}  // namespace poinsot::optimal::detail
