#pragma once
/// @file integrator.hpp
/// The one interface every integrator implements (Boost.Odeint's `step(state, dt)` concept, as a small
/// virtual class): a new method is one new file. Fixed-step methods take exactly the step asked; adaptive
/// ones take at most that step (and at most IntegratorOptions::max_step), report the step taken and propose
/// the next, and offer dense output inside the last step.
///
/// The methods, each in its own file with its order and what it preserves, are listed once, in the registry
/// (methods.hpp), which make_integrator reads.

#include <limits>
#include <memory>
#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::dynamics {

/// Options common to all integrators; each uses those that apply to it.
struct IntegratorOptions {
  double dt = 1e-3;  ///< s: the step of fixed-step methods, the first step of adaptive ones
  /// s, > 0: the largest step of adaptive methods. By default there is none: the tolerances alone set the
  /// step, and a caller that needs the state between steps (samples, events) reads the dense output.
  double max_step = std::numeric_limits<double>::infinity();
  double rtol = 1e-10;              ///< relative tolerance of adaptive methods
  double atol = 1e-12;              ///< absolute tolerance of adaptive methods
  double newton_tolerance = 1e-14;  ///< implicit methods (rattle): relative tolerance of the Newton iteration
  int newton_max_iterations = 50;
};

/// What one call of step() did.
struct StepResult {
  double dt_taken = 0.0;  ///< s
  double dt_next = 0.0;   ///< s, the step the method proposes next (= dt for fixed-step methods)
  int rejected = 0;       ///< rejected attempts inside this call (adaptive methods)
};

/// Sees each step that Integrator::advance takes, through the body angular velocity alone, so that a method
/// need not form the attitude between the steps (the simulation driver tracks the energy and the flips of a
/// torque-free body with it).
class StepWatcher {
 public:
  virtual ~StepWatcher() = default;
  /// After step k (0 ≤ k < n) of an advance: the time (s) that step reached and the body angular velocity
  /// (rad/s). The integrator's dense output, if it has one, covers that step. May throw; the advance then
  /// stops with the state it was handed unchanged or partly advanced.
  virtual void after_step(long long k, double time, const Vec3& omega_body) = 0;
};

class Integrator {
 public:
  virtual ~Integrator() = default;
  /// The method's name in the registry (methods.hpp).
  virtual std::string_view name() const = 0;
  /// Order of accuracy in the step (0 for exact).
  virtual int order() const = 0;
  virtual bool is_adaptive() const { return false; }
  virtual bool has_dense_output() const { return false; }
  /// s: the step the method was configured with (IntegratorOptions::dt), which the simulation driver uses
  /// for fixed-step methods and as the first step of adaptive ones; 0 when the method has none
  /// (exact: any step is exact), in which case the driver steps from sample to sample.
  virtual double nominal_step() const { return 0.0; }

  /// Advances `state` by one step of at most `dt` seconds (exactly dt for fixed-step methods).
  /// Throws ComputationFailed (with t and the cause) when the step cannot be taken.
  virtual StepResult step(State& state, double dt) = 0;
  /// Advances `state` by n ≥ 1 consecutive steps of dt (at most dt for adaptive methods): bit for bit what n
  /// calls of step(state, dt) leave, the time included, but a method may keep its own representation between
  /// the steps and convert to a State once, at the end (rk4). `watcher`, if not null, sees every step.
  /// Returns the last step's result with `rejected` summed over the n steps. Allocates nothing. Throws
  /// InvalidInput for n < 1 and what step() throws.
  virtual StepResult advance(State& state, double dt, long long n, StepWatcher* watcher = nullptr);
  /// The state at time t inside the last step taken (has_dense_output() only). Allocates nothing.
  virtual State dense_output(double t) const;

  /// The multiplier matrix Λ = Rᵀ R̈ K (body frame, J = kg·m²/s²) of the last step, for methods that compute
  /// it (rattle); false otherwise. rattle returns its discrete multiplier centred on the midpoint of the last
  /// step, t − dt_taken/2, where it approximates (j(ω)² + j(ω̇))K to second order.
  virtual bool last_multiplier(Mat3& lambda_body) const;

 protected:
  /// Throws InvalidInput "METHOD: advance: n = N steps; expected at least 1" for n < 1.
  static void require_step_count(std::string_view method, long long n);
};

/// Creates the integrator of the registry (methods.hpp) named `name` for a body and a torque (null: none).
/// Throws InvalidInput for an unknown name (listing the registry's names), invalid options, or a torque-free
/// method (MethodInfo::takes_torque false, i.e. exact) with a non-zero torque. Defined in methods.cpp.
std::unique_ptr<Integrator> make_integrator(std::string_view name, const RigidBody& body,
                                            std::shared_ptr<const TorqueModel> torque,
                                            const IntegratorOptions& options = {});

}  // namespace poinsot::dynamics
