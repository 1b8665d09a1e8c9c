#include "poinsot/dynamics/integrator.hpp"

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::dynamics {

State Integrator::dense_output(double t) const {
  throw InvalidInput(
      fmt::format("{}: no dense output (asked for t = {} s); expected an adaptive method such as "
                  "dopri5 or dop853",
                  name(), t));
}

bool Integrator::last_multiplier(Mat3&) const {
  return false;
}

}  // namespace poinsot::dynamics
