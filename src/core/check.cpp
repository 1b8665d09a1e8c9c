#include "poinsot/core/check.hpp"

#include <cmath>
#include <string>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot {
namespace {
std::string with_unit(double value, std::string_view unit) {
  return unit.empty() ? format_number(value) : fmt::format("{} {}", value, unit);
}
}  // namespace

void require_finite(std::string_view what, double value) {
  if (!std::isfinite(value))
    throw InvalidInput(fmt::format("{}: got {}, expected a finite number", what, value));
}

void require_finite(std::string_view what, const Vec3& v) {
  if (!v.allFinite()) {
    throw InvalidInput(fmt::format("{}: got {}, expected finite numbers", what, format_vector(v)));
  }
}

void require_finite(std::string_view what, const Mat3& m) {
  if (!m.allFinite()) {
    throw InvalidInput(fmt::format("{}: got {}, expected finite numbers", what, format_matrix(m)));
  }
}

void require_finite(std::string_view what, const Quat& q) {
  if (!q.coeffs().allFinite()) {
    throw InvalidInput(fmt::format("{}: got {}, expected finite numbers", what, format_quaternion(q)));
  }
}

void require_positive(std::string_view what, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InvalidInput(fmt::format("{}: got {}, expected a finite number > 0", what, with_unit(value, unit)));
  }
}

void require_non_negative(std::string_view what, double value, std::string_view unit) {
  if (!(std::isfinite(value) && value >= 0.0)) {
    throw InvalidInput(
        fmt::format("{}: got {}, expected a finite number >= 0", what, with_unit(value, unit)));
  }
}

}  // namespace poinsot
