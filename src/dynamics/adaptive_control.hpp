#pragma once
// Internal to the dynamics layer: the error norm and the step-size controller of Hairer's codes DOPRI5 and
// DOP853 (Hairer, Nørsett & Wanner, Solving ODEs I, 2nd ed., §II.4 and §II.5; the "PI" controller of
// Gustafsson with Hairer's default constants), shared by dopri5.cpp and dop853.cpp.
#include <algorithm>
#include <cmath>

#include <string>

#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics::detail {

/// The options an adaptive integrator needs: the largest step dt (s) and the tolerances, all > 0. `method`
/// names the integrator in the message ("dopri5: rtol: got 0, expected a number > 0").
inline void require_adaptive_options(const std::string& method, const IntegratorOptions& options) {
  require_positive(method + ": dt", options.dt, "s");
  require_positive(method + ": rtol", options.rtol);
  require_positive(method + ": atol", options.atol);
}

/// Componentwise scale sk_i = atol + rtol · max(|y0_i|, |y1_i|).
inline Vec7 error_scale(const Vec7& y0, const Vec7& y1, double rtol, double atol) {
  return Vec7::Constant(atol) + rtol * y0.cwiseAbs().cwiseMax(y1.cwiseAbs());
}

/// Step-size controller: h_new = h / clamp(err^expo / err_old^beta / safe, 1/grow_max, 1/shrink_max).
struct StepController {
  double expo;        // 1/(q+1) − 0.75 β for the error estimator of order q
  double beta;        // PI stabilisation (0.04 for DOPRI5, 0 for DOP853)
  double grow_max;    // largest factor of increase (10 for DOPRI5, 6 for DOP853)
  double shrink_max;  // largest factor of decrease (5 for DOPRI5, 1/0.333 for DOP853)
  double safe = 0.9;
  double err_old = 1e-4;
  bool last_rejected = false;

  /// The next step after accepting a step h with scaled error err ≤ 1.
  double accept(double h, double err) {
    const double fac11 = std::pow(err, expo);
    double fac = fac11 / std::pow(err_old, beta) / safe;
    fac = std::clamp(fac, 1.0 / grow_max, shrink_max);
    err_old = std::max(err, 1e-4);
    double h_new = h / fac;
    if (last_rejected) h_new = std::min(h_new, h);
    last_rejected = false;
    return h_new;
  }
  /// The retry after rejecting a step h with scaled error err > 1 (or not finite).
  double reject(double h, double err) {
    last_rejected = true;
    if (!std::isfinite(err)) return h / shrink_max;
    return h / std::min(shrink_max, std::pow(err, expo) / safe);
  }
};

}  // namespace poinsot::dynamics::detail
