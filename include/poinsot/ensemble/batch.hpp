#pragma once
/// @file batch.hpp
/// Batched integrators: `rk4` and `dlm` advance kBatchLanes samples at once, their states stored as
/// structures of arrays (one array per component, one entry per sample) so that every operation of a step is
/// a loop over the lanes that the compiler vectorises (AVX2 when the CPU has it, SSE2 otherwise; chosen at
/// run time, or forced off).
///
/// The mathematics is that of the scalar integrators (dynamics/rk4.hpp, dynamics/dlm.hpp) with the same
/// operations in the same order for each lane, compiled without floating-point contraction (no FMA): a lane's
/// result is bit-for-bit that of the scalar integrator stepping the same body with the same steps whenever
/// the scalar one takes its principal-frame path — always for `dlm`; for `rk4` when the body frame is the
/// principal frame (no misalignment of the axes). A misaligned `rk4` sample is integrated in its principal
/// frame (R P, Pᵀω), which the scalar rk4 does not do: the results agree to the method's error, not bit for
/// bit. Whatever the SIMD width or the batch a sample lands in, its result is the same (lanes do not
/// interact).
///
/// Supported: free bodies (no pivot) under no torque or a constant torque in the body frame or in space (the
/// latter rotated into the principal frame at every evaluation, with the scalar integrators' arithmetic; one
/// kind of torque per batch). Gravity (tops) runs through the scalar integrators (ensemble/runner.hpp).
///
/// Steps: [0, t_end] in n = ⌈t_end/dt − 10⁻⁹⌉ equal steps h = t_end/n, as dynamics::simulate takes them for
/// one sample interval. Each step tests the intermediate-axis component s = I₂ ω₂ of the body momentum
/// (principal frame, I₂ the median moment) for a sign change and locates the first two flips by the cubic
/// Hermite interpolant of dynamics::FlipDetector.
#include <cstdint>
#include <limits>
#include <span>
#include <string>
#include <string_view>

#include "poinsot/dynamics/state.hpp"
#include "poinsot/ensemble/sampler.hpp"

namespace poinsot::ensemble {

inline constexpr int kBatchLanes = 32;

enum class Simd {
  automatic,  ///< AVX2 when the CPU has it, else the portable loops
  off,        ///< the portable loops only (same results, bit for bit)
};

/// The end of one sample's run in a batch.
struct LaneResult {
  dynamics::State final_state;
  double first_flip = std::numeric_limits<double>::quiet_NaN();   ///< s, NaN: none
  double second_flip = std::numeric_limits<double>::quiet_NaN();  ///< s, NaN: fewer than two flips
  long long flips = 0;
};

/// The names of the methods that have a batched kernel, "rk4 or dlm" (the last two joined by
/// `last_separator`).
std::string batched_method_names(std::string_view last_separator = " or ");

/// True when `method` has a batched kernel (batched_method_names()) and the sample is a free body under no
/// torque or a constant torque in the body frame or in space.
bool batchable(std::string_view method, const Sample& sample);

/// The number of steps n = ⌈t_end/dt − 10⁻⁹⌉ (at least 1) of a run to t_end with nominal step dt (s).
long long batch_step_count(double t_end, double dt);

/// Advances up to kBatchLanes samples (all batchable with `method`) from t = 0 to t_end (s) with nominal step
/// dt (s) and writes one LaneResult each. Throws InvalidInput for an unsupported method or sample, a bad
/// t_end or dt, more than kBatchLanes samples, or body-frame and space-frame torques in one batch.
void run_batch(std::string_view method, std::span<const Sample> samples, double t_end, double dt, Simd simd,
               std::span<LaneResult> results);

/// True when this CPU runs the AVX2 path under Simd::automatic.
bool simd_available();

}  // namespace poinsot::ensemble
