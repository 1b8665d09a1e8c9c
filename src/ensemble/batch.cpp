#include "poinsot/ensemble/batch.hpp"

#include <array>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "batch_kernels.hpp"
#include "batch_lanes.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/dlm.hpp"
#include "poinsot/dynamics/rk4.hpp"

namespace poinsot::ensemble {

namespace {

/// The methods of the dynamics registry that have a batched kernel, with it: the one list of them.
struct BatchedMethod {
  std::string_view name;
  void (*run)(std::span<const Sample> samples, double t_end, long long n, bool avx2,
              std::span<LaneResult> results);
};
constexpr std::array kBatchedMethods{BatchedMethod{dynamics::Rk4Integrator::kName, detail::run_rk4_batch},
                                     BatchedMethod{dynamics::DlmIntegrator::kName, detail::run_dlm_batch}};

const BatchedMethod* batched_method(std::string_view name) {
  for (const BatchedMethod& m : kBatchedMethods)
    if (m.name == name) return &m;
  return nullptr;
}

}  // namespace

std::string batched_method_names(std::string_view last_separator) {
  std::string out;
  for (std::size_t i = 0; i < kBatchedMethods.size(); ++i) {
    if (i > 0) out += i + 1 == kBatchedMethods.size() ? last_separator : std::string_view(", ");
    out += kBatchedMethods[i].name;
  }
  return out;
}

bool batchable(std::string_view method, const Sample& sample) {
  return batched_method(method) != nullptr && !sample.has_pivot &&
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
          "ensemble: method \"{}\" has no batched kernel for sample {} (expected {} on a free body under no "
          "torque or a constant torque in the body frame or in space)",
          method, s.index, batched_method_names()));
    }
  }
  detail::torque_mode(samples);  // refuses a batch mixing body-frame and space-frame torques
  const long long n = batch_step_count(t_end, dt);
  const bool avx2 = simd == Simd::automatic && simd_available();
  batched_method(method)->run(samples, t_end, n, avx2, results);
}

}  // namespace poinsot::ensemble
