#pragma once
// Declarations of the per-layer binding functions of poinsot._core, and helpers shared between them.
#include <pybind11/pybind11.h>

#include <memory>
#include <string>

#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::python {

void bind_so3(pybind11::module_& m);
void bind_dynamics(pybind11::module_& m);
void bind_simulate(pybind11::module_& m);
void bind_inertia(pybind11::module_& m);
void bind_analysis(pybind11::module_& m);
void bind_io(pybind11::module_& m);
void bind_multibody(pybind11::module_& m);
/// poinsot.multibody.System (bind_multibody_system.cpp), called by bind_multibody.
void bind_multibody_system(pybind11::module_& m);
void bind_view(pybind11::module_& m);
void bind_ensemble(pybind11::module_& m);
void bind_optimal(pybind11::module_& m);
/// poinsot.optimal's multibody problems; after bind_optimal (adds to its submodule).
void bind_optimal_multibody(pybind11::module_& m);

/// A TorqueModel calling the Python callable f(t, R, omega_body) -> (3,) (takes the GIL for each call).
std::shared_ptr<dynamics::TorqueModel> python_torque(pybind11::function f, bool depends_on_omega,
                                                     std::string description);
/// None → no torque, a TorqueModel as is, a callable → python_torque; anything else raises TypeError.
std::shared_ptr<dynamics::TorqueModel> as_torque(const pybind11::object& torque);
/// A State from keyword arguments (R or quaternion, omega_body); None means the default.
dynamics::State make_state(double t, const pybind11::object& R, const pybind11::object& quaternion,
                           const pybind11::object& omega_body);

}  // namespace poinsot::python
