#include "poinsot/dynamics/tabulated_torque.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::dynamics {

const char* table_interpolation_name(TableInterpolation interpolation) {
  return interpolation == TableInterpolation::cubic ? "cubic" : "linear";
}

TabulatedTorque::TabulatedTorque(std::vector<double> time, std::vector<Vec3> torque_body, std::string source,
                                 TableInterpolation interpolation)
    : time_(std::move(time)),
      torque_(std::move(torque_body)),
      source_(std::move(source)),
      interpolation_(interpolation) {
  if (time_.size() != torque_.size())
    throw InvalidInput(fmt::format("{}: {} times for {} torques; expected one torque per time", source_,
                                   time_.size(), torque_.size()));
  if (time_.size() < 2)
    throw InvalidInput(
        fmt::format("{}: {} row(s); expected at least two rows (t, ux, uy, uz)", source_, time_.size()));
  for (std::size_t i = 0; i < time_.size(); ++i) {
    if (!std::isfinite(time_[i]) || !torque_[i].allFinite())
      throw InvalidInput(fmt::format("{}: row {}: t = {}, u = {}; expected finite values", source_, i + 1,
                                     format_number(time_[i]), format_vector(torque_[i])));
    if (i > 0 && time_[i] < time_[i - 1])
      throw InvalidInput(
          fmt::format("{}: row {}: t = {} s is below the previous row's {} s; expected "
                      "times in ascending order",
                      source_, i + 1, format_number(time_[i]), format_number(time_[i - 1])));
    // Times that differ by rounding only (a switch computed twice) are one time: a jump. Kept apart, the
    // piece between them would be an ulp long and a cubic through it would reach 1/ulp.
    if (i > 0 && time_[i] - time_[i - 1] <=
                     same_time * std::max({std::abs(time_[0]), std::abs(time_[i]), time_[i] - time_[0]}))
      time_[i] = time_[i - 1];
    if (i > 1 && time_[i] == time_[i - 2])
      throw InvalidInput(
          fmt::format("{}: row {}: a third row at t = {} s; expected at most two rows (the "
                      "left and right values of a jump) at one time",
                      source_, i + 1, format_number(time_[i])));
  }
  if (time_[0] == time_[1] || time_[time_.size() - 1] == time_[time_.size() - 2])
    throw InvalidInput(
        fmt::format("{}: the table starts or ends with two rows at one time; expected a jump "
                    "only inside the table (τ is 0 outside it)",
                    source_));
  breakpoints_ = time_;
  breakpoints_.erase(std::unique(breakpoints_.begin(), breakpoints_.end()), breakpoints_.end());
}

Vec3 TabulatedTorque::on_piece(std::size_t p, double t) const {
  if (interpolation_ == TableInterpolation::linear) {
    const double a = time_[p], b = time_[p + 1];
    const double w = std::clamp((t - a) / (b - a), 0.0, 1.0);
    return (1.0 - w) * torque_[p] + w * torque_[p + 1];
  }
  // The stencil: rows p, p + 1 and one neighbour on each side on the same arc (an arc ends at a repeated
  // time); at an arc's end, two on the side that has them (one-sided, still O(Δt⁴)).
  const auto left = [&](std::size_t i) { return i > 0 && time_[i - 1] < time_[i]; };
  const auto right = [&](std::size_t i) { return i + 1 < time_.size() && time_[i + 1] > time_[i]; };
  std::size_t lo = p, hi = p + 1;
  if (left(lo)) --lo;
  if (right(hi)) ++hi;
  if (lo == p && right(hi))
    ++hi;
  else if (hi == p + 1 && left(lo))
    --lo;
  const double x = std::clamp(t, time_[p], time_[p + 1]);
  Vec3 out = Vec3::Zero();
  for (std::size_t i = lo; i <= hi; ++i) {
    double w = 1.0;
    for (std::size_t k = lo; k <= hi; ++k)
      if (k != i) w *= (x - time_[k]) / (time_[i] - time_[k]);
    out += w * torque_[i];
  }
  return out;
}

Vec3 TabulatedTorque::torque_body(double t, const Mat3&, const Vec3&) const {
  // Stage times t + c·h are rounded: a stage meant for the end of a step may land a few ulps past it.
  const auto slack = [](double a, double b) { return 1e-12 * std::max({std::abs(a), std::abs(b), b - a}); };
  const double first = time_.front(), last = time_.back();
  if (piece_ == before && t <= first + slack(first, first)) return Vec3::Zero();
  if (piece_ == after && t >= last - slack(last, last)) return Vec3::Zero();
  if (piece_ < time_.size()) {
    const double a = time_[piece_], b = time_[piece_ + 1], d = slack(a, b);
    if (t >= a - d && t <= b + d) return on_piece(piece_, t);
  }
  if (t < time_.front() || t > time_.back()) return Vec3::Zero();
  if (t == time_.back()) return torque_.back();
  // The right-hand piece: the last row with time ≤ t starts it (at a jump, the second of the two rows).
  const auto p =
      static_cast<std::size_t>(std::upper_bound(time_.begin(), time_.end(), t) - time_.begin()) - 1;
  return on_piece(p, t);
}

std::vector<double> TabulatedTorque::breakpoints() const {
  return breakpoints_;
}

void TabulatedTorque::enter_interval(double t_begin) const {
  if (t_begin < time_.front()) {
    piece_ = before;
  } else if (t_begin >= time_.back()) {
    piece_ = after;
  } else {
    piece_ =
        static_cast<std::size_t>(std::upper_bound(time_.begin(), time_.end(), t_begin) - time_.begin()) - 1;
  }
}

std::string TabulatedTorque::describe() const {
  return fmt::format("table {} ({} rows, t {} … {} s, {}; 0 outside)", source_, time_.size(),
                     format_number(time_.front()), format_number(time_.back()),
                     table_interpolation_name(interpolation_));
}

}  // namespace poinsot::dynamics
