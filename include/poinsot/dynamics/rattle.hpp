#pragma once
/// @file rattle.hpp
/// The variational (RATTLE / discrete Moser–Veselov) integrator of the rotation-matrix formulation of
/// Vallée & Dumitriu (2002), `R̈ K = R Λ`, `RᵀR = I`, with K = tr(J)/2·I − J the Poinsot tensor, in the
/// Lie-group form of Lee, Leok & McClamroch (2005, "A Lie group variational integrator for the attitude
/// dynamics of a rigid body with applications to the 3D pendulum", eqs. 19–21), which never inverts K and so
/// also works for plane laminae (K singular).
///
/// One step of size h, body momentum Π = J ω, torque kicks at both ends (Strang):
///
///     Π⁺ = Π_k + (h/2) τ_k
///     h j(Π⁺) = F K − K Fᵀ,   F ∈ SO(3)            (solved for F = cay(c) by Newton on the Cayley vector c)
///     R_{k+1} = R_k F,   Π⁻ = Fᵀ Π⁺,   Π_{k+1} = Π⁻ + (h/2) τ_{k+1}
///
/// With cay(c) = (I − j(c))⁻¹(I + j(c)) (so3/cayley.hpp) the implicit equation reads
/// `h (1 + |c|²) Π⁺ = 2 (J c + c × J c)`, whose Jacobian `2h Π⁺cᵀ − 2(J + j(c)J − j(Jc))` involves J only.
/// This is RATTLE applied to R̈K = RΛ with the constraint RᵀR = I: the position update is
/// `R_{k+1}K = R_k K + h Ṙ_k K + (h²/2) R_k Λ_k` with a symmetric multiplier Λ_k, and the velocity update
/// gives Λ'_{k+1}; their mean is the multiplier returned by last_multiplier(), centred on the midpoint of the
/// step, where it approximates Λ = (j(ω)² + j(ω̇))K to second order (with a torque the kicks add j(J⁻¹τ̄)K).
///
/// Order 2, symplectic, time-reversible; conserves L_space = R Π to round-off (torque-free), |Π|, keeps R in
/// SO(3) to round-off (F is a rotation by construction; every 16 steps one Björck step R ← R − ½R(RᵀR − I)
/// removes the accumulated rounding; F is applied as the increment R + R(F − I), so that the rounding of the
/// invariants random-walks: Brouwer's law, docs/integrators.md), and the energy error bounded (no drift; for
/// the free body the kinetic energy is in fact conserved to round-off, as measured). Cost: a Newton iteration
/// of 2–3 solves of 3×3 systems per step, predicted from the previous step's Cayley vector.
#include <memory>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

class RattleIntegrator final : public Integrator {
 public:
  /// Uses options.dt (s) as the nominal step, options.newton_tolerance (relative, on c) and
  /// options.newton_max_iterations. Throws InvalidInput for a non-positive dt or tolerance.
  RattleIntegrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                   const IntegratorOptions& options = {});
  ~RattleIntegrator() override;

  /// The method's name in the registry (methods.hpp), scenario files and the command line.
  static constexpr std::string_view kName = "rattle";
  std::string_view name() const override { return kName; }
  int order() const override { return 2; }
  double nominal_step() const override { return dt_; }
  /// Advances by exactly dt (s). Allocates nothing. Throws ComputationFailed when Newton's iteration does not
  /// converge (a step far too large for the spin rate) or an ω-dependent torque kick does not converge.
  StepResult step(State& state, double dt) override;
  /// Λ (body frame, J) at the midpoint t − dt/2 of the last step; false before the first step.
  bool last_multiplier(Mat3& lambda_body) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double dt_;
};

}  // namespace poinsot::dynamics
