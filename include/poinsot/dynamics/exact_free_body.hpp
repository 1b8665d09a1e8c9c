#pragma once
/// @file exact_free_body.hpp
/// The torque-free rigid body in closed form: ω(t) by Jacobi elliptic functions and R(t) from the invariant
/// L_space and the rotation angle about it (incomplete elliptic integral of the third kind; Celledoni, Fassò,
/// Säfström & Zanna 2008, with Leroy's corrections), at any time t for a cost independent of t. Covers both
/// regimes |L|² ≷ 2 T I2, the separatrix, symmetric bodies and the sphere; for axisymmetric bodies also the
/// paper's eq. (4.2), R(t) = exp[t j(L/A)] E(t)ᵀ.
///
/// Method (docs/exact.md has the derivation). In the principal frame (moments I1 ≤ I2 ≤ I3, axes the columns
/// P of RigidBody::principal_axes(), a proper rotation), ω(t) is Landau's Jacobi-elliptic solution
/// (free_body_theory.hpp) with phase u = ω_p (t − t0) + u0. Let c be a polar axis, 3 or 1 (both are valid in
/// both regimes, since the component of ω that follows dn never vanishes), o the other extreme axis, and
/// (a, b, c) the cyclic order ending in c. With n = L_body/|L| and B(n) the rotation with rows
/// ((n_b, −n_a, 0)/s, (n_c n_a, n_c n_b, −s²)/s, n), s = √(n_a² + n_b²) (the Euler angles θ, ψ of L in the
/// body, Landau & Lifshitz §37), the attitude is
///
///     R_principal(t) = R_principal(t0) B(t0)ᵀ Rz(φ(t)) B(t),
///     φ̇ = |L| (2T − L_c²/I_c)/(|L|² − L_c²) = |L|/I_c + |L| (1/I_o − 1/I_c) / (1 − N sn²u),
///     N = −I3 d1 q/(I1 d3) for c = 3,  N = −I1 d3 q/(I3 d1) for c = 1,
///
/// with d1 = |L|² − 2T I1, d3 = 2T I3 − |L|², q = k² when L_c follows dn and 1 when it follows cn. The two
/// N multiply to k²; the polar axis with the smaller |N| is taken (|N| → ∞ for a nearly symmetric body
/// with the other one). In the regime around axis 3 with c = 3, N = −I3(I2 − I1)/(I1(I3 − I2)).
///
/// so φ(t) = |L| t/I_c + |L| (1/I_o − 1/I_c)/ω_p · [Π(N; am u | k) − Π(N; am u0 | k)], with Π the incomplete
/// elliptic integral of the third kind, continued beyond am u = ±π/2 by Π(N; φ + mπ) = Π(N; φ) + 2m Π(N).
/// Π is evaluated through Carlson's form Π(N; am u) = u + (N/3) sn³ R_J(cn², dn², 1, 1 − N sn²) for
/// |u| ≤ K (Boost.Math ellint_rj), and sn, cn, dn, K from the complementary modulus (jacobi_elliptic.hpp),
/// which keeps full precision near the separatrix.
/// On the separatrix ∫du/(1 − N tanh²u) = [u + √−N atan(√−N tanh u)]/(1 − N). Axisymmetric bodies (and the
/// sphere) use eq. (4.2) of Vallée & Dumitriu (docs/conventions.md C11); steady rotations R(t) = R0 exp[(t −
/// t0) j(ω0)].
///
/// Units: t in s, ω in rad/s, J in kg·m². The body's J is taken about its rotation point
/// (RigidBody::inertia()), so a body held at a pivot with no torque is also covered.

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/dynamics/jacobi_elliptic.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"

namespace poinsot::dynamics {

/// Which closed form evaluates the motion.
enum class ExactMethod {
  automatic,  ///< by regime: eq. (4.2) for symmetric bodies, Jacobi elliptic functions otherwise
  elliptic,   ///< the Jacobi-elliptic form also for a body with I1 = I2 < I3 or I1 < I2 = I3 exactly (k = 0)
};

/// Evaluates the exact free motion from an initial state. Construction does the set-up (principal frame,
/// regime, elliptic modulus, constants: a few µs); state_at(t) costs the same for every t (< 1 µs).
class ExactFreeBody {
 public:
  /// Throws InvalidInput for an invalid initial state (validate_state) or, with ExactMethod::elliptic, a
  /// body or state the elliptic form does not cover (sphere, rest, a symmetric body spinning in its
  /// equatorial plane).
  ExactFreeBody(const RigidBody& body, const State& initial, ExactMethod method = ExactMethod::automatic);
  /// The state at time t (s), any t (also before the initial time). Allocates nothing.
  State state_at(double t) const;

