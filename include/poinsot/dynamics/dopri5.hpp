#pragma once
/// @file dopri5.hpp
/// Dormand–Prince 5(4) with Hairer's step-size control and Shampine's dense output of order 4, on Euler's
/// equations and the quaternion kinematics (y = (q, ω), J ω̇ = τ_body − ω × Jω, q̇ = ½ q ⊗ (0, ω)).
///
/// Order 5 (local extrapolation), error estimate of order 4, 6 right-hand sides per accepted step (FSAL). The
/// scaled error `sqrt(mean((e_i / (atol + rtol·max(|y0_i|, |y1_i|)))²))` is kept ≤ 1 per step. Preserves
/// nothing exactly: invariants drift within the tolerance. Coefficients: Dormand & Prince (1980); dense
/// output and controller: Hairer, Nørsett & Wanner, Solving ODEs I (2nd ed.), §II.5 and §II.6, code DOPRI5.
#include <memory>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

class Dopri5Integrator final : public Integrator {
 public:
  /// options.dt (s): the first step; options.max_step (s, default none): the largest; rtol, atol > 0.
  /// Throws InvalidInput otherwise.
  Dopri5Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                   const IntegratorOptions& options = {});
  ~Dopri5Integrator() override;

  /// The method's name in the registry (methods.hpp), scenario files and the command line.
  static constexpr std::string_view kName = "dopri5";
  std::string_view name() const override { return kName; }
  int order() const override { return 5; }
  bool is_adaptive() const override { return true; }
  bool has_dense_output() const override { return true; }
  double nominal_step() const override;
  /// One accepted step of at most min(dt, max_step) (s); rejected attempts are retried with a smaller step.
  /// Throws ComputationFailed when rejections shrink the step below 1e-14·max(1, |t|) s; InvalidInput for
  /// dt ≤ 0.
  StepResult step(State& state, double dt) override;
  /// The interpolated state at t (s) in the last accepted step (quaternion normalised), error O(h⁵).
  State dense_output(double t) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace poinsot::dynamics
