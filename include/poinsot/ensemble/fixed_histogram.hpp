#pragma once
/// @file fixed_histogram.hpp
/// Histograms of an ensemble's outputs accumulated on the fly, with edges fixed before the run, so that they
/// need no stored values and merge exactly: integer counts, added in any order (threads, blocks, MPI ranks),
/// give the same counts.
///
/// `bins` equal bins over [lo, hi]: the edges are e_i = lo + i·w (i < bins, rounded), w = (hi − lo)/bins,
/// and e_bins = hi; bin i holds e_i ≤ x < e_(i+1), the last bin also x = hi. A value is counted against these
/// rounded edges exactly (the quotient (x − lo)/w only guesses the bin), so a count over the edges as
/// written equals the histogram's. Values below lo (−∞ included) are counted in `underflow`, above hi (+∞
/// included) in `overflow`, NaN in `nan_count`: none is dropped.
///
/// The edges of an output are given (the scenario's [ensemble.histogram]) or taken from a pilot: the finite
/// values of the samples 0 … min(samples, pilot size) − 1, whose draws depend only on the seed and their
/// indices, so every thread and MPI rank derives the same edges (pilot_range).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace poinsot::ensemble {

/// The default number of bins, and the largest accepted.
inline constexpr int kHistogramBins = 20;
inline constexpr int kMaxHistogramBins = 100000;

/// A closed range [lo, hi] of an output's values (the output's unit).
struct HistogramRange {
  double lo = 0.0;
  double hi = 0.0;
};

/// The range of the pilot's finite values [min, max] widened by a tenth of max − min on each side (but not
/// across 0 when all values have one sign: errors stay ≥ 0); for a single distinct value x, x ∓ max(10⁻³|x|,
/// 10⁻³⁰⁰). Empty when the pilot has no finite value (then the output has no histogram).
std::optional<HistogramRange> pilot_range(std::span<const double> pilot);

class FixedHistogram {
 public:
  /// A histogram without edges: counts nothing, has_edges() false.
  FixedHistogram() = default;
  /// Throws InvalidInput unless lo and hi are finite, lo < hi, hi − lo finite and 1 ≤ bins ≤
  /// kMaxHistogramBins.
  FixedHistogram(HistogramRange range, int bins);

  void add(double x);
  /// Adds the counts of `other`, which must have the same edges (InvalidInput otherwise).
  void merge(const FixedHistogram& other);

  bool has_edges() const { return !counts_.empty(); }
  int bins() const { return static_cast<int>(counts_.size()); }
  HistogramRange range() const { return range_; }
  /// e_i for 0 ≤ i ≤ bins (as above).
  double edge(int i) const;
  /// The bin of a value lo ≤ x ≤ hi, against the rounded edges.
  int bin_of(double x) const;
  const std::vector<std::int64_t>& counts() const { return counts_; }
  std::int64_t underflow() const { return underflow_; }
  std::int64_t overflow() const { return overflow_; }
  std::int64_t nan_count() const { return nan_; }

  /// All counts in one array, [underflow, overflow, NaN, bins…], for transport (MPI), and back: adds such an
  /// array (of this histogram's length: InvalidInput otherwise) to the counts.
  std::vector<std::int64_t> flat_counts() const;
  void add_flat_counts(std::span<const std::int64_t> flat);

 private:
  HistogramRange range_;
  double width_ = 0.0;
  std::vector<std::int64_t> counts_;
  std::int64_t underflow_ = 0, overflow_ = 0, nan_ = 0;
};

}  // namespace poinsot::ensemble
