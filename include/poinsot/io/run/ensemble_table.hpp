#pragma once
/// @file ensemble_table.hpp
/// The one list of the columns of an ensemble's per-sample table, from which both samples.csv
/// (io::ensemble_csv) and samples.h5 (the command line's HDF5 writer, `/samples/<dataset>`) are written: each
/// column group has its HDF5 dataset name, the CSV names of its components and their values for a sample.
///
/// The groups, in order: index, rejected, repaired (integers); moments I1, I2, I3 (kg·m², principal, about
/// the centre of mass); misalignment (rad); omega0 (rad/s, body frame); one column per ensemble output
/// (ensemble::kOutputNames, its units in ensemble::kOutputUnits); quaternion_final q_w, q_x, q_y, q_z (body →
/// space); omega_final (rad/s, body frame).
#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "poinsot/ensemble/runner.hpp"

namespace poinsot::io {

/// A group of columns of the per-sample table.
struct SampleColumn {
  enum class Kind { unsigned_integer, integer, real };
  std::string dataset;                 ///< the HDF5 dataset under /samples
  std::vector<std::string> csv_names;  ///< the CSV header's names of its components (1 to 4)
  Kind kind = Kind::real;
  /// The components' values for a sample, for Kind::integer (small counts, exact as doubles) and Kind::real.
  std::array<double, 4> (*values)(const ensemble::SampleRow& row) = nullptr;
  /// The unsigned integer of a Kind::unsigned_integer column (the sample's index, any 64-bit value).
  std::uint64_t (*index)(const ensemble::SampleRow& row) = nullptr;
};

/// Every column group, in the order of the CSV header and of the HDF5 datasets.
std::span<const SampleColumn> sample_columns();

}  // namespace poinsot::io
