#pragma once
// The MPI driver of `poinsot ensemble` (optional: built when CMake finds MPI, POINSOT_MPI=AUTO). Under mpirun
// each rank runs a contiguous range of blocks of samples (ensemble::run_ensemble_blocks); rank 0 gathers the
// complete subtrees of their block statistics (O(log blocks) a rank) and merges them in the fixed tree over
// the block indices (ensemble::set_statistics, block_merge.hpp), so the statistics are those of one
// process bit for bit, and gathers the rows (per-sample output on) in index order. Only rank 0 writes files.
#include <vector>

#include "poinsot/ensemble/runner.hpp"

namespace poinsot::cli {

/// True when MPI support was built and this process was started by an MPI launcher (OMPI_COMM_WORLD_SIZE or
/// PMI_SIZE in the environment).
bool mpi_launched();

/// Initialises MPI on construction (when launched) and finalises it on destruction.
class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;
  int rank() const { return rank_; }
  int size() const { return size_; }

 private:
  int rank_ = 0, size_ = 1;
  bool active_ = false;
};

/// Runs this rank's share and returns, on rank 0, the whole result (statistics merged in the block tree, rows
/// in index order, body steps summed, wall time the longest rank's); on other ranks their share only.
/// With `own_rows` (per-rank files): the rows are not gathered but moved to *own_rows on every rank, and the
/// percentiles of the result come from quantile sketches of each rank's rows (quantile_sketch.hpp), merged
/// on rank 0; the result's rows are then empty.
ensemble::EnsembleResult run_ensemble_mpi(const MpiSession& session, const ensemble::Sampler& sampler,
                                          const ensemble::EnsembleOptions& options,
                                          std::vector<ensemble::SampleRow>* own_rows = nullptr);

}  // namespace poinsot::cli
