#pragma once
/// @file exact_integrator.hpp
/// The exact torque-free motion (ExactFreeBody) behind the Integrator interface: step(state, dt) returns the
/// closed-form state at state.time + dt (s). The closed-form set-up is cached for the state the integrator
/// last produced, so a run of many steps costs one set-up; a state it did not produce (a new run, a state
/// edited by the caller) re-initialises it. Its error does not grow with the step: order() is 0, and it
/// offers dense output at any time (the closed form itself).

#include <memory>
#include <string_view>

#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::dynamics {

/// The name of the closed-form method in the registry (methods.hpp), scenario files and the command line.
inline constexpr std::string_view kExactMethodName = "exact";

/// The "exact" integrator. `torque` may be null or TorqueModel::none(); any other torque throws InvalidInput
/// ("exact: the closed-form solution is torque-free; got torque ..."). The body's J about its rotation point
/// is used (a body with a pivot and no torque rotates freely about the pivot).
std::unique_ptr<Integrator> make_exact_integrator(const RigidBody& body,
                                                  std::shared_ptr<const TorqueModel> torque);

}  // namespace poinsot::dynamics
