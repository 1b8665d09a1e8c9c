#pragma once
/// @file pointing_constraint.hpp
/// Attitude path constraints of a slew: a body-fixed unit vector b (a star tracker's boresight, an antenna's
/// axis; body frame) and a space-fixed unit vector s (the Sun, the Earth, a target; space frame) whose angle
/// φ(t) = arccos(sᵀ R(t) b) must stay at least θ (keep-out) or at most θ (keep-in) at every instant, R body →
/// space.
///
/// With q = (w, v) the attitude quaternion, R(q) b = (w² − v·v) b + 2 (v·b) v + 2 w v × b is a homogeneous
/// quadratic in q, so the cosine is an exact quadratic form c(q) = sᵀ R(q) b = qᵀ A q with
///     A = [[ s·b,       (b × s)ᵀ            ],
///          [ b × s,     b sᵀ + s bᵀ − (s·b) I ]]      (order w, x, y, z),
/// whose gradient 2 A q and Hessian 2 A are what the direct method's path inequalities use (exact for any q;
/// the transcription keeps ‖q‖ = 1). Keep-out: c(q) ≤ cos θ; keep-in: c(q) ≥ cos θ.
///
/// The margin of a constraint at an attitude (rad): φ − θ for keep-out, θ − φ for keep-in; ≥ 0 where it
/// holds, the distance in angle to the cone's edge.
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "poinsot/core/types.hpp"

namespace poinsot::optimal {

/// The 4×4 symmetric A with sᵀ R(q) b = qᵀ A q for any vectors b (body frame) and s (space frame) and any
/// quaternion q = (w, x, y, z) (the form above; homogeneous of degree 2 in q, exact for unit q).
Eigen::Matrix4d rotation_bilinear_form(const Vec3& b, const Vec3& s);

enum class PointingKind { keep_out, keep_in };

/// "keep_out" or "keep_in" (the scenario files' table names).
std::string_view pointing_kind_name(PointingKind kind);

struct PointingConstraint {
  std::string name;  ///< for messages, reports and file columns (e.g. "sun"); may be empty
  PointingKind kind = PointingKind::keep_out;
  Vec3 boresight_body = Vec3::UnitX();   ///< b, unit, body frame
  Vec3 direction_space = Vec3::UnitX();  ///< s, unit, space frame
  double half_angle = 0.0;               ///< θ (rad), 0 < θ < π

  /// sᵀ R(q) b for a unit quaternion q (body → space).
  double cosine(const Quat& attitude) const;
  /// φ = arccos(sᵀ R b) (rad), the boresight's angle to the cone's axis.
  double angle(const Quat& attitude) const;
  double angle(const Mat3& R_space_body) const;
  /// φ − θ (keep-out) or θ − φ (keep-in), rad: ≥ 0 where the constraint holds.
  double margin(const Quat& attitude) const;
  double margin(const Mat3& R_space_body) const;
  /// The 4×4 symmetric A with sᵀ R(q) b = qᵀ A q, q ordered (w, x, y, z).
  Eigen::Matrix4d quadratic_form() const;
  /// The same constraint with the cone widened by δ ≥ 0 rad: θ + δ keep-out, θ − δ keep-in.
  PointingConstraint widened(double delta) const;
  /// "keep_out \"sun\"" (the kind and, when given, the name), for messages.
  std::string label() const;
};

/// Throws InvalidInput naming `field` (e.g. "optimal_control.keep_out[1]") unless both vectors are finite
/// and unit to 1e-9 and 0 < θ < π.
void validate(const PointingConstraint& constraint, std::string_view field);

/// The smallest margin of every constraint (rad) over a sampled attitude history, and where it is reached.
struct PointingMargins {
  std::vector<double> margin;  ///< one per constraint, +inf when there are no samples
  std::vector<double> time;    ///< s, the sample of the smallest margin
  /// The smallest margin over every constraint (rad); +inf without constraints.
  double worst() const;
  /// Sized for `constraints` (margins +inf), or left as they are when they already are.
  void reset(const std::vector<PointingConstraint>& constraints);
  /// Lowers each margin to the constraint's margin at the attitude q at time t (s) where that is smaller.
  void lower(const std::vector<PointingConstraint>& constraints, double t, const Quat& q);
  /// Lowers each margin to its smallest value along a motion between two states (q0, ω0 at t0 and q1, ω1 at
  /// t1; ω body frame, rad/s), with the attitude interpolated by the cubic Hermite of the quaternion with
  /// q̇ = ½ q ⊗ (0, ω) at both ends (normalised): `samples` points inside the step, the end included (the
  /// start is the previous step's end). The interpolation's error is O(h⁴ ‖q⁗‖): below 1e-12 rad for steps of
  /// 1e-3 of a turn, so the samples, not the interpolant, set how closely a grazing minimum is found
  /// (Δφ²/8 for an angle step Δφ between samples).
  void lower_along(const std::vector<PointingConstraint>& constraints, double t0, const Quat& q0,
                   const Vec3& omega0, double t1, const Quat& q1, const Vec3& omega1, int samples);
};

}  // namespace poinsot::optimal
