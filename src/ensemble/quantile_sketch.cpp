#include "poinsot/ensemble/quantile_sketch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
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
  (x > 0.0 ? positive_ : negative_).add(i, 1);
}

void QuantileSketch::DenseStore::add(std::int32_t index, std::int64_t n) {
  if (counts.empty()) {
    offset = lowest = highest = index;
    counts.assign(1, 0);
  }
  lowest = std::min(lowest, index);
  highest = std::max(highest, index);
  const std::int64_t first = offset, last = offset + static_cast<std::int64_t>(counts.size()) - 1;
  if (index < first || index > last) {
    // Grow to cover `index` with a margin of an eighth of the occupied range (at least 16) on that side, so
    // that a range filled one bucket at a time costs amortised O(1) per bucket, and the storage stays within
    // R + 2 max(16, R/8) for an occupied range of R indices; never beyond the int32 indices.
    const std::int64_t margin =
        std::max<std::int64_t>(16, (static_cast<std::int64_t>(highest) - lowest + 1) / 8);
    const std::int64_t new_first = index < first ? std::max<std::int64_t>(INT32_MIN, index - margin) : first;
    const std::int64_t new_last = index > last ? std::min<std::int64_t>(INT32_MAX, index + margin) : last;
    std::vector<std::int64_t> grown(static_cast<std::size_t>(new_last - new_first + 1), 0);
    std::copy(counts.begin(), counts.end(), grown.begin() + (first - new_first));
    counts = std::move(grown);
    offset = static_cast<std::int32_t>(new_first);
  }
  counts[static_cast<std::size_t>(index - offset)] += n;
}

std::size_t QuantileSketch::storage_buckets() const {
  return positive_.counts.size() + negative_.counts.size();
}

void QuantileSketch::merge(const QuantileSketch& o) {
  if (o.alpha_ != alpha_) {
    throw InvalidInput(fmt::format("quantile sketch: merging alpha = {} into alpha = {}; expected the same",
                                   o.alpha_, alpha_));
  }
  for (const DenseStore* from : {&o.positive_, &o.negative_}) {
    DenseStore& to = from == &o.positive_ ? positive_ : negative_;
    for (std::size_t k = 0; k < from->counts.size(); ++k)
      if (from->counts[k] != 0) to.add(from->offset + static_cast<std::int32_t>(k), from->counts[k]);
  }
  zeros_ += o.zeros_;
  count_ += o.count_;
}

std::vector<QuantileBucket> QuantileSketch::buckets() const {
  std::vector<QuantileBucket> out;
  for (std::size_t k = negative_.counts.size(); k-- > 0;)
    if (negative_.counts[k] != 0)
      out.push_back({-1, negative_.offset + static_cast<std::int32_t>(k), negative_.counts[k]});
  if (zeros_ > 0) out.push_back({0, 0, zeros_});
  for (std::size_t k = 0; k < positive_.counts.size(); ++k)
    if (positive_.counts[k] != 0)
      out.push_back({1, positive_.offset + static_cast<std::int32_t>(k), positive_.counts[k]});
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
  else if (b.count > 0)
    (b.store > 0 ? positive_ : negative_).add(b.index, b.count);
  count_ += b.count;
}

double QuantileSketch::representative(std::int32_t index) const {
  // 2γ^i/(γ + 1): the point of (γ^(i−1), γ^i] whose relative distance to both ends is α.
  return 2.0 * std::exp(static_cast<double>(index) * log_gamma_) / (gamma_ + 1.0);
}

double QuantileSketch::value_at_rank(std::int64_t k) const {
  // Most negative first: the negative store by decreasing |x|, then the zeros, then the positive store.
  for (std::size_t j = negative_.counts.size(); j-- > 0;) {
    if (k < negative_.counts[j]) return -representative(negative_.offset + static_cast<std::int32_t>(j));
    k -= negative_.counts[j];
  }
  if (k < zeros_) return 0.0;
  k -= zeros_;
  for (std::size_t j = 0; j < positive_.counts.size(); ++j) {
    if (k < positive_.counts[j]) return representative(positive_.offset + static_cast<std::int32_t>(j));
    k -= positive_.counts[j];
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
