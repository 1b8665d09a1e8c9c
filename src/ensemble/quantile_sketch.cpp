#include "poinsot/ensemble/quantile_sketch.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::ensemble {

QuantileSketch::QuantileSketch(double alpha) : alpha_(alpha) {
  if (!(alpha > 0.0 && alpha < 1.0)) {
    throw InvalidInput(
        fmt::format("quantile sketch: alpha = {}; expected a relative accuracy in (0, 1)", alpha));
  }
  gamma_ = (1.0 + alpha) / (1.0 - alpha);
  log_gamma_ = std::log1p(2.0 * alpha / (1.0 - alpha));  // ln γ, accurate for small α
}

void QuantileSketch::add(double x) {
  if (!std::isfinite(x)) return;
  ++count_;
  if (x == 0.0) {
    ++zeros_;
    return;
  }
  // |x| ≥ 4.9e-324 and ≤ 1.8e308: |ln|x|| ≤ 745, so the index fits in 32 bits for any α ≥ 1e-6.
  const auto i = static_cast<std::int32_t>(std::ceil(std::log(std::abs(x)) / log_gamma_));
  (x > 0.0 ? positive_ : negative_)[i] += 1;
}

void QuantileSketch::merge(const QuantileSketch& o) {
  if (o.alpha_ != alpha_) {
    throw InvalidInput(fmt::format("quantile sketch: merging alpha = {} into alpha = {}; expected the same",
                                   o.alpha_, alpha_));
  }
  for (const auto& [i, n] : o.positive_)
    positive_[i] += n;
  for (const auto& [i, n] : o.negative_)
    negative_[i] += n;
  zeros_ += o.zeros_;
  count_ += o.count_;
}

std::vector<QuantileBucket> QuantileSketch::buckets() const {
  std::vector<QuantileBucket> out;
  for (auto it = negative_.rbegin(); it != negative_.rend(); ++it)
    out.push_back({-1, it->first, it->second});
  if (zeros_ > 0) out.push_back({0, 0, zeros_});
  for (const auto& [i, n] : positive_)
    out.push_back({1, i, n});
  return out;
}

void QuantileSketch::add_bucket(const QuantileBucket& b) {
  if (b.count < 0 || b.store < -1 || b.store > 1) {
    throw InvalidInput(
        fmt::format("quantile sketch: bucket (store {}, count {}); expected store -1, 0 or 1 "
                    "and a count >= 0",
                    b.store, b.count));
  }
  if (b.store == 0)
    zeros_ += b.count;
  else
    (b.store > 0 ? positive_ : negative_)[b.index] += b.count;
  count_ += b.count;
}

double QuantileSketch::representative(std::int32_t index) const {
  // 2γ^i/(γ + 1): the point of (γ^(i−1), γ^i] whose relative distance to both ends is α.
  return 2.0 * std::exp(static_cast<double>(index) * log_gamma_) / (gamma_ + 1.0);
}

double QuantileSketch::value_at_rank(std::int64_t k) const {
  // Most negative first: the negative store by decreasing |x|, then the zeros, then the positive store.
  for (auto it = negative_.rbegin(); it != negative_.rend(); ++it) {
    if (k < it->second) return -representative(it->first);
    k -= it->second;
  }
  if (k < zeros_) return 0.0;
  k -= zeros_;
  for (const auto& [i, n] : positive_) {
    if (k < n) return representative(i);
    k -= n;
  }
  return std::numeric_limits<double>::quiet_NaN();  // k ≥ count: not reached
}

double QuantileSketch::percentile(double p) const {
  if (!(p >= 0.0 && p <= 100.0))
    throw InvalidInput(fmt::format("quantile sketch: percentile {}; expected 0 to 100", p));
  if (count_ == 0) return std::numeric_limits<double>::quiet_NaN();
  const double rank = p / 100.0 * static_cast<double>(count_ - 1);
  const auto lo = static_cast<std::int64_t>(std::floor(rank));
  const std::int64_t hi = std::min(lo + 1, count_ - 1);
  const double frac = rank - static_cast<double>(lo);
  const double a = value_at_rank(lo);
  const double b = hi == lo ? a : value_at_rank(hi);
  return a + frac * (b - a);
}

}  // namespace poinsot::ensemble
