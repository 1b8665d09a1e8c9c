#pragma once
/// @file flip_events.hpp
/// The flips of the intermediate axis (the tennis-racket or Dzhanibekov effect): for a body with principal
/// moments I1 < I2 < I3, the instants where the component of the body angular momentum on the intermediate
/// principal axis, s(t) = e2ᵀ J ω (kg·m²/s; = I2 ω2 in the principal frame), changes sign. For the free body
/// successive flips are 2K(k)/ω_p apart (half the period 4K(k)/ω_p of ω(t)); see ExactFreeBody.
///
/// Roots are located by the TOMS 748 bracketing method (Alefeld, Potra & Shi 1995; Boost.Math) on an
/// interpolant of the step in which s changes sign: the integrator's dense output when it has one, otherwise
/// the cubic Hermite interpolant of s from its values and rates ṡ = e2ᵀ(τ_body − ω × Jω) at both ends of
/// the step, whose error O(h⁴) per step is below that of the fixed-step methods it serves (dlm and rattle are
/// of order 2; for rk4 it is of the same order as the method).
#include <memory>

#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::dynamics {

class FlipDetector {
 public:
  FlipDetector(const RigidBody& body, std::shared_ptr<const TorqueModel> torque);
  /// False when two principal moments agree to a relative 1e-12 (no intermediate axis, no flips).
  bool applicable() const { return applicable_; }
  /// s = e2ᵀ J ω (kg·m²/s), e2 the intermediate principal axis in the body frame.
  double component(const State& s) const { return component(s.omega_body); }
  /// s of the body angular velocity ω (rad/s).
  double component(const Vec3& omega_body) const;
  /// ṡ = e2ᵀ (τ_body − ω × J ω) (N·m).
  double rate(const State& s) const;
  /// ṡ = −e2ᵀ (ω × J ω) (N·m) of the torque-free body, ω in rad/s: rate() without the torque.
  double free_rate(const Vec3& omega_body) const;
  /// True when s changes sign from s0 to s1 (s0 ≠ 0 and s1 zero or of the other sign).
  static bool sign_change(double s0, double s1) { return (s0 > 0.0 && s1 <= 0.0) || (s0 < 0.0 && s1 >= 0.0); }
  /// The root in [t0, t1] of the cubic Hermite interpolant with values s0, s1 and rates r0, r1 at t0, t1
  /// (s0, s1 of opposite signs or s1 = 0), to full double precision in t.
  static double hermite_root(double t0, double t1, double s0, double s1, double r0, double r1);

 private:
  Mat3 J_;
  Vec3 e2_;
  std::shared_ptr<const TorqueModel> torque_;
  bool applicable_ = false;
};

/// The root in [t0, t1] of a continuous function g with g(t0) = g0, g(t1) = g1 of opposite signs (or g1 =
/// 0), by TOMS 748 to full double precision in t; at most 100 evaluations.
double locate_sign_change(double (*g)(double, const void*), const void* context, double t0, double t1,
                          double g0, double g1);

}  // namespace poinsot::dynamics
