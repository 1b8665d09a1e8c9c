#pragma once
/// @file top_theory.hpp
/// The heavy symmetric top in closed form (Goldstein, Classical Mechanics, 3rd ed., §5.7): a body with
/// I1 = I2 about the pivot (kg·m²) and I3 about its symmetry axis (kg·m²), mass M (kg), the centre of mass at
/// distance l (m) from the pivot along the axis, in uniform gravity g (m/s²) pointing down (−z). Euler
/// angles: θ the tilt of the axis (pivot → centre of mass) from the upward vertical, φ the precession about
/// +z, ψ the spin; ω3 = ψ̇ + φ̇ cos θ is the (conserved) spin component along the axis (rad/s).
///
/// With u = cos θ, a = I3 ω3/I1, b = p_φ/I1 = φ̇ sin²θ + a u, β = 2 M g l/I1 and α = 2E'/I1 (E' = I1(θ̇² +
/// φ̇² sin²θ)/2 + M g l u), the energy equation is
///
///     u̇² = f(u) = (1 − u²)(α − β u) − (b − a u)²,      φ̇ = (b − a u)/(1 − u²),
///
/// a cubic with roots u1 ≤ u2 ≤ 1 ≤ u3: the axis nods (nutation) between θ = acos u2 and acos u1. With
/// m = k² = (u2 − u1)/(u3 − u1), the nutation period and the mean precession rate are, exactly,
///
///     T_nut = 2∫_{u1}^{u2} du/√f = 4 K(k)/√(β(u3 − u1)),
///     Ω̄ = Δφ/T_nut = [(b − a) Π(n₊|k)/(1 − u1) + (b + a) Π(n₋|k)/(1 + u1)] / (2 K(k)),
///     n₊ = (u2 − u1)/(1 − u1),  n₋ = −(u2 − u1)/(1 + u1),
///
/// from u = u1 + (u2 − u1) sin²s and (b − a u)/(1 − u²) = ½[(b − a)/(1 − u) + (b + a)/(1 + u)]; K and Π are
/// the complete elliptic integrals of the first and third kinds (Boost.Math). For a fast top Ω̄ tends to
/// the gyroscopic formula of the notes, M g l/(I3 ω3), with a relative error of order I1 M g l/(I3 ω3)²
/// (docs/conventions.md B3), and the nutation frequency 2π/T_nut to a = I3 ω3/I1.

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"

namespace poinsot::dynamics {

/// The constant parameters of a heavy symmetric top (SI units).
struct HeavyTop {
  double I1 = 0.0;        ///< kg·m², transverse moment about the pivot (I1 = I2)
  double I3 = 0.0;        ///< kg·m², moment about the symmetry axis
  double mass = 0.0;      ///< kg
  double length = 0.0;    ///< m, pivot to centre of mass
  double gravity = 9.81;  ///< m/s², magnitude of g
  double mgl() const { return mass * gravity * length; }  ///< M g l (N·m)
};

/// Throws InvalidInput unless every parameter is finite and positive.
void validate(const HeavyTop& top);

/// The gyroscopic (fast-top) precession rate of the notes, Ω = M g l/(I3 ω3) (rad/s), docs/conventions.md B3:
/// an approximation that neglects nutation and the transverse angular momentum. Throws for ω3 = 0.
double fast_top_precession_rate(const HeavyTop& top, double omega3);

/// The two rates of steady precession at tilt θ (rad) and spin ω3 (rad/s): the roots of
/// I1 cos θ φ̇² − I3 ω3 φ̇ + M g l = 0 (θ̈ = 0 in Lagrange's equation for θ). `slow` → M g l/(I3 ω3) and
/// `fast` → I3 ω3/(I1 cos θ) for a fast top. At θ = π/2 only the slow root exists (`count` = 1); for
/// cos θ > 0 both are real only when I3² ω3² ≥ 4 I1 M g l cos θ (`count` = 0 otherwise).
struct SteadyPrecession {
  int count = 0;      ///< number of real roots: 0, 1 or 2
  double slow = 0.0;  ///< rad/s, the root of smaller magnitude
  double fast = 0.0;  ///< rad/s, the other root (0 when count < 2)
};
SteadyPrecession steady_precession_rates(const HeavyTop& top, double theta, double omega3);

/// The sleeping-top criterion: a top spinning upright is stable when ω3² > 4 I1 M g l / I3² (I1 about the
/// pivot). Returns the threshold spin √(4 I1 M g l)/I3 (rad/s).
double sleeping_top_threshold(const HeavyTop& top);
bool is_sleeping_top_stable(const HeavyTop& top, double omega3);

/// The exact motion of the top's axis from θ0 ∈ (0, π) (rad), θ̇0 and φ̇0 (rad/s) and spin ω3 (rad/s).
struct TopMotion {
  double u1 = 0.0, u2 = 0.0, u3 = 0.0;   ///< roots of f(u), u1 ≤ u2 ≤ 1 ≤ u3
  double theta_min = 0.0;                ///< rad, acos u2 (highest position of the axis)
  double theta_max = 0.0;                ///< rad, acos u1 (lowest)
  double nutation_period = 0.0;          ///< s, T_nut
  double nutation_frequency = 0.0;       ///< rad/s, 2π/T_nut
  double precession_per_nutation = 0.0;  ///< rad, Δφ over one nutation period
  double mean_precession_rate = 0.0;     ///< rad/s, Ω̄ = Δφ/T_nut
};
/// Throws InvalidInput for invalid parameters or θ0 outside (0, π).
TopMotion top_motion(const HeavyTop& top, double theta0, double theta_dot0, double phi_dot0, double omega3);

/// The top of a RigidBody held at a pivot (RigidBody::with_pivot) in gravity g (space frame, m/s²): I3 = eᵀJe
/// and I1 = (tr J − I3)/2 about the pivot with e = d/|d| the pivot-to-centre-of-mass axis, M = mass(),
/// l = |d|, g = |g|. Throws InvalidInput unless the body has a pivot and J is symmetric about e (J e = I3 e
/// and the two transverse moments equal, to 1e-9 of tr J), and g ≠ 0.
HeavyTop heavy_top_from(const RigidBody& body, const Vec3& gravity_space);

/// The initial data of top_motion() from a state of that body: θ = the angle between the axis R e and "up"
/// (−g/|g|), θ̇ = −up·ṡ/sin θ and φ̇ = up·(s × ṡ)/sin²θ with s = R e, ṡ = R(ω × e), and ω3 = ω·e (rad, rad/s).
struct TopInitialConditions {
  double theta = 0.0, theta_dot = 0.0, phi_dot = 0.0, omega3 = 0.0;
};
TopInitialConditions top_initial_conditions(const RigidBody& body, const State& state,
                                            const Vec3& gravity_space);

}  // namespace poinsot::dynamics
