// The CSV tables the io layer reads (csv_fields.hpp).
#include "csv_fields.hpp"

#include <algorithm>
#include <charconv>
#include <string>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::io::detail {

std::vector<std::vector<double>> read_numeric_columns(std::string_view text, std::string_view source,
                                                      std::initializer_list<const char*> columns) {
  const std::vector<const char*> names(columns);
  const std::size_t n = names.size();
  std::string header_text;
  for (const char* c : names)
    header_text.append(header_text.empty() ? "" : ",").append(c);
  std::vector<std::vector<double>> rows;
  bool header = false;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = csv_trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> cols = csv_split(line);
    if (!header) {
      for (std::size_t i = 0; i < n; ++i)
        if (cols.size() <= i || cols[i] != names[i])
          throw InvalidInput(fmt::format("{}: line {}: header \"{}\"; expected the columns {} first", source,
                                         line_no, line, header_text));
      header = true;
      continue;
    }
    if (cols.size() < n)
      throw InvalidInput(
          fmt::format("{}: line {}: {} values; expected {}", source, line_no, cols.size(), header_text));
    std::vector<double>& v = rows.emplace_back(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto [p, ec] = std::from_chars(cols[i].data(), cols[i].data() + cols[i].size(), v[i]);
      if (ec != std::errc() || p != cols[i].data() + cols[i].size())
        throw InvalidInput(
            fmt::format("{}: line {}: {} = \"{}\" is not a number", source, line_no, names[i], cols[i]));
    }
  }
  if (!header)
    throw InvalidInput(
        fmt::format("{}: no header line; expected a table with the columns {}", source, header_text));
  return rows;
}

}  // namespace poinsot::io::detail
