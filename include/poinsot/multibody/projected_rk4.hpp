#pragma once
/// @file projected_rk4.hpp
/// The classical fourth-order Runge–Kutta method on the index-1 form of the multibody equations, projected
/// back onto the constraints after every step: the accurate, short-horizon alternative to RATTLE
/// (rattle.hpp).
///
/// The vector field at a state (x, R, v, ω) is ẋ = v, Ṙ = R j(ω), and the accelerations (a, ω̇) with the joint
/// multipliers λ solved from the KKT system of the constraints differentiated twice (Vallée & Dumitriu 2002's
/// `R̈ K = R Λ + F_R + G_Rᵀλ` with Λ eliminated in (v, ω) coordinates, multipliers.hpp):
///
///     m a = f + Gₓᵀλ,   J ω̇ + ω × J ω = τ + G_θᵀλ,   G (a, ω̇) + γ(q, v) = 0,
///
/// one O(N) factorisation and solve per stage (kkt_solver.hpp). After the four stages, qₙ₊₁ is brought back
/// onto the constraints:
/// - each R to the nearest rotation (polar decomposition by Newton–Schulz, R ← R (3I − RᵀR)/2, until
///   max |RᵀR − I| ≤ 1e-15);
/// - the joints by the M-orthogonal projection, a simplified Newton iteration δq = −M⁻¹Gᵀ(G M⁻¹ Gᵀ)⁻¹ g with
///   the last stage's factorisation (its G is O(h²) from G(qₙ₊₁), so each iteration gains about (hω)²), the
///   rotations updated by exact rotations R ← R cay(δθ/2), until every gap is below `tolerance` times the
///   system's length scale (m; perpendicularity rows: absolute);
/// - the velocities by the M-orthogonal projection onto G(qₙ₊₁) (v, ω) = 0, which removes the normal part
///   of the velocity and so never adds kinetic energy; applied as a correction (zero without joints), so that
///   the velocities never pass through M and the rounded M⁻¹ (a bias that made a free body's energy drift).
///
/// The factorisation at qₙ₊₁ also serves the first stage of the next step (first same as last), whose solve
/// gives the exact multipliers of the continuous equations at the current state (multipliers()).
///
/// Global error O(h⁴); constraints at the projection tolerance after every step. It is neither symplectic
/// nor symmetric: its energy error grows secularly (linearly in t, from an O(h⁴) per-unit-time rate), so
/// RATTLE stays the method for long runs and for momentum conservation; this one is for accurate trajectories
/// over a bounded time, and for the multipliers exactly at the sample times. (Hairer & Wanner, Solving ODE
/// II, VII.2, projection methods; Simbody's default integrators project the same way.)

#include <memory>

#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

struct ProjectedRk4Options {
  double tolerance = 1e-13;  ///< joint gaps after projection, relative to System::length_scale()
  int max_iterations = 20;   ///< projection iterations per step before ComputationFailed
};

class ProjectedRk4 {
 public:
  /// The integrator keeps a copy of `system`. Throws InvalidInput for dt <= 0 or a bad option.
  ProjectedRk4(const System& system, double dt, ProjectedRk4Options options = {});
  ~ProjectedRk4();
  ProjectedRk4(ProjectedRk4&&) noexcept;
  ProjectedRk4& operator=(ProjectedRk4&&) noexcept;

  /// Advances `state` by one step dt. The state must satisfy the constraints (check_consistent()). Throws
  /// ComputationFailed (with the time) when the projection does not converge or a KKT pivot is singular; the
  /// state is then left as it was before the step.
  void step(State& state);

  double dt() const;
  const System& system() const;
  KktMethod kkt_method() const;  ///< how the KKT systems are solved (kkt_solver.hpp)
  /// Joint projection iterations of the last step (0 when the RK4 step already landed within the tolerance).
  int last_iterations() const;
  /// The exact multipliers of the continuous equations (joint reactions, each body's Λ, the accelerations)
  /// at the state the last step produced, as exact_multipliers() gives them (to round-off): the next step's
  /// first stage. Computed on first access after a step. Empty before the first step.
  const ExactMultipliers& multipliers() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace poinsot::multibody
