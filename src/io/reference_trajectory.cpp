#include "poinsot/io/reference_trajectory.hpp"

#include <charconv>
#include <vector>

#include <fmt/format.h>

#include "csv_fields.hpp"
#include "poinsot/core/error.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
namespace {

constexpr int kColumnCount = 11;
constexpr const char* kColumns[kColumnCount] = {"t",  "qw", "qx", "qy", "qz", "wx",
                                                "wy", "wz", "ux", "uy", "uz"};
constexpr const char* kHeader = "t,qw,qx,qy,qz,wx,wy,wz,ux,uy,uz";

}  // namespace

ensemble::ReferenceRows parse_reference_trajectory(std::string_view text, std::string_view source) {
  ensemble::ReferenceRows rows;
  bool header = false;
  int line_no = 0;
  std::size_t pos = 0;
  while (pos < text.size()) {
    const std::size_t end = std::min(text.find('\n', pos), text.size());
    const std::string_view line = detail::csv_trim(text.substr(pos, end - pos));
    pos = end + 1;
    ++line_no;
    if (line.empty() || line.front() == '#') continue;
    const std::vector<std::string_view> cols = detail::csv_split(line);
    if (!header) {
      for (int i = 0; i < kColumnCount; ++i)
        if (static_cast<int>(cols.size()) <= i || cols[i] != kColumns[i])
          throw InvalidInput(fmt::format("{}: line {}: header \"{}\"; expected the columns {} first", source,
                                         line_no, line, kHeader));
      header = true;
      continue;
    }
    if (cols.size() < kColumnCount)
      throw InvalidInput(
          fmt::format("{}: line {}: {} values; expected {}", source, line_no, cols.size(), kHeader));
    double v[kColumnCount];
    for (int i = 0; i < kColumnCount; ++i) {
      const auto [p, ec] = std::from_chars(cols[i].data(), cols[i].data() + cols[i].size(), v[i]);
      if (ec != std::errc() || p != cols[i].data() + cols[i].size())
        throw InvalidInput(
            fmt::format("{}: line {}: {} = \"{}\" is not a number", source, line_no, kColumns[i], cols[i]));
    }
    rows.time.push_back(v[0]);
    rows.attitude.emplace_back(v[1], v[2], v[3], v[4]);
    rows.omega.emplace_back(v[5], v[6], v[7]);
    rows.torque.emplace_back(v[8], v[9], v[10]);
  }
  if (!header)
    throw InvalidInput(
        fmt::format("{}: no header line; expected a table with the columns {}", source, kHeader));
  return rows;
}

ensemble::ReferenceRows read_reference_trajectory(const std::string& path) {
  return parse_reference_trajectory(detail::read_text_file(path), path);
}

}  // namespace poinsot::io
