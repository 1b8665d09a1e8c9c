#include "poinsot/io/torque_table.hpp"

#include <charconv>
#include <vector>

#include <fmt/format.h>

#include "csv_fields.hpp"
#include "poinsot/core/error.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {

std::shared_ptr<const dynamics::TabulatedTorque> parse_torque_table(
    std::string_view text, std::string_view source, dynamics::TableInterpolation interpolation) {
  static constexpr const char* kColumns[] = {"t", "ux", "uy", "uz"};
  std::vector<double> time;
  std::vector<Vec3> torque;
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
      for (int i = 0; i < 4; ++i)
        if (static_cast<int>(cols.size()) <= i || cols[i] != kColumns[i])
          throw InvalidInput(fmt::format("{}: line {}: header \"{}\"; expected the columns t,ux,uy,uz first",
                                         source, line_no, line));
      header = true;
      continue;
    }
    if (cols.size() < 4)
      throw InvalidInput(
          fmt::format("{}: line {}: {} values; expected t,ux,uy,uz", source, line_no, cols.size()));
    double v[4];
    for (int i = 0; i < 4; ++i) {
      const auto [p, ec] = std::from_chars(cols[i].data(), cols[i].data() + cols[i].size(), v[i]);
      if (ec != std::errc() || p != cols[i].data() + cols[i].size())
        throw InvalidInput(
            fmt::format("{}: line {}: {} = \"{}\" is not a number", source, line_no, kColumns[i], cols[i]));
    }
    time.push_back(v[0]);
    torque.emplace_back(v[1], v[2], v[3]);
  }
  if (!header)
    throw InvalidInput(
        fmt::format("{}: no header line; expected a table with the columns t,ux,uy,uz", source));
  return std::make_shared<const dynamics::TabulatedTorque>(std::move(time), std::move(torque),
                                                           std::string(source), interpolation);
}

std::shared_ptr<const dynamics::TabulatedTorque> read_torque_table(
    const std::string& path, dynamics::TableInterpolation interpolation) {
  return parse_torque_table(detail::read_text_file(path), path, interpolation);
}

}  // namespace poinsot::io
