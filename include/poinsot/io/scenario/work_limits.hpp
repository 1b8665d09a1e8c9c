#pragma once
/// @file work_limits.hpp
/// Limits on the work and the output of a run, checked when a scenario is read or overridden — before
/// anything runs or is written — so that no input makes poinsot run without end or write without bound:
///  * steps: t_end / dt (single body; for adaptive methods, whose tolerance sets the steps, a conservative
///    measure with dt their first step) or duration / dt (multibody), at most 1e9 (environment variable
///    POINSOT_MAX_STEPS raises it);
///  * samples (trajectory rows, hence the output size): t_end / sample_dt (single body) or
///    steps / output_every (multibody), at most 1e7 (POINSOT_MAX_SAMPLES).
#include <string_view>

namespace poinsot::io {

struct WorkLimits {
  double max_steps = 1e9;
  double max_samples = 1e7;
};

/// The defaults, or the positive numbers in POINSOT_MAX_STEPS and POINSOT_MAX_SAMPLES when they are set.
WorkLimits work_limits();

/// Throws InvalidInput `WHAT: RATIO = N steps; the limit is M (raise it with the environment variable
/// POINSOT_MAX_STEPS)` when `steps` (a number, not necessarily finite) exceeds work_limits().max_steps.
/// `ratio` names the quotient, e.g. "t_end / dt".
void check_step_count(double steps, std::string_view what, std::string_view ratio);

/// The same for a number of samples (POINSOT_MAX_SAMPLES).
void check_sample_count(double samples, std::string_view what, std::string_view ratio);

}  // namespace poinsot::io
