#pragma once
/// @file rattle.hpp
/// RATTLE (Andersen 1983; Hairer, Lubich & Wanner, Geometric Numerical Integration, VII.1.4) for the
/// constrained system in the 12 coordinates per body (x, R) with the constant mass matrix
/// blockdiag(m I, K ⊗ I) (model.hpp). It is symplectic, symmetric, second order, and conserves the linear and
/// angular momentum of free systems exactly (up to the Newton tolerance).
///
/// One step of size h, per body (docs/multibody_theory.md §2 for the derivation):
///
///     position stage:  m (u − vₙ) = h/2 fₙ + Gₓᵀν,
///                      J w + σ w × J w = J ωₙ + h/2 τₙ + G_θᵀν,     σ = h / (1 + √(1 − h²|w|²)),
///                      xₙ₊₁ = xₙ + h u,  Rₙ₊₁ = Rₙ Q,  Q = I + j(hw) + j(hw)² / (1 + √(1 − h²|w|²)),
///                      g(xₙ₊₁, Rₙ₊₁) = 0                        (ν = h/2 λ, G at qₙ);
///     velocity stage:  m vₙ₊₁ = m u + h/2 fₙ₊₁ + Gₓᵀμ,
///                      J ωₙ₊₁ = J w − σ w × J w + h/2 τₙ₊₁ + G_θᵀμ,   G(qₙ₊₁) (vₙ₊₁, ωₙ₊₁) = 0.
///
/// These are exactly RATTLE's equations `M(V½ − Vₙ) = h/2 (F + ∇g ᵀλ)`, `qₙ₊₁ = qₙ + h V½`, in which the
/// orthogonality constraint Rₙ₊₁ᵀRₙ₊₁ = I is solved in closed form (Q is the orthogonal matrix near I whose
/// skew part is j(hw)) and its multiplier Λ is then explicit (the symmetric part of the R-equation); K is
/// never inverted. The position stage is solved by a simplified Newton iteration on (u, w, ν) whose matrix is
/// the KKT matrix [M Gᵀ; G 0] at qₙ (kkt_solver.hpp, O(N) on trees), factored once per step and reused by the
/// next step's velocity stage; it stops when every joint residual is below `tolerance` times the system's
/// length scale (m; dimensionless rows: absolute) and every momentum residual below `tolerance` relative to
/// the sum of its terms' magnitudes (or has reached its round-off floor once the joints have converged).
/// Damper forces in the velocity stage use the extrapolated velocities 2V½ − Vₙ, which keeps second order.
///
/// Round-off: the momenta (m v, J ω) are carried from step to step as increments,
/// M Vₙ₊₁ = M Vₙ + h/2 (Fₙ + Fₙ₊₁) + Gₙᵀν + Gₙ₊₁ᵀμ − 2σ w × J w, so that only their sum rounds and never
/// through the rounded J⁻¹ and back; the velocities of the state are the velocity stage's solution. They are
/// carried while step() is given the state the last step returned (bit-identical velocities), and computed
/// from the state otherwise. Over an ensemble the invariants of a free system then random-walk (Brouwer's
/// law; docs/integrators.md).
///
/// Order 4 (RattleOptions::order = 4) composes three such steps of sizes γ₁h, γ₂h, γ₁h with
/// γ₁ = 1/(2 − 2^{1/3}), γ₂ = 1 − 2γ₁ (the "triple jump" of Yoshida 1990 and Suzuki 1990; Hairer, Lubich &
/// Wanner II.4): still symplectic, symmetric and momentum-conserving, fourth order, at three times the cost.
/// Its energy error is O(h⁴): on the 64-link benchmark chain at h = 1e-3 its peak is 40 times smaller than
/// order 2's.

#include <memory>

#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

struct RattleOptions {
  double tolerance =
      1e-13;                ///< Newton tolerance: joints relative to System::length_scale(), momenta relative
  int max_iterations = 50;  ///< Newton iterations per step before ComputationFailed
  int order = 2;            ///< 2: RATTLE; 4: RATTLE composed by the triple jump (three substeps)
};

class Rattle {
 public:
  /// The integrator keeps a copy of `system`. Throws InvalidInput for dt <= 0.
  Rattle(const System& system, double dt, RattleOptions options = {});
  ~Rattle();
  Rattle(Rattle&&) noexcept;
  Rattle& operator=(Rattle&&) noexcept;

  /// Advances `state` by one step dt. The state must satisfy the constraints (positions and velocities) to
  /// the tolerance; check_consistent() says by how much it fails. Throws ComputationFailed (with the time)
  /// when the Newton iteration does not converge or h|w| ≥ 1 (step far too large for the rotation rate);
  /// the state is then left as it was before the step.
  void step(State& state);

  double dt() const;
  int order() const;  ///< 2 or 4 (RattleOptions::order)
  const System& system() const;
  bool uses_tree_solver() const;
  KktMethod kkt_method() const;  ///< how the KKT systems are solved (kkt_solver.hpp)
  int last_iterations() const;   ///< Newton iterations of the last step's position stages (all substeps)
  /// Multipliers of the last step's first position stage (at the start of the step, from λ = 2ν/h₀) and of
  /// its last velocity stage (at its end, λ = 2μ/h₁); h₀ = h₁ = h at order 2, γ₁h at order 4. Both
  /// approximate the exact multipliers to O(h); at order 2 their mean at the same time t_n (velocity stage of
  /// step n−1, position stage of step n) does to O(h²). Computed on first access after a step.
  const Multipliers& position_stage() const;
  const Multipliers& velocity_stage() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace poinsot::multibody
