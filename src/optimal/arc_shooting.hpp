#pragma once
/// @file arc_shooting.hpp (internal)
/// The indirect method for minimum time with per-axis torque bounds |u_i| ≤ u_max,i over arcs that are not
/// all bang-bang: boundary arcs of an active rate bound |ω_i| ≤ r, on which one or more rates ride the bound,
/// ω_k = s_k r (s_k = ±1), and singular arcs, on which a switching function σ_i vanishes identically and u_i
/// lies inside its bound. Single shooting (docs/optimal_control_arcs.md).
///
/// Boundary arcs. The rate bound c_k = s_k ω_k − r ≤ 0 is a first-order state constraint (ċ_k = s_k ω̇_k
/// holds u). It is adjoined directly: 𝓛 = H + Σ μ_k c_k with μ_k ≥ 0, zero off the boundary arcs, so that on
/// an arc holding the set A of axes
///     ṗ_ω = −p_θ + (j(ω)J − j(Jω))ᵀ σ − Σ_{k∈A} μ_k s_k e_k,      σ = J⁻¹ p_ω,
/// and u minimises H over the box. The held components u_A cannot be at their bounds (they keep ω̇_A = 0),
/// so σ_A ≡ 0 along the arc: (J⁻¹ u)_A = (J⁻¹ (ω × Jω))_A fixes u_A from the bang components u_k = −u_max,k
/// sign σ_k (k ∉ A), and σ̇_A = 0 fixes μ: (J⁻¹)_AA (μ s)_A = (J⁻¹ g)_A with g = −p_θ + (j(ω)J − j(Jω))ᵀ σ.
/// At entry and exit the costates are continuous: a jump ζ ≥ 0 of p_ω along −s_k e_k would need σ_k of the
/// sign that drives ω_k away from the bound just before entry (or beyond it just after exit), so ζ = 0 and
/// σ_k passes through 0 at both junctions. H (= 𝓛 on the arc, where c = 0) stays constant and 0.
///
/// Singular arcs. On an arc where σ_S ≡ 0 for the set S of axes, H does not fix u_S; σ̇_S = 0 and σ̈_S = 0
/// do. With ṗ_θ = p_θ × ω and ω̇ = J⁻¹(u − ω × Jω),
///     σ̇ = J⁻¹(Jω × σ − p_θ) − ω × σ,
///     σ̈ = J⁻¹(Jω̇ × σ + Jω × σ̇ − ṗ_θ) − ω̇ × σ − ω × σ̇,
/// which is affine in u with ∂σ̈/∂u = C(σ) = j(σ) J⁻¹ − J⁻¹ j(σ). Its diagonal C_ii = 2 σ·(J⁻¹e_i × e_i) is
/// zero when e_i is a principal axis (no singular arc of order one about a principal axis), and in general
/// not: the singular control solves C_SS u_S = −σ̈_S(u with u_S = 0), the other axes bang. The arc is a
/// minimum only if the generalised Legendre–Clebsch (Kelley) condition −∂σ̈_i/∂u_i ≥ 0 holds on it, which the
/// verification checks (verification.hpp). Entry rows: σ_i(entry) = 0 and σ̇_i(entry) = 0, so that σ̈_i = 0
/// keeps σ_i ≡ 0 along the arc; the exit has no row. A singular arc may not overlap a boundary arc in time.
///
/// Unknowns: p_θ(0), p_ω(0), T, and the time of every event: the sign changes of the bang components
/// (σ_i(t_s) = 0), and per arc its entry and exit. Rows: the final conditions of indirect_shooting.hpp
/// (R(T) = R_f or p_θ(0) = 0 for a free final attitude, ω(T) = ω_f, H(T) = 0), per switch σ_i(t_s) ū_i, per
/// boundary arc ω_k(entry) − s_k r (times T) and σ_k(entry) ū_k, per singular arc σ_i(entry) ū_i and
/// σ̇_i(entry) ū_i T: a square system. The exit has no row of its own: the final conditions decide it. The
/// structure (initial signs, switches, arcs and the sign after each exit) is read from the direct solution;
/// the multipliers μ_k ≥ 0, the bounds on u_A and u_S, |ω| ≤ r off the arcs and Kelley's condition are
/// checked by the verification on the samples.
#include <string>
#include <vector>

#include "arc_structure.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal::detail {

/// Shoots from the direct solution's costates and the structure above (Newton's method with a
/// central-difference Jacobian and a backtracking line search on the residual's max norm, RKF78 at
/// options.integration_tolerance, to options.tolerance; when it stalls within 100× the tolerance, polished
/// once with a tenfold tighter integration, and accepted at a round-off floor within 10×, as
/// solve_indirect). Fills the solution's samples, its events (switch_times, switch_axes), rate_bound_arcs
/// and singular_arcs. Single shooting only (options.shooting_nodes is not used: these horizons are short).
/// A direct solution that starts (ends) on a singular arc is shot as a short bang arc before its entry (after
/// its exit), of sign +1, then −1 (read_arc_structure's start_bang_sign and end_bang_sign); the first that
/// converges is returned. A converged extremal whose singular torque leaves its bound is shot again over the
/// structure with_bounded_singular_torque amends. A structure read_arc_structure refuses is returned
/// unsolved, its status "not applied: <reason>". With `dips`, the structure includes the short dips of
/// read_arc_structure.
IndirectSolution solve_over_arcs(const ReorientationProblem& p, const DirectSolution& d,
                                 const ShootingOptions& options,
                                 double shortest_singular_arc = kShortestSingularArc, bool dips = false);

}  // namespace poinsot::optimal::detail
