#include "poinsot/io/scenario/torque_table.hpp"

#include <vector>

#include "csv_fields.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {

std::shared_ptr<const dynamics::TabulatedTorque> parse_torque_table(
    std::string_view text, std::string_view source, dynamics::TableInterpolation interpolation) {
  std::vector<double> time;
  std::vector<Vec3> torque;
  for (const std::vector<double>& v : detail::read_numeric_columns(text, source, {"t", "ux", "uy", "uz"})) {
    time.push_back(v[0]);
    torque.emplace_back(v[1], v[2], v[3]);
  }
  return std::make_shared<const dynamics::TabulatedTorque>(std::move(time), std::move(torque),
                                                           std::string(source), interpolation);
}

std::shared_ptr<const dynamics::TabulatedTorque> read_torque_table(
    const std::string& path, dynamics::TableInterpolation interpolation) {
  return parse_torque_table(detail::read_text_file(path), path, interpolation);
}

}  // namespace poinsot::io
