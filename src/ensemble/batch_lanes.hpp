#pragma once
// Internal to the ensemble layer: what the batched rk4 and dlm kernels share: the lane count, the flip
// tracker over lanes, the torque mode of a batch, and the dispatch between the AVX2 and the portable
// compilation of a kernel.
#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "poinsot/dynamics/flip_events.hpp"
#include "poinsot/ensemble/batch.hpp"

namespace poinsot::ensemble::detail {

constexpr int B = kBatchLanes;
using Lanes = double[B];

/// The first two sign changes of s = Σᵢ eᵢ ωᵢ per lane (eᵢ = I₂ on the intermediate principal axis, else 0).
struct FlipLanes {
  alignas(64) double e[3][B];  // weights
  alignas(64) double s[B];     // s at the start of the step
  alignas(64) double r[B];     // ṡ at the start of the step
  double first[B], second[B];
  long long count[B];
};

/// s of each lane from ω (principal frame), vectorisable.
inline __attribute__((always_inline)) void flip_component(const FlipLanes& f, const double* w0,
                                                          const double* w1, const double* w2, double* s) {
  for (int l = 0; l < B; ++l)
    s[l] = f.e[0][l] * w0[l] + f.e[1][l] * w1[l] + f.e[2][l] * w2[l];
}

/// Records the sign changes between f.s (at t0) and s1 (at t1) with rates f.r and r1, then moves s1, r1 into
/// f. The test over the lanes vectorises; the root finding runs only for a step in which some lane flipped.
inline __attribute__((always_inline)) void advance_flips(FlipLanes& f, const double* s1, const double* r1,
                                                         double t0, double t1, int lanes) {
  // A vectorisable prefilter: every sign change has s0·s1 <= 0 (an underflow to 0 only costs a scalar pass).
  int any = 0;
  for (int l = 0; l < B; ++l)
    any |= static_cast<int>(f.s[l] * s1[l] <= 0.0);
  if (any) {
    for (int l = 0; l < lanes; ++l) {
      if (dynamics::FlipDetector::sign_change(f.s[l], s1[l])) {
        const double t = dynamics::FlipDetector::hermite_root(t0, t1, f.s[l], s1[l], f.r[l], r1[l]);
        if (f.count[l] == 0) f.first[l] = t;
        if (f.count[l] == 1) f.second[l] = t;
        ++f.count[l];
      }
    }
  }
  for (int l = 0; l < B; ++l) {
    f.s[l] = s1[l];
    f.r[l] = r1[l];
  }
}

/// Sets the weights of one lane: the median of the principal moments (kg·m²) on its axis; zero weights (no
/// flips) when two moments agree to 1e-12 of the largest, as dynamics::FlipDetector decides.
inline void set_flip_weights(FlipLanes& f, int lane, const double I[3]) {
  int idx[3] = {0, 1, 2};
  std::sort(idx, idx + 3, [&](int a, int b) { return I[a] < I[b] || (I[a] == I[b] && a < b); });
  const int m = idx[1];
  const double top = std::max({I[0], I[1], I[2]});
  const double lo = std::min({I[0], I[1], I[2]});
  const bool distinct = I[m] - lo > 1e-12 * top && top - I[m] > 1e-12 * top;
  for (int i = 0; i < 3; ++i)
    f.e[i][lane] = (distinct && i == m) ? I[m] : 0.0;
  f.count[lane] = 0;
  f.first[lane] = f.second[lane] = std::numeric_limits<double>::quiet_NaN();
}

/// The torque on the lanes of a batch: none, constant in the body frame, or constant in space (then the
/// kernels rotate it into the principal frame at every evaluation).
enum class TorqueMode { free, body, space };

/// The torque mode of a batch: space when any lane has a space-frame torque, body when any has a body-frame
/// one (torque-free lanes take the torqued path with a zero torque). Throws InvalidInput for a batch with
/// both.
TorqueMode torque_mode(std::span<const Sample> samples);

/// The kernel's step loop for the lanes' torque mode, inlined into the caller (so compiled with its target).
template <class Kernel, class KernelLanes>
inline __attribute__((always_inline)) void steps_in_mode(KernelLanes& L, FlipLanes& F, long long n, double h,
                                                         int lanes, TorqueMode mode) {
  switch (mode) {
    case TorqueMode::free:
      return Kernel::template steps<TorqueMode::free>(L, F, n, h, lanes);
    case TorqueMode::body:
      return Kernel::template steps<TorqueMode::body>(L, F, n, h, lanes);
    case TorqueMode::space:
      return Kernel::template steps<TorqueMode::space>(L, F, n, h, lanes);
  }
}

/// The step loop of a kernel, `Kernel::template steps<Mode>(L, F, n, h, lanes)` (always inlined), compiled
/// with AVX2 enabled: the loops over the lanes vectorise 4 wide. Called only when the CPU has AVX2.
template <class Kernel, class KernelLanes>
__attribute__((target("avx2"))) void steps_avx2(KernelLanes& L, FlipLanes& F, long long n, double h,
                                                int lanes, TorqueMode mode) {
  steps_in_mode<Kernel>(L, F, n, h, lanes, mode);
}

/// The same loop for any x86-64 (SSE2) or other CPU.
template <class Kernel, class KernelLanes>
void steps_portable(KernelLanes& L, FlipLanes& F, long long n, double h, int lanes, TorqueMode mode) {
  steps_in_mode<Kernel>(L, F, n, h, lanes, mode);
}

/// Advances the lanes by n steps of h (s) with the AVX2 or the portable compilation of the kernel's loop; the
/// two give the same bits (no fused multiply–add: the kernels are compiled with -ffp-contract=off).
template <class Kernel, class KernelLanes>
void run_steps(bool avx2, KernelLanes& L, FlipLanes& F, long long n, double h, int lanes, TorqueMode mode) {
  if (avx2) {
    steps_avx2<Kernel>(L, F, n, h, lanes, mode);
  } else {
    steps_portable<Kernel>(L, F, n, h, lanes, mode);
  }
}

}  // namespace poinsot::ensemble::detail
