#pragma once
/// @file rk4.hpp
/// The classical fourth-order Runge–Kutta method on Euler's equations and the quaternion kinematics,
///
///     J ω̇ = τ_body − ω × J ω,   q̇ = ½ q ⊗ (0, ω)   (R = R(q) maps body → space, Ṙ = R j(ω)),
///
/// with the quaternion renormalised every kRk4RenormaliseEvery steps and R formed from the normalised q (so R
/// is orthogonal to round-off). Order 4 in ω and R.
/// Preserves nothing exactly: energy and |L| drift by O(h⁴) per unit time (secularly). The baseline; cost 4
/// right-hand sides per step. Reference: Hairer, Nørsett & Wanner, Solving ODEs I, §II.1.
#include <memory>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

/// rk4 renormalises its quaternion after every 16th step counted from the State it started from (the Newton
/// step q ← q(3 − |q|²)/2, off the chain of dependent operations of the other 15), not after every step: |q|
/// does not enter the motion (R is formed from q/|q|), and |q|² − 1 stays at 16 steps' truncation error in
/// |q|, 16 (h|ω|/2)⁶/72 (2e-9 at h|ω| = 0.1). The ensemble layer's batched rk4 repeats this schedule.
inline constexpr int kRk4RenormaliseEvery = 16;

class Rk4Integrator final : public Integrator {
 public:
  /// Uses options.dt (s) as the nominal step. Throws InvalidInput for a non-positive dt.
  Rk4Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                const IntegratorOptions& options = {});
  ~Rk4Integrator() override;

  /// The method's name in the registry (methods.hpp), scenario files and the command line.
  static constexpr std::string_view kName = "rk4";
  std::string_view name() const override { return kName; }
  int order() const override { return 4; }
  double nominal_step() const override { return dt_; }
  /// Advances by exactly dt (s): advance(state, dt, 1). Allocates nothing.
  StepResult step(State& state, double dt) override;
  /// n steps of exactly dt (s) on the method's own y = (q, ω), the rotation matrix formed once at the end.
  StepResult advance(State& state, double dt, long long n, StepWatcher* watcher = nullptr) override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double dt_;
};

}  // namespace poinsot::dynamics
