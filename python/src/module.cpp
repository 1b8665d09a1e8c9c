// The extension module poinsot._core. Each layer's bindings live in bind_<layer>.cpp.
#include <pybind11/pybind11.h>

#include "bindings.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/version.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "poinsot compiled core (see the poinsot package)";
  m.attr("__version__") = poinsot::kVersion;
  // Every poinsot::Error becomes ValueError with the same message.
  pybind11::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const poinsot::Error& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    }
  });
  poinsot::python::bind_so3(m);
  poinsot::python::bind_dynamics(m);
  poinsot::python::bind_inertia(m);
  poinsot::python::bind_simulate(m);
  poinsot::python::bind_analysis(m);
  poinsot::python::bind_io(m);
  poinsot::python::bind_multibody(m);
  poinsot::python::bind_view(m);
  poinsot::python::bind_ensemble(m);
  poinsot::python::bind_optimal(m);
  poinsot::python::bind_optimal_multibody(m);
}
