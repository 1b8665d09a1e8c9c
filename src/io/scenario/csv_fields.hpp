#pragma once
/// @file csv_fields.hpp (internal)
/// The fields of one line of the CSV tables the io layer reads (torque tables, reference trajectories):
/// comma-separated, each trimmed of spaces and tabs (and a trailing carriage return).
#include <initializer_list>
#include <string_view>
#include <vector>

namespace poinsot::io::detail {

inline std::string_view csv_trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return s;
}

/// The trimmed fields of `line`, split at every comma (an empty line gives one empty field).
inline std::vector<std::string_view> csv_split(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= line.size(); ++i)
    if (i == line.size() || line[i] == ',') {
      out.push_back(csv_trim(line.substr(start, i - start)));
      start = i + 1;
    }
  return out;
}

/// The numbers of a CSV table whose header line starts with `columns` (further columns are allowed and
/// ignored): one row per data line, the values of those columns in order. Blank lines and `#` comments are
/// skipped. Throws InvalidInput naming `source` and the line for a header without those columns first, a
/// row with fewer values, a value that is not a number, or no header at all.
std::vector<std::vector<double>> read_numeric_columns(std::string_view text, std::string_view source,
                                                      std::initializer_list<const char*> columns);

}  // namespace poinsot::io::detail
