#pragma once
// Internal to the ensemble layer: the two batched kernels behind run_batch (batch.hpp). Each advances up to
// kBatchLanes samples by n equal steps to t_end; `avx2` selects the AVX2 compilation of the same loops.
#include <span>

#include "poinsot/ensemble/batch.hpp"

namespace poinsot::ensemble::detail {

void run_rk4_batch(std::span<const Sample> samples, double t_end, long long n, bool avx2,
                   std::span<LaneResult> results);
void run_dlm_batch(std::span<const Sample> samples, double t_end, long long n, bool avx2,
                   std::span<LaneResult> results);

}  // namespace poinsot::ensemble::detail
