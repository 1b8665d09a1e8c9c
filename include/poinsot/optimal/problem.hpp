#pragma once
/// @file problem.hpp
/// The optimal reorientation of one rigid body by body torques: the data of the optimal-control problem,
/// checked once, shared read-only by the direct (collocation) and indirect (shooting) methods.
///
/// Dynamics (docs/conventions.md conventions): `Ṙ = R j(ω)` with R body → space and ω the body-frame angular
/// velocity (rad/s); Euler `J ω̇ + ω × Jω = u` with J the inertia about the centre of mass in the body frame
/// (kg·m²) and u the control torque in the body frame (N·m). Controls: per-axis bounds `|u_i| ≤ u_max,i` or a
/// norm bound `‖u‖ ≤ u_max`; optional rate bounds
/// `|ω_i| ≤ ω_max` (a state constraint). Boundary conditions: R(0) = R_0, ω(0) = ω_0, R(T) = R_f, ω(T) = ω_f.
/// Attitude path constraints (pointing_constraint.hpp): body-fixed boresights kept out of, or within, cones
/// about space-fixed directions at every instant.
/// Reaction wheels (reaction_wheels.hpp): with `wheels` set, the controls are the three wheels' motor torques
/// u_k (|u_k| ≤ torque_max[k], per axis only) instead of body torques, the bus obeys J_b ω̇ = −A u − ω × Rᵀ L
/// with L the constant total angular momentum, and |h_k| ≤ momentum_max[k] holds at every instant.
/// Objectives:
///   minimum_time                 J = T, T free;
///   minimum_energy               J = ∫₀ᵀ ‖u‖² dt (N²·m²·s) at the fixed final time T;
///   minimum_time_regularised     J = T + ε ∫₀ᵀ ‖u‖² dt, T free, ε (s/(N·m)²) small: the regularisation
///                                smooths bang-bang controls into steep continuous ones (stated as such in
///                                every report; it is not the minimum-time problem).
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/pointing_constraint.hpp"
#include "poinsot/optimal/reaction_wheels.hpp"

namespace poinsot::optimal {

enum class Objective { minimum_time, minimum_energy, minimum_time_regularised };
enum class TorqueBound { per_axis, norm };

/// "minimum_time", "minimum_energy", "minimum_time_regularised".
std::string_view objective_name(Objective objective);
/// Inverse of objective_name; throws InvalidInput naming `field` and the accepted names.
Objective parse_objective(std::string_view name, std::string_view field = "objective");

struct ReorientationProblem {
  Mat3 inertia_body = Mat3::Identity();  ///< J about the centre of mass, body frame (kg·m²)
  TorqueBound bound = TorqueBound::per_axis;
  /// Per-axis bounds u_max,i (N·m) on the body torque, or with reaction wheels on wheel i's motor torque;
  /// with a norm bound only [0] is used.
  Vec3 torque_max = Vec3::Ones();
  double rate_max = std::numeric_limits<double>::infinity();  ///< |ω_i| ≤ rate_max (rad/s); inf = none
  Quat attitude_initial = Quat::Identity();                   ///< R_0 as a unit quaternion (body → space)
  Quat attitude_final = Quat::Identity();                     ///< R_f as a unit quaternion (body → space)
  Vec3 omega_initial = Vec3::Zero();                          ///< ω_0, body frame (rad/s)
  Vec3 omega_final = Vec3::Zero();                            ///< ω_f, body frame (rad/s)
  /// Detumbling: R(T) is free (attitude_final is ignored); the transversality condition is p_θ(T) = 0.
  bool free_final_attitude = false;
  /// Keep-out and keep-in cones, in the order of the files (each kind's entries numbered from 1 in messages).
  std::vector<PointingConstraint> pointing;
  /// The actuators are three reaction wheels (inertia_body is then the whole spacecraft's, wheels locked).
  std::optional<ReactionWheels> wheels;

  Objective objective = Objective::minimum_time;
  double final_time = 0.0;     ///< T (s) for minimum_energy; ignored by the free-time objectives
  double energy_weight = 0.0;  ///< ε (s/(N·m)²) of minimum_time_regularised; must be 0 otherwise

  /// The largest torque norm the bounds allow (N·m): ‖u_max‖ per axis, u_max with a norm bound.
  double torque_norm_limit() const;
  bool has_rate_bound() const { return rate_max < std::numeric_limits<double>::infinity(); }
  bool free_final_time() const { return objective != Objective::minimum_energy; }
  /// J_b (kg·m²): inertia_body less the wheels' axial inertia; inertia_body without wheels.
  Mat3 bus_inertia() const;
  /// L = R_0 (J_b ω_0 + A h_0) (N·m·s, space frame), constant with reaction wheels; zero without them.
  Vec3 wheel_system_momentum() const;
};

/// A necessary lower bound on the duration of any admissible manoeuvre (s): the geodesic angle Θ between R_0
/// and R_f (0 with a free final attitude) is at most ∫‖ω‖dt, ‖ω‖ ≤ ‖L‖/J_min, and ‖L(t)‖ ≤ min(‖L_0‖ + ū t,
/// ‖L_f‖ + ū (T − t)) because ‖L̇_space‖ = ‖u‖ ≤ ū (ū = torque_norm_limit()); with a rate bound also ‖ω‖ ≤ √3
/// ω_max. Also ‖L_f‖ and ‖L_0‖ differ by at most ū T. The smallest T meeting both (found by bisection to
/// 1e-12 relative). With reaction wheels the same argument holds for J_b ω = Rᵀ L − A h: ‖J_b ω‖ ≤ ‖L‖ +
/// ‖A h(t)‖, where ‖A h‖ changes at most at the rate ‖A‖ ū (capped by the momentum bounds). Assumes a
/// problem whose other fields are valid.
double minimum_duration_bound(const ReorientationProblem& problem);

/// Throws InvalidInput (one line naming the field, the value and what was expected) for: an invalid or
/// singular inertia; non-finite or non-positive torque bounds; a rate bound ≤ 0 or below |ω_0,i| or |ω_f,i|;
/// non-unit or non-finite attitudes (tolerance 1e-9 on ‖q‖); a minimum-energy final time that is not
/// finite and positive or is below minimum_duration_bound; an energy weight that is negative, non-finite, or
/// given for another objective; a pointing constraint that is malformed (validate(PointingConstraint)) or
/// that the initial attitude, or the final one when it is given, does not meet with a positive margin (the
/// boresight starts or ends inside a keep-out cone, or outside a keep-in cone).
///
/// The field of a pointing constraint is "optimal_control.keep_out[i]" or "optimal_control.keep_in[i]", i
/// counting the constraints of that kind from 1.
///
/// With reaction wheels also: the wheels themselves (validate(ReactionWheels)); a norm bound (the wheels
/// take per-wheel bounds); and momentum bounds that the final state's own wheel momenta h_f = A⁻¹ (R_fᵀ L −
/// J_b ω_f) exceed (the slew's angular momentum must fit in the wheels at the end).
std::string pointing_field(const ReorientationProblem& problem, std::size_t index);
void validate(const ReorientationProblem& problem);

}  // namespace poinsot::optimal
