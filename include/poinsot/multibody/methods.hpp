#pragma once
/// @file methods.hpp
/// The registry of multibody integration methods: for each its name, order(s), what it preserves, a one-line
/// description and its factory. It is the one list of multibody methods: scenario files' `[simulation]
/// method`, `poinsot run --method`, Python's `Scenario.method` and poinsot.multibody.METHODS, and the
/// contract tests (tests/multibody/test_method_contract.cpp) all read it. A new method is one new file (a
/// class with `step(State&)`, `last_iterations()`, `kkt_method()`) plus its enumerator and entry here and in
/// methods.cpp. Recipe: docs/extending.md.

#include <memory>
#include <span>
#include <string>
#include <string_view>

#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::multibody {

/// The integrator of a multibody run: RATTLE (rattle.hpp; symplectic, for long runs; order 2 or 4) or the
/// projected classical RK4 (projected_rk4.hpp; fourth order, not symplectic, for accurate bounded runs and
/// exact multipliers at every sample).
enum class MultibodyMethod { rattle, projected_rk4 };

/// What a method keeps over any number of steps: RᵀR = I to round-off, the joints to the method's
/// tolerance, and (for a free system: no joint to the ground, no external load) the linear and angular
/// momentum to that tolerance; a symplectic method also keeps the energy error bounded (no drift).
struct MultibodyPreserved {
  bool orthogonality = false;
  bool joints = false;
  bool momentum = false;
};

/// One step of a multibody method, behind one interface (the classes themselves are not virtual).
class MultibodyIntegrator {
 public:
  virtual ~MultibodyIntegrator() = default;
  /// Advances `state` by one step of the configured dt (s); throws as the method's own step() does.
  virtual void step(State& state) = 0;
  virtual int last_iterations() const = 0;  ///< Newton or projection iterations of the last step
  virtual KktMethod kkt_method() const = 0;
};

/// One registry entry.
struct MultibodyMethodInfo {
  MultibodyMethod method;
  std::string_view name;    ///< what scenario files, the command line and Python call it ("rattle")
  int order = 2;            ///< the default order of accuracy
  int max_order = 2;        ///< the highest order it offers (orders order, order + 2, ..., max_order)
  bool symplectic = false;  ///< symplectic and symmetric: energy error bounded, no drift
  MultibodyPreserved preserves;
  std::string_view label;        ///< a few words, for messages ("RATTLE, symplectic")
  std::string_view description;  ///< one line, for help texts and reports
  /// Creates the integrator for a system, a step dt (s) and an order (one it offers).
  std::unique_ptr<MultibodyIntegrator> (*make)(const System& system, double dt, int order) = nullptr;
};

/// Every method, the default first.
std::span<const MultibodyMethodInfo> multibody_methods();

/// The default method of multibody scenarios, `poinsot run` and Python: RATTLE, symplectic and
/// momentum-conserving, so fit for runs of any length.
inline constexpr MultibodyMethod kDefaultMultibodyMethod = MultibodyMethod::rattle;

/// The entry of a method.
const MultibodyMethodInfo& multibody_method_info(MultibodyMethod method);

/// The method named `name`. Throws InvalidInput `WHAT: got "NAME", expected "rattle" (RATTLE, symplectic) or
/// "rk4" (...)` (every entry listed) for an unknown name; `what` names the source of the value.
MultibodyMethod parse_multibody_method(std::string_view name, std::string_view what);

/// The names joined by `separator` ("rattle, rk4").
std::string multibody_method_names(std::string_view separator = ", ");

/// "rattle" or "rk4": the names of scenario files' `[simulation] method`, of `poinsot run --method`, of
/// summary.json and of Python.
const char* multibody_method_name(MultibodyMethod method);

/// `order` if the method offers it, else the method's default order: what a scenario's order becomes when
/// its method changes (RATTLE keeps 2 or 4, the projected RK4 is always 4).
int order_for_method(MultibodyMethod method, int order);

}  // namespace poinsot::multibody
