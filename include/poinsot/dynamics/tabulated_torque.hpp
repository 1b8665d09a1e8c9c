#pragma once
/// @file tabulated_torque.hpp
/// A body torque given by a table of rows (t_i, τ_i), a function of time only (N·m, body frame): the replay
/// of a control history, e.g. the control.csv that `poinsot optimize` writes.
///
/// Interpolation (the one used wherever a sampled control is replayed, the optimal layer's verification too):
///  - two rows with the same time are a jump: the first holds the left limit, the second the right one; the
///    rows between two jumps (or the table's ends) form an arc; a row within `same_time` (relative to the
///    table's span and its times' magnitude) of the previous one has the same time, a difference that is
///    rounding only (a switch time computed twice);
///  - between two rows with t_i < t_{i+1} (a piece), TableInterpolation::linear (the default) takes the line
///    through them: error O(Δt² τ̈), never outside the two rows' values, exact for a piecewise-linear profile;
///  - TableInterpolation::cubic takes the cubic through four rows of the piece's arc, i − 1 … i + 2 (at the
///    arc's ends i … i + 3 or i − 2 … i + 1; the quadratic or the line through three or two rows where the
///    arc has no more): a local Lagrange interpolant, continuous, exact at the rows, error O(Δt⁴ τ⁽⁴⁾), for
///    the replay of a smooth control sampled densely (docs/optimal_control.md, "Replaying a control",
///    measures both); it overshoots at the corners of a profile that is not smooth (a trapezoid's);
///  - either way a bang-bang control written with two rows per switch is a zero-order hold with the exact
///    switch times (the arcs are constant);
///  - before the first row and after the last one τ = 0 (the control history is over: the body moves
///    torque-free).
/// At a time where pieces meet, torque_body returns the right-hand piece's value, except when the simulation
/// driver has announced (enter_interval) a step lying in the piece that ends there: then every stage of that
/// step, including those at its end (to within 1e-12 relative, the rounding of stage times), sees one
/// piece (τ has a kink at every row). The driver ends a step at each
/// breakpoint, so an integrator of any order keeps its order across the jumps.
#include <cstddef>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::dynamics {

/// How τ is interpolated between two rows of one arc (above).
enum class TableInterpolation { linear, cubic };

/// The name of `interpolation` as the scenario files spell it ("linear", "cubic").
const char* table_interpolation_name(TableInterpolation interpolation);

class TabulatedTorque final : public TorqueModel {
 public:
  /// Two row times closer than this, relative to max(|t_first|, |t_i|, t_i − t_first), are one time.
  static constexpr double same_time = 1e-12;

  /// Rows (t_i s, τ_i N·m). Throws InvalidInput naming `source` and the row (1-based) for: fewer than two
  /// rows, a non-finite value, a time below the previous one, three rows at one time, or a first or last
  /// time that is a jump (times within `same_time` of each other counting as one).
  TabulatedTorque(std::vector<double> time, std::vector<Vec3> torque_body, std::string source,
                  TableInterpolation interpolation = TableInterpolation::linear);

  Vec3 torque_body(double t, const Mat3& R, const Vec3& omega_body) const override;
  std::string describe() const override;
  /// The distinct times of the table (s, ascending): every jump or kink of τ(t).
  std::vector<double> breakpoints() const override;
  /// Selects the piece that contains [t_begin, next breakpoint] for the evaluations of the coming step.
  void enter_interval(double t_begin) const override;

  const std::vector<double>& time() const { return time_; }
  const std::vector<Vec3>& torque_rows() const { return torque_; }
  TableInterpolation interpolation() const { return interpolation_; }

 private:
  /// The interpolant of piece p (rows p, p + 1, and for the cubic their neighbours on its arc), t clamped to
  /// the piece.
  Vec3 on_piece(std::size_t p, double t) const;

  std::vector<double> time_;
  std::vector<Vec3> torque_;
  std::vector<double> breakpoints_;
  std::string source_;
  TableInterpolation interpolation_;
  /// The announced piece: the index of its first row (time_[p] < time_[p + 1]), or before / after the table
  /// (τ = 0 there, also at the table's first or last time), or none. Only the driver of one simulation sets
  /// it (a model with breakpoints serves one simulation at a time).
  static constexpr std::size_t none = static_cast<std::size_t>(-1);
  static constexpr std::size_t before = static_cast<std::size_t>(-2);
  static constexpr std::size_t after = static_cast<std::size_t>(-3);
  mutable std::size_t piece_ = none;
};

}  // namespace poinsot::dynamics
