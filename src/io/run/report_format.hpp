#pragma once
/// @file report_format.hpp
/// The number forms of the text reports and their summary lines: a physical quantity with a fixed number of
/// significant digits (6 unless stated), a vector as "(x, y, z)" of such numbers.

#include <string>

#include <fmt/format.h>

#include "poinsot/core/format.hpp"
#include "poinsot/core/types.hpp"

namespace poinsot::io::detail {

/// `x` with `digits` significant digits ("%.{digits}g").
inline std::string report_number(double x, int digits = 6) {
  return format_number(x, digits);
}

/// "(x, y, z)", each entry as report_number.
inline std::string report_vector(const Vec3& v, int digits = 6) {
  return fmt::format("({}, {}, {})", report_number(v[0], digits), report_number(v[1], digits),
                     report_number(v[2], digits));
}

}  // namespace poinsot::io::detail
