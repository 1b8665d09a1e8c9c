#pragma once
// samples.h5: the per-sample table of `poinsot ensemble` in HDF5 (optional: built when CMake finds HDF5,
// POINSOT_HDF5=AUTO; Debian libhdf5-dev), readable with h5py: one dataset per column under /samples (index,
// rejected, repaired, moments (N, 3) kg·m², misalignment rad, omega0 (N, 3) rad/s, every output of
// ensemble/runner.hpp, quaternion_final (N, 4), omega_final (N, 3) rad/s), written to a temporary file and
// renamed.
#include <string>

#include "poinsot/ensemble/runner.hpp"

namespace poinsot::cli {

/// True when HDF5 support was built.
bool hdf5_available();

/// Writes the rows to `path` atomically. Throws ComputationFailed when HDF5 cannot write, InvalidInput when
/// HDF5 support was not built.
void write_ensemble_hdf5(const std::string& path, const ensemble::EnsembleResult& result);

}  // namespace poinsot::cli
