#pragma once
/// @file dop853.hpp
/// Hairer's DOP853: the explicit Runge–Kutta method of order 8 of Dormand & Prince (1981) with the 5th- and
/// 3rd-order error estimators combined as in Hairer's code, and a dense output of order 7 (3 extra stages,
/// computed only when dense output is asked for in a step), on Euler's equations and the quaternion
/// kinematics (y = (q, ω), J ω̇ = τ_body − ω × Jω, q̇ = ½ q ⊗ (0, ω)).
///
/// Order 8; 12 right-hand sides per accepted step (FSAL), 15 with dense output. The scaled error is kept
/// ≤ 1 per step. Preserves nothing exactly; at rtol = atol = 1e-13 it is the reference for the other methods.
/// Coefficients and controller: Hairer, Nørsett & Wanner, Solving ODEs I (2nd ed.), §II.5 and §II.10, code
/// DOP853 (the published tables; Hairer's constants fac1 = 0.333, fac2 = 6, β = 0, safe = 0.9).
#include <memory>

#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics {

class Dop853Integrator final : public Integrator {
 public:
  /// options.dt (s): the first step; options.max_step (s, default none): the largest; rtol, atol > 0.
  /// Throws InvalidInput otherwise.
  Dop853Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                   const IntegratorOptions& options = {});
  ~Dop853Integrator() override;

  /// The method's name in the registry (methods.hpp), scenario files and the command line.
  static constexpr std::string_view kName = "dop853";
  std::string_view name() const override { return kName; }
  int order() const override { return 8; }
  bool is_adaptive() const override { return true; }
  bool has_dense_output() const override { return true; }
  double nominal_step() const override;
  /// One accepted step of at most min(dt, max_step) (s). Throws ComputationFailed when rejections shrink the
  /// step below 1e-14·max(1, |t|) s; InvalidInput for dt ≤ 0.
  StepResult step(State& state, double dt) override;
  /// The interpolated state at t (s) in the last accepted step, error O(h⁸). The first call in a step
  /// evaluates the 3 extra stages (no allocation).
  State dense_output(double t) const override;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace poinsot::dynamics
