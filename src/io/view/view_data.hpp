#pragma once
/// @file view_data.hpp
/// Reading a finished run folder for view.html (view_page.hpp): the rows of trajectory.csv kept as frames,
/// and the equivalent shapes of a body. Internal to the io layer.

#include <string>
#include <vector>

#include "poinsot/core/types.hpp"

namespace poinsot::io {

/// The rows of a CSV file kept as frames: every row when there are at most `max_frames`, otherwise rows 0,
/// k, 2k, ... and the last, with k = ceil((n − 1)/(max_frames − 1)), so at most `max_frames` rows.
struct CsvFrames {
  std::vector<std::string> columns;         ///< the names line
  long long rows = 0;                       ///< rows in the file
  long long stride = 1;                     ///< k
  std::vector<std::vector<double>> values;  ///< per kept row, one number per column
};

/// Significant digits of the numbers the page only draws (multipliers, surfaces): three.js draws in single
/// precision (7 digits), and 9 digits take half the text of a shortest round-trip double.
inline constexpr int kViewDrawDigits = 9;

/// `x` rounded to kViewDrawDigits significant digits: the double nearest to that decimal, whose shortest
/// text has at most that many digits.
double rounded_for_drawing(double x);

/// The index of the column `name` of `f` (read from `path`); InvalidInput naming the column when absent.
std::size_t csv_column(const CsvFrames& f, const std::string& name, const std::string& path);

/// Indices of the rows kept out of `rows` for at most `max_frames` frames (see CsvFrames).
std::vector<long long> frame_rows(long long rows, int max_frames);

/// Counts the rows of `path` (lines after the `#` comment and the names line). Throws InvalidInput when it
/// cannot be read.
long long count_csv_rows(const std::string& path);

/// Reads the kept rows of `path`. Throws InvalidInput on a missing file, a short row or a non-number.
CsvFrames read_csv_frames(const std::string& path, int max_frames);

/// The uniform box and the uniform ellipsoid of mass `mass` (kg) whose inertia about their centre is
/// `inertia_com` (J, body frame, kg·m²): the Poinsot tensor K = tr(J)/2·I − J has eigenvalues k_i along the
/// principal axes, and a box of half-edges h_i has k_i = m h_i²/3, an ellipsoid of semi-axes a_i has
/// k_i = m a_i²/5.
struct EquivalentShapes {
  Vec3 box_half_extents = Vec3::Zero();     ///< m
  Vec3 ellipsoid_semi_axes = Vec3::Zero();  ///< m
  Mat3 axes = Mat3::Identity();             ///< columns: the principal axes in the body frame (det = +1)
};
EquivalentShapes equivalent_shapes(const Mat3& inertia_com, double mass);

}  // namespace poinsot::io
