#pragma once
// Declarations of the per-layer binding functions of poinsot._core.
#include <pybind11/pybind11.h>

namespace poinsot::python {

void bind_so3(pybind11::module_& m);

}  // namespace poinsot::python
