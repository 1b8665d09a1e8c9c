#pragma once
/// @file axis_tracker.hpp
/// Precession and nutation of a body axis measured from sampled states, in constant memory.
///
/// The tip of a unit body axis `a_body` moves on the unit sphere as `a(t) = R(t) a_body` (space frame). About
/// a fixed unit direction `u` (the vertical −g/|g| for a heavy top, L_space/|L| for a free symmetric top):
///   - the azimuth φ(t) of `a` about `u` is unwrapped from sample to sample (dφ = atan2((a_prev × a)·u,
///   a_prev⊥·a⊥),
///     valid while the azimuth moves by less than π between samples); the mean precession rate is
///     (φ_last − φ_first)/(t_last − t_first) (rad/s);
///   - the polar angle θ(t) = acos(a·u) nutates; each local minimum of θ is located between its three samples
///     by the vertex of the parabola through them, and the nutation angular frequency is
///     2π (n − 1)/(t_n − t_1) (rad/s) over the n minima found. It is reported only when θ varies by more than
///     `min_nutation_amplitude` (rad), so that round-off on a steady precession is not taken for nutation.
/// The samples must resolve the nutation (several samples per nutation period).

#include <optional>

#include "poinsot/core/types.hpp"

namespace poinsot::dynamics {

class AxisTracker {
 public:
  /// `axis_body` and `direction_space` need not be unit vectors (they are normalised); both non-zero.
  AxisTracker(const Vec3& axis_body, const Vec3& direction_space, double min_nutation_amplitude = 1e-7);

  /// Adds the sample at time t (s) with attitude R (body → space); times must increase.
  void add(double t, const Mat3& R);

  /// Mean precession rate (rad/s, positive counter-clockwise about the direction); nullopt before two
  /// samples.
  std::optional<double> precession_rate_mean() const;
  /// Nutation angular frequency (rad/s); nullopt with fewer than two minima of θ or no visible nutation.
  std::optional<double> nutation_frequency() const;
  /// Smallest and largest θ seen (rad).
  double theta_min() const { return theta_min_; }
  double theta_max() const { return theta_max_; }
  int nutation_minima() const { return minima_; }

  const Vec3& axis_body() const { return axis_body_; }
  const Vec3& direction_space() const { return u_; }

 private:
  Vec3 axis_body_, u_;
  double min_amplitude_;
  long long samples_ = 0;
  double t_first_ = 0.0, t_last_ = 0.0, phi_ = 0.0;
  Vec3 a_prev_ = Vec3::Zero();
  double theta_min_ = 0.0, theta_max_ = 0.0;
  double t1_ = 0.0, t2_ = 0.0, th1_ = 0.0, th2_ = 0.0;  // the two previous samples of θ
  int minima_ = 0;
  double t_min_first_ = 0.0, t_min_last_ = 0.0;
};

}  // namespace poinsot::dynamics
