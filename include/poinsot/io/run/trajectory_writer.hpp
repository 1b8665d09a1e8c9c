#pragma once
/// @file trajectory_writer.hpp
/// The trajectory of a run as CSV, streamed: constant memory, whatever the number of rows.
///
/// Layout: one comment line (`# ...`, the units and frames), one line of column names, then one row per
/// sample:
///   t [s]; qw, qx, qy, qz [1], the unit quaternion of R (body → space, w ≥ 0); wx, wy, wz [rad/s], ω in the
///   body frame; energy [J], T + V (V = −m gᵀ R d with gravity, else 0); L_space_x..z [kg·m²/s], R J ω;
///   L_body_x..z [kg·m²/s], J ω.
/// Numbers are the shortest text that reads back to the same double.
///
/// Robustness: only whole rows are ever written to the file (line_file.hpp), so a run killed at any moment
/// leaves a file complete up to its last full row; flush() writes out every row.

#include <string>
#include <string_view>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/io/run/line_file.hpp"

namespace poinsot::io {

class TrajectoryCsvWriter {
 public:
  /// Creates (or truncates) `path` and writes the header. `gravity_space` (m/s²) enters the energy column.
  /// Throws InvalidInput if the file cannot be created.
  TrajectoryCsvWriter(const std::string& path, const dynamics::RigidBody& body, const Vec3& gravity_space);
  TrajectoryCsvWriter(const TrajectoryCsvWriter&) = delete;
  TrajectoryCsvWriter& operator=(const TrajectoryCsvWriter&) = delete;

  /// Appends the row of one sample.
  void write(const dynamics::State& sample);
  /// Hands every gathered row to the operating system. Throws ComputationFailed on a write error.
  void flush() { file_.flush(); }
  /// Rows written so far (not counting the header).
  long long rows() const { return file_.lines(); }
  const std::string& path() const { return file_.path(); }

  /// The column names, in order.
  static const std::vector<std::string>& columns();

 private:
  LineFile file_;  ///< flushed and closed on destruction (errors then ignored)
  const dynamics::RigidBody& body_;
  Vec3 gravity_space_;
};

}  // namespace poinsot::io
