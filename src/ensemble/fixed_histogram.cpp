#include "poinsot/ensemble/fixed_histogram.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::ensemble {

std::optional<HistogramRange> pilot_range(std::span<const double> pilot) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double x : pilot) {
    if (!std::isfinite(x)) continue;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
  }
  if (lo > hi) return std::nullopt;
  const double span = hi - lo;
  if (span == 0.0) {
    const double d = std::max(1e-3 * std::abs(lo), 1e-300);
    return HistogramRange{lo - d, hi + d};
  }
  if (!std::isfinite(span)) return HistogramRange{lo, hi};  // values across the whole double range
  const double margin = span / 10;
  HistogramRange r{lo - margin, hi + margin};
  if (lo >= 0.0) r.lo = std::max(r.lo, 0.0);
  if (hi <= 0.0) r.hi = std::min(r.hi, 0.0);
  if (!std::isfinite(r.lo) || !std::isfinite(r.hi) || !std::isfinite(r.hi - r.lo))
    return HistogramRange{lo, hi};
  return r;
}

FixedHistogram::FixedHistogram(HistogramRange range, int bins) : range_(range) {
  if (!(std::isfinite(range.lo) && std::isfinite(range.hi) && range.lo < range.hi &&
        std::isfinite(range.hi - range.lo))) {
    throw InvalidInput(fmt::format("histogram: range [{}, {}]; expected finite lo < hi", range.lo, range.hi));
  }
  if (bins < 1 || bins > kMaxHistogramBins) {
    throw InvalidInput(fmt::format("histogram: bins = {}; expected 1 to {}", bins, kMaxHistogramBins));
  }
  width_ = (range.hi - range.lo) / static_cast<double>(bins);
  counts_.assign(static_cast<std::size_t>(bins), 0);
}

double FixedHistogram::edge(int i) const {
  return i >= bins() ? range_.hi : range_.lo + static_cast<double>(i) * width_;
}

int FixedHistogram::bin_of(double x) const {
  const int n = bins();
  const double guess = std::floor((x - range_.lo) / width_);
  int i = guess < 0.0 ? 0 : guess >= static_cast<double>(n - 1) ? n - 1 : static_cast<int>(guess);
  // The rounded quotient may miss by one bin near an edge: settle against the edges themselves.
  while (i > 0 && x < edge(i))
    --i;
  while (i < n - 1 && x >= edge(i + 1))
    ++i;
  return i;
}

void FixedHistogram::add(double x) {
  if (!has_edges()) return;
  if (std::isnan(x)) {
    ++nan_;
  } else if (x < range_.lo) {
    ++underflow_;
  } else if (x > range_.hi) {
    ++overflow_;
  } else {
    ++counts_[static_cast<std::size_t>(bin_of(x))];
  }
}

void FixedHistogram::merge(const FixedHistogram& o) {
  if (o.range_.lo != range_.lo || o.range_.hi != range_.hi || o.bins() != bins()) {
    throw InvalidInput(
        fmt::format("histogram: merging [{}, {}] in {} bins into [{}, {}] in {} bins; expected "
                    "the same edges",
                    o.range_.lo, o.range_.hi, o.bins(), range_.lo, range_.hi, bins()));
  }
  add_flat_counts(o.flat_counts());
}

std::vector<std::int64_t> FixedHistogram::flat_counts() const {
  std::vector<std::int64_t> f{underflow_, overflow_, nan_};
  f.insert(f.end(), counts_.begin(), counts_.end());
  return f;
}

void FixedHistogram::add_flat_counts(std::span<const std::int64_t> f) {
  if (f.size() != counts_.size() + 3) {
    throw InvalidInput(fmt::format("histogram: {} counts to add to {} bins; expected {}", f.size(),
                                   counts_.size(), counts_.size() + 3));
  }
  underflow_ += f[0];
  overflow_ += f[1];
  nan_ += f[2];
  for (std::size_t i = 0; i < counts_.size(); ++i)
    counts_[i] += f[i + 3];
}

}  // namespace poinsot::ensemble
