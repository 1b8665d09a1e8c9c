#pragma once
/// @file collocation_mesh.hpp (internal)
/// The mesh of the Hermite–Simpson transcription (hermite_simpson_nlp.hpp), for one body and for coupled
/// bodies alike.
///
/// A mesh is one or more phases in order. Phase a lasts Δ_a (s) and has its own normalised mesh
/// 0 = τ_0 < … < τ_{N_a} = 1, so its interval k spans h_k = (τ_{k+1} − τ_k) Δ_a. The intervals are numbered
/// over all phases. Every interval has a left node, a midpoint and a right node; the points are numbered
/// phase by phase (node, midpoint, node, …, the phase's last node), and the node between two phases is
/// duplicated: the last point of phase a and the first point of phase a + 1 are two points, so that a
/// control may jump there. One phase of N intervals has 2N + 1 points; P phases with N intervals in all have
/// 2N + P.
///
/// A uniform mesh (one phase, N equal intervals) computes its steps as h = Δ/N exactly as written, without
/// the round-off of Δ · (1/N).
#include <vector>

namespace poinsot::optimal::detail {

/// The refinement rule of every collocation mesh: an interval whose local error ε exceeds the tolerance is
/// split into n = ⌈(ε/tolerance)^¼⌉ equal pieces, at least 2 and at most 5 (the error of Hermite–Simpson
/// falls as h⁴ on a smooth arc, so n pieces bring ε to about ε/n⁴); one piece (kept) otherwise.
int refinement_pieces(double error, double tolerance);

class CollocationMesh {
 public:
  /// One phase of `intervals` equal intervals (at least 1). Throws InvalidInput otherwise.
  static CollocationMesh uniform(int intervals);
  /// One phase whose intervals have the fractions Δτ_k of its duration (positive, summing to 1; the
  /// problem's validation checks them).
  static CollocationMesh from_fractions(std::vector<double> fractions);
  /// Phases with `intervals[a]` intervals each (at least 1) and their normalised nodes, concatenated (each
  /// phase N_a + 1 increasing values from 0 to 1). Throws InvalidInput when the sizes disagree.
  static CollocationMesh from_nodes(std::vector<double> tau, const std::vector<int>& intervals);

  int phases() const { return static_cast<int>(phase_first_interval_.size()) - 1; }
  int intervals() const { return static_cast<int>(dtau_.size()); }
  int points() const { return 2 * intervals() + phases(); }
  bool uniform() const { return uniform_; }

  int interval_phase(int k) const { return interval_phase_[static_cast<std::size_t>(k)]; }
  int point_phase(int p) const { return point_phase_[static_cast<std::size_t>(p)]; }
  /// The point index of the left node of interval k (its midpoint and its right node follow).
  int interval_first_point(int k) const { return 2 * k + interval_phase(k); }
  int phase_first_interval(int a) const { return phase_first_interval_[static_cast<std::size_t>(a)]; }
  int phase_first_point(int a) const { return 2 * phase_first_interval(a) + a; }
  int phase_last_point(int a) const { return phase_first_point(a + 1) - 1; }
  bool first_of_phase(int p) const { return p == phase_first_point(point_phase(p)); }

  /// Δτ_k: interval k's share of its phase's duration.
  double step_fraction(int k) const { return dtau_[static_cast<std::size_t>(k)]; }
  /// h_k (s) for its phase's duration Δ (s).
  double step(int k, double duration) const {
    return uniform_ ? duration / intervals() : step_fraction(k) * duration;
  }
  /// τ of point p in its phase (0 at the phase's first point, 1 at its last).
  double point_fraction(int p) const;
  /// The normalised nodes of the phases, concatenated (N_a + 1 values per phase).
  const std::vector<double>& tau() const { return tau_; }
  /// Simpson's weight of point p per unit duration of its phase: ∫_phase g dt ≈ Δ_a Σ_p w_p g(t_p), with
  /// w = Δτ_k/6 at each node of interval k and 4Δτ_k/6 at its midpoint.
  double quadrature_weight(int p) const;
  /// The times of every point (s) for the phases' durations.
  std::vector<double> point_times(const std::vector<double>& durations) const;

 private:
  CollocationMesh() = default;
  void index_phases(const std::vector<int>& intervals);

  bool uniform_ = false;
  std::vector<double> dtau_;               // per interval
  std::vector<double> tau_;                // the nodes of every phase, concatenated
  std::vector<int> phase_first_interval_;  // P + 1 entries, the last = N
  std::vector<int> interval_phase_;        // per interval
  std::vector<int> point_phase_;           // per point
};

}  // namespace poinsot::optimal::detail
