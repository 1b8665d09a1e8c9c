#pragma once
/// @file statistics.hpp
/// Mergeable statistics of an ensemble's per-sample outputs.
///
/// RunningStats: count, mean and M2 = Σ(x − mean)² by Welford's update, merged by Chan, Golub & LeVeque's
/// formula (1979): δ = mean_b − mean_a, mean = mean_a + δ n_b/n, M2 = M2_a + M2_b + δ² n_a n_b/n; exact
/// minimum and maximum. Floating-point merging is not associative, so the ensemble always merges in one fixed
/// order (blocks of samples in index order), whatever the threads: the results are bit-identical.
/// NaN values (an output that does not apply to a sample, e.g. no flip) are counted apart, not averaged.
///
/// Percentiles are exact order statistics of the stored values with linear interpolation between closest
/// ranks (Hyndman & Fan 1996, definition 7, NumPy's default): x at rank p(n − 1).
#include <cstdint>
#include <limits>
#include <vector>

namespace poinsot::ensemble {

struct RunningStats {
  std::int64_t count = 0;  ///< finite values
  std::int64_t nan_count = 0;
  double mean = 0.0;
  double m2 = 0.0;
  double min = std::numeric_limits<double>::infinity();
  double max = -std::numeric_limits<double>::infinity();

  void add(double x);
  void merge(const RunningStats& other);
  /// The sample variance M2/(n − 1) (0 for n < 2).
  double variance() const;
};

/// The percentiles P1, P5, P50, P95, P99, P99.9.
inline constexpr double kPercentiles[] = {1.0, 5.0, 50.0, 95.0, 99.0, 99.9};

/// The p-th percentile (0 ≤ p ≤ 100) of the finite values (definition 7); NaN when there are none.
double percentile(std::vector<double> values, double p);

}  // namespace poinsot::ensemble
