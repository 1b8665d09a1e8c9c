#pragma once
/// @file methods.hpp
/// The registry of single-body integration methods: for each its name, order, what it preserves, whether it
/// takes a torque, a one-line description and its factory. It is the one list of methods: make_integrator,
/// the scenario files' `[integrator] method`, the command line's help and messages, the Python constants
/// (poinsot.METHODS) and the contract tests (tests/dynamics/test_integrator_contract.cpp) all read it, so a
/// new method is one new file (its Integrator) plus its entry in methods.cpp. Recipe: docs/extending.md.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/rattle.hpp"

namespace poinsot::dynamics {

/// The invariants of the torque-free motion a method keeps to round-off over any number of steps (not only
/// within its truncation error): kinetic energy T = ½ ωᵀJω, the space-frame angular momentum L_space = R J ω,
/// the norm of the body-frame momentum |J ω| (a Casimir), and RᵀR = I.
struct Preserved {
  bool energy = false;
  bool L_space = false;
  bool L_body_norm = false;
  bool orthogonality = false;
};

/// One registry entry.
struct MethodInfo {
  std::string_view name;  ///< what scenario files, the command line and Python call it ("rk4")
  int order = 0;          ///< order of accuracy in the step; 0: exact (no truncation error)
  bool adaptive = false;  ///< chooses its own steps (at most the one asked) within rtol, atol
  bool dense_output = false;
  bool takes_torque = true;  ///< false: torque-free motion only (make_integrator refuses a torque)
  bool symplectic = false;   ///< symplectic and time-reversible: energy error bounded, no drift
  Preserved preserves;
  std::string_view description;  ///< one line, for help texts and reports
  /// Creates the integrator; the arguments as make_integrator's (torque never null).
  std::unique_ptr<Integrator> (*make)(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                      const IntegratorOptions& options) = nullptr;
};

/// Every method, in the order help texts list them.
std::span<const MethodInfo> methods();

/// The default method of scenario files (`[integrator] method`), `poinsot run` and poinsot.simulate: DOP853,
/// adaptive and of order 8, accurate to its tolerance with any torque.
inline constexpr std::string_view kDefaultMethod = Dop853Integrator::kName;
/// The default method of the Λ analysis (`poinsot lambda`, analysis::analyse_lambda,
/// poinsot.analysis.lambda_report): RATTLE, the discretisation of R̈K = RΛ itself, whose own multipliers the
/// analysis then checks against the state formula; it keeps RᵀR = I, L_space and |L| to round-off.
inline constexpr std::string_view kDefaultLambdaMethod = RattleIntegrator::kName;

/// The entry named `name`. Throws InvalidInput "WHAT: got "NAME", expected one of exact, rk4, ..." for an
/// unknown name; `what` names the source of the value ("--method", "[integrator] method").
const MethodInfo& method_info(std::string_view name, std::string_view what = "method");

/// The names joined by `separator` ("exact, rk4, dopri5, dop853, dlm, rattle").
std::string method_names(std::string_view separator = ", ");

/// What the entry preserves to round-off, for help texts: "energy, L_space, |L|, RᵀR = I", or "nothing".
std::string preserved_names(const Preserved& preserved);

}  // namespace poinsot::dynamics
