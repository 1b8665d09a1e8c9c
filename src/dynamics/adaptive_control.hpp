#pragma once
// Internal to the dynamics layer: the error norm, the step-size controller and the step loop (accept or
// reject, resume, minimum step) of Hairer's codes DOPRI5 and DOP853 (Hairer, Nørsett & Wanner, Solving ODEs
// I, 2nd ed., §II.4 and §II.5; the "PI" controller of Gustafsson with Hairer's default constants), shared by
// dopri5.cpp and dop853.cpp, which supply only their tableau (one attempt) and dense output.
#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/dynamics/integrator.hpp"

namespace poinsot::dynamics::detail {

/// The options an adaptive integrator needs: the first step dt (s) and the tolerances, all finite and > 0,
/// and the largest step max_step (s), > 0 or infinite (no limit). `method` names the integrator in the
/// message ("dopri5: rtol: got 0, expected a finite number > 0").
inline void require_adaptive_options(const std::string& method, const IntegratorOptions& options) {
  require_positive(method + ": dt", options.dt, "s");
  if (!(options.max_step > 0.0)) {
    throw InvalidInput(
        fmt::format("{}: max_step: got {} s, expected a number > 0 (infinity: no largest step)", method,
                    options.max_step));
  }
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

/// The step loop of an explicit embedded Runge–Kutta method with first-same-as-last on y = (q, ω): what
/// persists between steps (y, the controller, the resume check) and one accepted step.
struct AdaptiveLoop {
  AdaptiveLoop(std::string_view method_name, EulerRhs rhs, const IntegratorOptions& o, StepController c)
      : name(method_name), f(std::move(rhs)), opt(o), control(c) {
    require_adaptive_options(std::string(name), opt);
  }

  std::string_view name;  ///< for messages
  EulerRhs f;
  IntegratorOptions opt;
  Vec7 y = Vec7::Zero();  ///< the state reached, as the method integrates it
  bool fsal_valid = false;
  ResumeCheck resume;
  StepController control;

  /// One accepted step of at most min(dt, opt.max_step) s from `state`. `fsal` is the method's storage of
  /// f(t, y), the first stage, recomputed only when the state is not the one the last step produced; `y1`
  /// its storage of the attempt's result. `attempt(t, y, h)` computes y1 and returns the scaled error (≤ 1:
  /// accepted); `accept(t, y, h)`, called once per accepted step before y becomes y1, keeps what dense output
  /// needs and stores f(t + h, y1) in `fsal`. Rejected attempts are retried with the controller's smaller
  /// step. Throws InvalidInput for dt ≤ 0 and ComputationFailed when rejections shrink the step below
  /// 1e-14·max(1, |t|) s.
  template <class Attempt, class Accept>
  StepResult step(State& state, double dt, Vec7& fsal, const Vec7& y1, Attempt&& attempt, Accept&& accept) {
    if (!resume.matches(state)) {
      y = vec7_of(state);
      fsal_valid = false;
    }
    const double t = state.time;
    if (!fsal_valid) fsal = f(t, y);
    double h = std::min(dt, opt.max_step);
    if (!(h > 0.0)) {
      throw InvalidInput(fmt::format("{}: step dt = {} s at t = {} s; expected dt > 0", name, h, t));
    }
    int rejected = 0;
    for (;;) {
      if (rejected > 0 && !(h > 1e-14 * std::max(1.0, std::abs(t)))) {
        throw ComputationFailed(fmt::format(
            "{}: step size {:.3g} s too small at t = {} s after {} rejections; expected a step that "
            "meets rtol = {:.3g}, atol = {:.3g} (stiff or singular motion?)",
            name, h, t, rejected, opt.rtol, opt.atol));
      }
      const double err = attempt(t, std::as_const(y), h);
      if (err <= 1.0 && y1.allFinite()) {
        const double h_next = std::min(control.accept(h, err), opt.max_step);
        accept(t, std::as_const(y), h);
        y = y1;
        fsal_valid = accept_step(y, t + h, state, resume);
        return {h, h_next, rejected};
      }
      ++rejected;
      h = control.reject(h, err);
    }
  }
};

}  // namespace poinsot::dynamics::detail