  /// The theory of this motion (regime, k, ω_p, K) in the principal frame.
  const FreeBodyTheory& theory() const { return theory_; }
  FreeBodyRegime regime() const { return theory_.regime; }
  const State& initial() const { return initial_; }

  /// The period of ω(t) (s): 4K(k)/ω_p for an asymmetric body off the separatrix, 2π/ω_p for an
  /// axisymmetric body; 0 when ω is constant or the motion is on the separatrix (infinite period).
  double omega_period() const { return theory_.omega_period(); }
  /// The interval between two successive flips of the intermediate axis (sign changes of ω2), 2K(k)/ω_p (s);
  /// 0 when ω2 never changes sign (steady rotation about a principal axis, symmetric bodies, the separatrix).
  double flip_interval() const { return theory_.flip_interval(); }

 private:
  enum class Kind { steady, axisymmetric, elliptic, separatrix };
  struct Phase {
    double sn, cn, dn;  // Jacobi functions at u
    double pi_minus_u;  // Π(N; am u | k) − u, continued beyond am u = ±π/2 (or its separatrix form)
  };
  Phase phase(double u) const;
  Mat3 attitude_frame(const Vec3& omega_principal) const;  // B(n) in the cyclic frame (a, b, c)

  FreeBodyTheory theory_;
  State initial_;
  Kind kind_ = Kind::steady;
  Mat3 axes_ = Mat3::Identity();  // P: principal axes in the body frame (columns)
  Vec3 moments_ = Vec3::Ones();   // I1 ≤ I2 ≤ I3 (kg·m²) as used by the formulas
  // Axisymmetric (eq. 4.2), principal frame.
  int axis_ = 2;           // index of the symmetry axis
  double precession_ = 0;  // (C/A − 1) μ (rad/s)
  Vec3 omega0_ = Vec3::Zero();
  Vec3 l_over_a_ = Vec3::Zero();  // L/A (rad/s)
  Mat3 r0_ = Mat3::Identity();    // R_principal(t0)
  // Elliptic.
  int a_ = 0, b_ = 1, c_ = 2;      // cyclic frame (a, b, c), c the axis ω circles
  Vec3 amplitude_ = Vec3::Zero();  // signed a1, a2, a3 (rad/s)
  int cn_axis_ = 0, dn_axis_ = 2;  // which component follows cn, which dn (sn: axis 1)
  JacobiElliptic jacobi_;
  double two_k_ = 0;     // 2K(k)
  double pi_shift_ = 0;  // 2(Π(N) − K): the advance of Π − F per half period 2K
  double n_ = 0;         // the characteristic N ≤ 0
  double kc2_ = 1;       // k'²
  double u0_ = 0, corr0_ = 0, omega_p_ = 0;
  double rate_lin_ = 0, rate1_ = 0;  // φ = rate_lin (t − t0) + rate1 [(Π − u)(u) − (Π − u)(u0)]
  Mat3 left_ = Mat3::Identity();     // R_principal(t0) B(t0)ᵀ
};

/// Vallée & Dumitriu eq. (4.2) (with docs/conventions.md C11): the free motion of an axisymmetric body J =
/// A·1 + (C − A) e⊗e (A, C in kg·m², e a unit vector in the body frame): with μ = ⟨e, ω0⟩, E(t) = exp[t (C/A
/// − 1) μ j(e)],
///     ω(t) = E(t) ω0,   R(t) = R0 exp[t j(J ω0/A)] E(t)ᵀ   (t measured from initial.time; order R·E, not
///     E·R).
/// No validation beyond finiteness; A, C > 0.
State axisymmetric_free_motion(double A, double C, const Vec3& axis_body, const State& initial, double t);

}  // namespace poinsot::dynamics
