#include "poinsot/ensemble/batch.hpp"

#include <cmath>

#include <fmt/format.h>

#include "batch_kernels.hpp"
#include "batch_lanes.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::ensemble {

bool batchable(std::string_view method, const Sample& sample) {
  return (method == "rk4" || method == "dlm") && !sample.has_pivot &&
         (sample.torque == TorqueKind::none || sample.torque == TorqueKind::body ||
          sample.torque == TorqueKind::space);
}

namespace detail {

TorqueMode torque_mode(std::span<const Sample> samples) {
  bool body = false, space = false;
  for (const Sample& s : samples) {
    body = body || s.torque == TorqueKind::body;
    space = space || s.torque == TorqueKind::space;
  }
  if (body && space) {
    throw InvalidInput(
        "ensemble: a batch with both body-frame and space-frame torques; expected one kind of torque per "
        "batch");
  }
  return space ? TorqueMode::space : body ? TorqueMode::body : TorqueMode::free;
}

}  // namespace detail

long long batch_step_count(double t_end, double dt) {
  return std::max(1LL, static_cast<long long>(std::ceil(t_end / dt - 1e-9)));
}

bool simd_available() {
  static const bool avx2 = __builtin_cpu_supports("avx2");
  return avx2;
}

void run_batch(std::string_view method, std::span<const Sample> samples, double t_end, double dt, Simd simd,
               std::span<LaneResult> results) {
  require_positive("ensemble: t_end", t_end, "s");
  require_positive("ensemble: dt", dt, "s");
  if (samples.size() > static_cast<std::size_t>(kBatchLanes) || results.size() < samples.size()) {
    throw InvalidInput(fmt::format("ensemble: a batch of {} samples into {} results; expected at most {}",
                                   samples.size(), results.size(), kBatchLanes));
  }
  if (samples.empty()) return;
  for (const Sample& s : samples) {
    if (!batchable(method, s)) {
      throw InvalidInput(fmt::format(
          "ensemble: method \"{}\" has no batched kernel for sample {} (expected rk4 "
          "or dlm on a free body under no torque or a constant torque in the body frame or in space)",
          method, s.index));
    }
  }
  detail::torque_mode(samples);  // refuses a batch mixing body-frame and space-frame torques
  const long long n = batch_step_count(t_end, dt);
  const bool avx2 = simd == Simd::automatic && simd_available();
  if (method == "rk4") {
    detail::run_rk4_batch(samples, t_end, n, avx2, results);
  } else {
    detail::run_dlm_batch(samples, t_end, n, avx2, results);
  }
}

}  // namespace poinsot::ensemble
