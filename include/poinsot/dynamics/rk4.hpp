#pragma once
/// @file rk4.hpp
/// The classical fourth-order Runge–Kutta method on Euler's equations and the quaternion kinematics,
///
///     J ω̇ = τ_body − ω × J ω,   q̇ = ½ q ⊗ (0, ω)   (R = R(q) maps body → space, Ṙ = R j(ω)),
///
/// with the quaternion renormalised after each step (so R is orthogonal to round-off). Order 4 in ω and R.
/// Preserves nothing exactly: energy and |L| drift by O(h⁴) per unit time (secularly). The baseline; cost 4
/// right-hand sides per step. Reference: Hairer, Nørsett & Wanner, Solving ODEs I, §II.1.
#include <memory>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

class Rk4Integrator final : public Integrator {
 public:
  /// Uses options.dt (s) as the nominal step. Throws InvalidInput for a non-positive dt.
  Rk4Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                const IntegratorOptions& options = {});
  ~Rk4Integrator() override;

  std::string_view name() const override { return "rk4"; }
  int order() const override { return 4; }
  double nominal_step() const override { return dt_; }
  /// Advances by exactly dt (s). Allocates nothing.
  StepResult step(State& state, double dt) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double dt_;
};

}  // namespace poinsot::dynamics
