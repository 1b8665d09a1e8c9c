#pragma once
/// @file report_format.hpp
/// The number forms of the text reports and their summary lines: a physical quantity with a fixed number of
/// significant digits (6 unless stated), a vector as "(x, y, z)" of such numbers.

#include <string>
#include <string_view>
#include <vector>

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

/// The report's block of what a robot file states and the model leaves out (multibody::Scenario::
/// not_modelled), one indented line each, under "not modelled (the file states them; the `who` leaves them
/// out):"; empty when there is none.
inline std::string not_modelled_block(const std::vector<std::string>& lines, std::string_view who) {
  if (lines.empty()) return {};
  std::string out = fmt::format("  not modelled (the file states them; the {} leaves them out):\n", who);
  for (const std::string& line : lines)
    out += fmt::format("    - {}\n", line);
  return out;
}

}  // namespace poinsot::io::detail
