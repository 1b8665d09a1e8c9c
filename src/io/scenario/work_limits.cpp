#include "poinsot/io/scenario/work_limits.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::io {
namespace {

double from_environment(const char* name, double fallback) {
  const char* env = std::getenv(name);
  if (env == nullptr || *env == '\0') return fallback;
  char* end = nullptr;
  const double v = std::strtod(env, &end);
  return (end != nullptr && *end == '\0' && std::isfinite(v) && v > 0.0) ? v : fallback;
}

void check_count(double count, double limit, std::string_view what, std::string_view ratio, const char* unit,
                 const char* variable) {
  if (count <= limit) return;  // NaN cannot occur: the quotients are of positive finite numbers
  throw InvalidInput(
      fmt::format("{}: {} = {} {}; the limit is {} (raise it with the environment variable {})", what, ratio,
                  format_number(count, 6), unit, format_number(limit, 6), variable));
}

}  // namespace

WorkLimits work_limits() {
  WorkLimits w;
  w.max_steps = from_environment("POINSOT_MAX_STEPS", w.max_steps);
  w.max_samples = from_environment("POINSOT_MAX_SAMPLES", w.max_samples);
  return w;
}

void check_step_count(double steps, std::string_view what, std::string_view ratio) {
  check_count(steps, work_limits().max_steps, what, ratio, "steps", "POINSOT_MAX_STEPS");
}

void check_sample_count(double samples, std::string_view what, std::string_view ratio) {
  check_count(samples, work_limits().max_samples, what, ratio, "samples", "POINSOT_MAX_SAMPLES");
}

}  // namespace poinsot::io
