// Precession and nutation of a body axis from samples (see axis_tracker.hpp).
#include "poinsot/dynamics/axis_tracker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::dynamics {

AxisTracker::AxisTracker(const Vec3& axis_body, const Vec3& direction_space, double min_nutation_amplitude)
    : min_amplitude_(min_nutation_amplitude) {
  if (!(axis_body.norm() > 0.0) || !(direction_space.norm() > 0.0)) {
    throw InvalidInput(fmt::format("axis tracker: axis {} and direction {} must be non-zero",
                                   format_vector(axis_body), format_vector(direction_space)));
  }
  axis_body_ = axis_body.normalized();
  u_ = direction_space.normalized();
}

void AxisTracker::add(double t, const Mat3& R) {
  const Vec3 a = R * axis_body_;
  const double theta = std::acos(std::clamp(a.dot(u_), -1.0, 1.0));
  if (samples_ == 0) {
    t_first_ = t;
    theta_min_ = theta_max_ = theta;
  } else {
    // Components perpendicular to u; the signed angle between them about u.
    const Vec3 p = a - a.dot(u_) * u_;
    const Vec3 q = a_prev_ - a_prev_.dot(u_) * u_;
    if (p.norm() > 1e-300 && q.norm() > 1e-300) phi_ += std::atan2(q.cross(p).dot(u_), q.dot(p));
    theta_min_ = std::min(theta_min_, theta);
    theta_max_ = std::max(theta_max_, theta);
  }
  if (samples_ >= 2 && th2_ < th1_ && th2_ <= theta) {
    // Local minimum at the middle sample: vertex of the parabola through (t1, θ1), (t2, θ2), (t, θ).
    const double d1 = (th2_ - th1_) / (t2_ - t1_);
    const double d2 = (theta - th2_) / (t - t2_);
    const double curvature = (d2 - d1) / (t - t1_);
    double tm = t2_;
    if (curvature > 0.0) tm = 0.5 * (t1_ + t2_) - d1 / (2.0 * curvature);
    tm = std::clamp(tm, t1_, t);
    if (minima_ == 0) t_min_first_ = tm;
    t_min_last_ = tm;
    ++minima_;
  }
  t1_ = t2_;
  th1_ = th2_;
  t2_ = t;
  th2_ = theta;
  a_prev_ = a;
  t_last_ = t;
  ++samples_;
}

std::optional<double> AxisTracker::precession_rate_mean() const {
  if (samples_ < 2 || !(t_last_ > t_first_)) return std::nullopt;
  return phi_ / (t_last_ - t_first_);
}

std::optional<double> AxisTracker::nutation_frequency() const {
  if (minima_ < 2 || theta_max_ - theta_min_ <= min_amplitude_ || !(t_min_last_ > t_min_first_)) {
    return std::nullopt;
  }
  return 2.0 * std::numbers::pi * (minima_ - 1) / (t_min_last_ - t_min_first_);
}

}  // namespace poinsot::dynamics
