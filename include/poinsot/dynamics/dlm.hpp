#pragma once
/// @file dlm.hpp
/// The explicit symplectic, time-reversible splitting of Dullweber, Leimkuhler & McLachlan (1997, J. Chem.
/// Phys. 107, 5840; "rotation by planar rotations"), order 2.
///
/// In the principal frame (J = diag(I1, I2, I3), body momentum Π = J ω) the free Hamiltonian
/// H = Σ Πᵢ²/(2Iᵢ) splits into three pieces Hᵢ = Πᵢ²/(2Iᵢ), each exactly solvable: the body turns about
/// principal axis i at the constant rate θ̇ = Πᵢ/Iᵢ, so Π ← rotᵢ(−θ) Π and R ← R rotᵢ(θ), two planar
/// rotations. The symmetric (Strang) composition
///
///     Φ_h = φ₁(h/2) ∘ φ₂(h/2) ∘ φ₃(h) ∘ φ₂(h/2) ∘ φ₁(h/2)
///
/// is symplectic (on T*SO(3)), time-reversible, order 2, conserves L_space = R Π and |Π| to round-off (every
/// sub-flow does), keeps R orthogonal to round-off (planar rotations), and keeps the energy error bounded
/// (O(h²), no drift) over exponentially long times (backward error analysis; Hairer, Lubich & Wanner,
/// Geometric Numerical Integration, §VII.5). Five sin/cos pairs per step (Taylor polynomials to round-off
/// for angles below 1/4 rad), each rotation applied as the increment x + ((cos θ − 1)x + sin θ y) so that
/// the rounding of the invariants random-walks (Brouwer's law, docs/integrators.md). Every 16 steps one
/// Björck step R ← R − ½R(RᵀR − I) removes the accumulated rounding (it moves R by ~1e-15), so ‖RᵀR − I‖
/// stays at round-off however long the run.
///
/// Torques enter as symmetric Strang kicks Π ← Π + (h/2) τ_body before and after the free flow. For gravity
/// about a pivot (τ from the potential V(R) = −m gᵀ R d) a kick is the exact flow of V, so the method stays
/// symplectic and reversible and the total energy error stays bounded; for any torque it stays of order 2.
/// For a torque that reads ω the closing kick is solved by fixed-point iteration (the adjoint of the opening
/// one), which keeps the method symmetric.
#include <memory>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

class DlmIntegrator final : public Integrator {
 public:
  /// Uses options.dt (s) as the nominal step. Throws InvalidInput for a non-positive dt.
  DlmIntegrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                const IntegratorOptions& options = {});
  ~DlmIntegrator() override;

  /// The method's name in the registry (methods.hpp), scenario files and the command line.
  static constexpr std::string_view kName = "dlm";
  std::string_view name() const override { return kName; }
  int order() const override { return 2; }
  double nominal_step() const override { return dt_; }
  /// Advances by exactly dt (s). Allocates nothing. Throws ComputationFailed when the implicit closing kick
  /// of an ω-dependent torque does not converge.
  StepResult step(State& state, double dt) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double dt_;
};

}  // namespace poinsot::dynamics
