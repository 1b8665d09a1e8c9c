// Reading a run folder's CSV files for view.html (see view_data.hpp).
#include "view_data.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/rigid_body.hpp"

namespace poinsot::io {
namespace {

std::ifstream open_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in)
    throw InvalidInput(
        fmt::format("view: cannot read \"{}\"; expected the CSV file of a finished run", path));
  return in;
}

/// Skips the `#` comment lines and returns the names line split at commas.
std::vector<std::string> read_header(std::ifstream& in, const std::string& path) {
  std::string line;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '#') continue;
    std::vector<std::string> names;
    std::size_t start = 0;
    while (true) {
      const std::size_t comma = line.find(',', start);
      names.push_back(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    return names;
  }
  throw InvalidInput(
      fmt::format("view: \"{}\" has no line of column names; expected the CSV file of a run", path));
}

}  // namespace

double rounded_for_drawing(double x) {
  char buf[40];
  const auto end = fmt::format_to_n(buf, sizeof buf, "{:.{}g}", x, kViewDrawDigits).out;
  double r = 0.0;
  std::from_chars(buf, end, r);
  return r;
}

std::size_t csv_column(const CsvFrames& f, const std::string& name, const std::string& path) {
  for (std::size_t i = 0; i < f.columns.size(); ++i)
    if (f.columns[i] == name) return i;
  throw InvalidInput(
      fmt::format("view: \"{}\" has no column \"{}\"; expected the trajectory of a run", path, name));
}

std::vector<long long> frame_rows(long long rows, int max_frames) {
  std::vector<long long> kept;
  if (rows <= 0) return kept;
  if (rows <= max_frames) {
    for (long long i = 0; i < rows; ++i)
      kept.push_back(i);
    return kept;
  }
  const long long stride = (rows - 1 + max_frames - 2) / (max_frames - 1);  // ceil((n − 1)/(F − 1))
  for (long long i = 0; i < rows; i += stride)
    kept.push_back(i);
  if (kept.back() != rows - 1) kept.push_back(rows - 1);
  return kept;
}

long long count_csv_rows(const std::string& path) {
  std::ifstream in = open_csv(path);
  read_header(in, path);
  long long rows = 0;
  std::string line;
  while (std::getline(in, line))
    if (!line.empty()) ++rows;
  return rows;
}

CsvFrames read_csv_frames(const std::string& path, int max_frames) {
  CsvFrames f;
  f.rows = count_csv_rows(path);
  const std::vector<long long> kept = frame_rows(f.rows, max_frames);
  f.stride = kept.size() >= 2 ? kept[1] - kept[0] : 1;
  std::ifstream in = open_csv(path);
  f.columns = read_header(in, path);
  std::string line;
  long long row = 0;
  std::size_t next = 0;
  while (next < kept.size() && std::getline(in, line)) {
    if (line.empty()) continue;
    if (row++ != kept[next]) continue;
    ++next;
    std::vector<double> v;
    v.reserve(f.columns.size());
    const char* p = line.data();
    const char* end = p + line.size();
    while (p <= end && v.size() < f.columns.size()) {
      double x = 0.0;
      const auto [q, ec] = std::from_chars(p, end, x);
      if (ec != std::errc() || (q != end && *q != ',')) {
        throw InvalidInput(
            fmt::format("view: {} row {}: column {} (\"{}\") is not a number; expected a run's CSV", path,
                        row, v.size() + 1, f.columns[v.size()]));
      }
      v.push_back(x);
      p = q + 1;
    }
    if (v.size() != f.columns.size()) {
      throw InvalidInput(fmt::format("view: {} row {} has {} numbers; expected {} (one per column)", path,
                                     row, v.size(), f.columns.size()));
    }
    f.values.push_back(std::move(v));
  }
  return f;
}

EquivalentShapes equivalent_shapes(const Mat3& inertia_com, double mass) {
  const dynamics::RigidBody body = dynamics::RigidBody::from_inertia(inertia_com);
  const Vec3 I = body.principal_moments();
  const double half_trace = 0.5 * I.sum();
  EquivalentShapes s;
  s.axes = body.principal_axes();
  for (int i = 0; i < 3; ++i) {
    const double k = std::max(half_trace - I[i], 0.0);  // eigenvalue of K (≥ 0 up to round-off)
    s.box_half_extents[i] = std::sqrt(3.0 * k / mass);
    s.ellipsoid_semi_axes[i] = std::sqrt(5.0 * k / mass);
  }
  return s;
}

}  // namespace poinsot::io
