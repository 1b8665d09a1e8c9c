#include "poinsot/ensemble/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace poinsot::ensemble {

void RunningStats::add(double x) {
  if (std::isnan(x)) {
    ++nan_count;
    return;
  }
  ++count;
  const double delta = x - mean;
  mean += delta / static_cast<double>(count);
  m2 += delta * (x - mean);
  min = std::min(min, x);
  max = std::max(max, x);
}

void RunningStats::merge(const RunningStats& o) {
  nan_count += o.nan_count;
  if (o.count == 0) return;
  if (count == 0) {
    const std::int64_t nan = nan_count;
    *this = o;
    nan_count = nan;
    return;
  }
  const double na = static_cast<double>(count), nb = static_cast<double>(o.count);
  const double n = na + nb;
  const double delta = o.mean - mean;
  mean += delta * (nb / n);
  m2 += o.m2 + delta * delta * (na * nb / n);
  count += o.count;
  min = std::min(min, o.min);
  max = std::max(max, o.max);
}

double RunningStats::variance() const {
  return count < 2 ? 0.0 : m2 / static_cast<double>(count - 1);
}

double percentile(std::vector<double> values, double p) {
  std::erase_if(values, [](double x) { return !std::isfinite(x); });
  if (values.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(values.begin(), values.end());
  const double rank = p / 100.0 * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(rank));
  const std::size_t hi = std::min(lo + 1, values.size() - 1);
  const double frac = rank - static_cast<double>(lo);
  return values[lo] + frac * (values[hi] - values[lo]);
}

}  // namespace poinsot::ensemble
