#include "poinsot/io/scenario/reference_trajectory.hpp"

#include <vector>

#include "csv_fields.hpp"
#include "toml_fields.hpp"

namespace poinsot::io {
ensemble::ReferenceRows parse_reference_trajectory(std::string_view text, std::string_view source) {
  ensemble::ReferenceRows rows;
  for (const std::vector<double>& v : detail::read_numeric_columns(
           text, source, {"t", "qw", "qx", "qy", "qz", "wx", "wy", "wz", "ux", "uy", "uz"})) {
    rows.time.push_back(v[0]);
    rows.attitude.emplace_back(v[1], v[2], v[3], v[4]);
    rows.omega.emplace_back(v[5], v[6], v[7]);
    rows.torque.emplace_back(v[8], v[9], v[10]);
  }
  return rows;
}

ensemble::ReferenceRows read_reference_trajectory(const std::string& path) {
  return parse_reference_trajectory(detail::read_text_file(path), path);
}

}  // namespace poinsot::io
