#pragma once
/// @file integrator.hpp
/// The one interface every integrator implements (Boost.Odeint's `step(state, dt)` concept, as a small
/// virtual class): a new method is one new file. Fixed-step methods take exactly the step asked; adaptive
/// ones take at most that step, report the step taken and propose the next, and offer dense output inside the
/// last step.
///
/// The methods, each in its own file with its order and what it preserves, are listed once, in the registry
/// (methods.hpp), which make_integrator reads.

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
  double dt = 1e-3;     ///< s: the step of fixed-step methods, the first and largest step of adaptive ones
  double rtol = 1e-10;  ///< relative tolerance of adaptive methods
  double atol = 1e-12;  ///< absolute tolerance of adaptive methods
  double newton_tolerance = 1e-14;  ///< implicit methods (rattle): relative tolerance of the Newton iteration
  int newton_max_iterations = 50;
};

/// What one call of step() did.
struct StepResult {
  double dt_taken = 0.0;  ///< s
  double dt_next = 0.0;   ///< s, the step the method proposes next (= dt for fixed-step methods)
  int rejected = 0;       ///< rejected attempts inside this call (adaptive methods)
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
  /// for fixed-step methods and as the first and largest step of adaptive ones; 0 when the method has none
  /// (exact: any step is exact), in which case the driver steps from sample to sample.
  virtual double nominal_step() const { return 0.0; }

  /// Advances `state` by one step of at most `dt` seconds (exactly dt for fixed-step methods).
  /// Throws ComputationFailed (with t and the cause) when the step cannot be taken.
  virtual StepResult step(State& state, double dt) = 0;
  /// The state at time t inside the last step taken (has_dense_output() only). Allocates nothing.
  virtual State dense_output(double t) const;

  /// The multiplier matrix Λ = Rᵀ R̈ K (body frame, J = kg·m²/s²) of the last step, for methods that compute
  /// it (rattle); false otherwise. rattle returns its discrete multiplier centred on the midpoint of the last
  /// step, t − dt_taken/2, where it approximates (j(ω)² + j(ω̇))K to second order.
  virtual bool last_multiplier(Mat3& lambda_body) const;
};

/// Creates the integrator of the registry (methods.hpp) named `name` for a body and a torque (null: none).
/// Throws InvalidInput for an unknown name (listing the registry's names), invalid options, or a torque-free
/// method (MethodInfo::takes_torque false, i.e. exact) with a non-zero torque. Defined in methods.cpp.
std::unique_ptr<Integrator> make_integrator(std::string_view name, const RigidBody& body,
                                            std::shared_ptr<const TorqueModel> torque,
                                            const IntegratorOptions& options = {});

}  // namespace poinsot::dynamics
