#pragma once
/// @file quantile_sketch.hpp
/// Percentiles of an ensemble's outputs without storing the values: a relative-error quantile sketch with
/// logarithmic buckets (the DDSketch of Masson, Rim & Lee, VLDB 2019).
///
/// A value x > 0 is counted in bucket i = ⌈log_γ x⌉, which holds (γ^(i−1), γ^i], with
/// γ = (1 + α)/(1 − α); a value x < 0 in the bucket of |x| of a second store; zeros apart. A bucket stands
/// for x̂ = 2γ^i/(γ + 1) (negated in the negative store), and every x of bucket i satisfies |x̂ − x| ≤ α|x|.
///
/// The p-th percentile is definition 7 of Hyndman & Fan (1996), as percentile() of statistics.hpp: the
/// order statistics x_(lo), x_(hi) at ranks ⌊r⌋, ⌈r⌉ of r = p(n − 1)/100, interpolated linearly; the sketch
/// interpolates the representatives of the buckets that hold those two ranks. Error bound: with P the exact
/// percentile, |P̂ − P| ≤ α · max(|x_(lo)|, |x_(hi)|) — that is ≤ α|P| when x_(lo), x_(hi) have one sign —
/// plus rounding (about 10⁻¹² relative, from computing log and γ^i). Tested against the exact percentiles in
/// tests/ensemble/test_quantile_sketch.cpp.
///
/// Mergeable and deterministic: a sketch is a set of integer counts, so merging sketches in any order, on any
/// number of threads or MPI ranks, gives the same counts and the same percentiles bit for bit.
///
/// Memory: each sign's counts are one contiguous array over the bucket indices from the smallest to the
/// largest occupied one, ln(max|x| / min|x|)/ln γ + 1 counts (≈ 1 151 per decade of |x| for α = 10⁻³) plus a
/// quarter for growth (storage_buckets()), whatever the number of values; at most ≈ 1.25 · 7.3 · 10⁵ counts
/// (7 MB) per sign for values spanning all finite doubles (ln(1.8e308 / 4.9e-324) / ln γ ≈ 7.3 · 10⁵). One
/// allocation per growth of the range, none per value: a sketch that fills its tails slowly does not fragment
/// the heap (a node per bucket did). NaN and ±∞ are not counted (as in percentile()).
#include <cstddef>
#include <cstdint>
#include <vector>

namespace poinsot::ensemble {

/// The relative accuracy α of the ensemble's sketches.
inline constexpr double kQuantileRelativeAccuracy = 1e-3;

/// One bucket, for transport (MPI): store −1 (negative values), 0 (zeros; index 0) or +1 (positive values).
struct QuantileBucket {
  std::int32_t store = 0;
  std::int32_t index = 0;
  std::int64_t count = 0;
};

class QuantileSketch {
 public:
  /// Throws InvalidInput unless 0 < alpha < 1.
  explicit QuantileSketch(double alpha = kQuantileRelativeAccuracy);

  void add(double x);
  /// Adds the counts of `other`, which must have the same α (InvalidInput otherwise).
  void merge(const QuantileSketch& other);
  /// The p-th percentile (0 ≤ p ≤ 100, InvalidInput otherwise), within the bound above; NaN when no value
  /// was counted.
  double percentile(double p) const;

  /// Values counted (finite ones).
  std::int64_t count() const { return count_; }
  double alpha() const { return alpha_; }
  /// Occupied buckets, in the order of the values they hold.
  std::vector<QuantileBucket> buckets() const;
  /// Counts allocated, both signs (8 bytes each): at most R + 2 max(16, R/8) per sign, R the range of
  /// its occupied bucket indices.
  std::size_t storage_buckets() const;
  /// Adds a bucket's count (from buckets() of a sketch with the same α). Throws InvalidInput for a store
  /// other than −1, 0, 1 or a negative count.
  void add_bucket(const QuantileBucket& b);

 private:
  /// The representative value of the k-th smallest counted value (0 ≤ k < count).
  double value_at_rank(std::int64_t k) const;
  double representative(std::int32_t index) const;

  /// Counts of the bucket indices [offset, offset + counts.size()), grown at either end as values arrive.
  struct DenseStore {
    std::int32_t offset = 0;
    std::int32_t lowest = 0, highest = 0;  // the occupied indices' range
    std::vector<std::int64_t> counts;
    void add(std::int32_t index, std::int64_t n);
  };

  double alpha_;
  double gamma_;
  double log_gamma_;
  DenseStore positive_, negative_;  // bucket index of |x| -> count
  std::int64_t zeros_ = 0;
  std::int64_t count_ = 0;
};

}  // namespace poinsot::ensemble
