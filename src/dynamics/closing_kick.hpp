#pragma once
// The implicit closing half-kick shared by the splitting (dlm) and variational (rattle) methods under a
// torque that depends on ω: Π = Π₋ + (h/2) τ(t + h, R, ω(Π)) (body or principal frame, as the caller's Π,
// kg·m²/s), solved by fixed-point iteration. The iteration contracts when (h/2)‖∂τ/∂Π‖ < 1, i.e. for steps
// small against the torque's own time scale.
#include <algorithm>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/types.hpp"

namespace poinsot::dynamics::detail {

/// Iterates Π ← Π₋ + (h/2)·torque(Π) from `pi` (the explicit kick) until the change is at most
/// tolerance·|Π|, and returns Π. `torque(Π)` gives τ at the end of the step (t_end, s). Throws
/// ComputationFailed naming `method` and t_end when `max_iterations` are exceeded or the change is not
/// finite.
template <class Torque>
Vec3 iterate_closing_kick(std::string_view method, const Vec3& pi_minus, Vec3 pi, double h, double t_end,
                          double tolerance, int max_iterations, Torque&& torque) {
  for (int it = 0;; ++it) {
    const Vec3 next = pi_minus + (0.5 * h) * torque(pi);
    const double change = (next - pi).norm();
    pi = next;
    if (change <= tolerance * std::max(pi.norm(), 1e-300)) return pi;
    if (it >= max_iterations || !std::isfinite(change)) {
      throw ComputationFailed(
          fmt::format("{}: the closing torque kick did not converge at t = {} s after {} iterations (change "
                      "{:.3g} kg·m²/s); "
                      "expected a smaller step for this ω-dependent torque",
                      method, t_end, it, change));
    }
  }
}

}  // namespace poinsot::dynamics::detail
