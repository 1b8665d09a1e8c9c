#pragma once
/// @file axisymmetric.hpp
/// Λ of a torque-free axisymmetric body in closed form (Vallée & Dumitriu 2002, §§4–5, with
/// docs/conventions.md C11–C23): constant eigenvalues, the rotating eigenvector and the constant matrix EᵀΛE.
///
/// Body: `J = A I + (C − A) k⊗k` (kg·m²) about the centre of mass, k the unit symmetry axis (body frame),
/// Ω0 = ω(t0) the initial body-frame angular velocity (rad/s). Notation (docs/conventions.md conventions
/// table):
///   μ = ⟨k, Ω0⟩,  η0* = ⟨Ω0, Ω0⟩,  r = √(η0* − μ²) = |Ω0 − μk|,  n = (Ω0 − μk)/r.
/// Motion (4.2, C11): `ω(t) = E(t) Ω0`, `E(t) = exp[(t − t0)(C/A − 1) μ j(k)]` (the sign as printed).
/// Constant matrix (Property 3): `EᵀΛE = Λ(t0)`, given by
///   (5.3, C17)  −Cη0* I/2 + C ξ0*/2 − C/(2A)(C − A) μ (Ω0⊗k + k⊗Ω0) + (C − A)[η0* + (C − A)μ²/A] k⊗k
///   (5.4, C19)  −Cη0*/2 (n×k)⊗(n×k) − Cμ²/2 n⊗n + C/A (A − C/2) r μ (n⊗k + k⊗n) − (A − C/2) r² k⊗k
/// and in the basis (n, k) of the plane of k and Ω0 the 2×2 block (5.5)
///   [[−Cμ²/2, C/A (A − C/2) r μ], [C/A (A − C/2) r μ, −(A − C/2) r²]].
/// Eigenvalues (J):
///   c1 = −(A − C/2) r² − Cμ²/2,  c2 = −C(A − C/2)(1 − C/A)² r² μ²/2,  Δ = c1² + 4c2 ≥ 0 (C22),
///   λ1,2 = (c1 ∓ √Δ)/2,  λ3 = −C⟨Ω0, Ω0⟩/2 (C21: not η0²),
/// λ3's eigenvector is `k × ω(t)` (C14: not k × Ω0). λ1 ≤ λ2 ≤ 0, and λ3 may fall anywhere among them.
///
/// Numerics: Δ is evaluated as (a − d)² + 4b² from the entries a, b, d of (5.5), which equals c1² + 4c2
/// and is a sum of squares (no cancellation); λ2 is evaluated as −c2/λ1 (= (c1 + √Δ)/2, since λ1λ2 = −c2)
/// when λ1 < 0, which avoids the cancellation of c1 + √Δ when c2 is small.

#include <optional>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"

namespace poinsot::analysis {

/// An axisymmetric inertia `J = A I + (C − A) k⊗k`: A (kg·m²) about any axis ⟂ k through the centre of mass,
/// C (kg·m²) about k, k a unit vector in the body frame.
struct AxisymmetricInertia {
  double A = 1.0;
  double C = 1.0;
  Vec3 k = Vec3::UnitZ();
  /// J (kg·m², body frame).
  Mat3 inertia() const;
};

/// The axisymmetric form of body.inertia() when two principal moments agree to `relative_tolerance` × the
/// largest moment: C is the distinct moment and k its principal axis (column of principal_axes()); for a
/// ball (three equal moments) A = C = their mean and k = the third principal axis. nullopt otherwise.
std::optional<AxisymmetricInertia> detect_axisymmetry(const dynamics::RigidBody& body,
                                                      double relative_tolerance = 1e-12);

/// The special cases of Section 5, each detected to a relative tolerance.
struct AxisymmetricSpecialCases {
  bool ball = false;               ///< A = C: E = I, Λ = C j(Ω0)²/2
  bool flat = false;               ///< A = C/2 (a plane disc): c2 = 0, λ2 = 0
  bool axial_spin = false;         ///< r = 0 (Ω0 ∥ k): steady spin, λ2 = 0, (5.4) not defined
  bool equatorial_spin = false;    ///< μ = 0 (Ω0 ⟂ k): E = I, λ2 = 0
  bool zero_discriminant = false;  ///< Δ = 0: λ1 = λ2
  bool zero_velocity = false;      ///< Ω0 = 0: Λ = 0
};

class AxisymmetricLambda {
 public:
  /// Throws InvalidInput unless A > 0, C > 0, C ≤ 2A (a physical body: A − C/2 = ⟨k, K k⟩ ≥ 0,
  /// docs/conventions.md C9), |k| > 0 (normalised here) and Ω0 finite. `t0` (s) is the time at which ω = Ω0.
  AxisymmetricLambda(const AxisymmetricInertia& inertia, const Vec3& omega0_body, double t0 = 0.0,
                     double relative_tolerance = 1e-12);

  const AxisymmetricInertia& inertia() const { return inertia_; }
  const Vec3& omega0() const { return omega0_; }  ///< Ω0 (rad/s, body frame)
  double mu() const { return mu_; }               ///< μ = ⟨k, Ω0⟩ (rad/s)
  double eta0() const { return eta0_; }           ///< η0* = ⟨Ω0, Ω0⟩ (rad²/s²)
  double r() const { return r_; }                 ///< r = |Ω0 − μk| (rad/s)
  /// n = (Ω0 − μk)/r; for r = 0 any unit vector ⟂ k (deterministic choice).
  const Vec3& n() const { return n_; }
  double c1() const { return c1_; }            ///< J
  double c2() const { return c2_; }            ///< J²
  double Delta() const { return Delta_; }      ///< J²
  double lambda1() const { return lambda1_; }  ///< (c1 − √Δ)/2 (J)
  double lambda2() const { return lambda2_; }  ///< (c1 + √Δ)/2 (J)
  double lambda3() const { return lambda3_; }  ///< −C⟨Ω0, Ω0⟩/2 (J)
  /// λ1, λ2, λ3 sorted ascending (J).
  Vec3 eigenvalues_sorted() const;
  const AxisymmetricSpecialCases& special_cases() const { return special_; }

  /// The body-frame precession rate of ω about k, (C/A − 1) μ (rad/s).
  double precession_rate() const { return (inertia_.C / inertia_.A - 1.0) * mu_; }
  /// E(t) = exp[(t − t0)(C/A − 1) μ j(k)] (eq. 4.2).
  Mat3 E(double t) const;
  /// ω(t) = E(t) Ω0 (rad/s, body frame).
  Vec3 omega(double t) const;
  /// k × ω(t): the eigenvector of Λ(t) for λ3 (C14); zero when r = 0.
  Vec3 lambda3_eigenvector(double t) const;

  /// EᵀΛE (J) by eq. (5.3).
  Mat3 constant_matrix_53() const;
  /// EᵀΛE (J) by eq. (5.4) with C19 (uses n; for r = 0, n is the arbitrary unit vector ⟂ k and the formula
  /// still holds since its r-terms vanish).
  Mat3 constant_matrix_54() const;
  /// The 2×2 block (5.5) in the basis (n, k) (J).
  Eigen::Matrix2d reduced_matrix_55() const;
  /// Λ(t) = E(t) (EᵀΛE) E(t)ᵀ (J, body frame).
  Mat3 lambda_at(double t) const;

 private:
  AxisymmetricInertia inertia_;
  Vec3 omega0_;
  double t0_ = 0.0;
  double mu_ = 0.0, eta0_ = 0.0, r_ = 0.0;
  Vec3 n_ = Vec3::UnitX();
  double c1_ = 0.0, c2_ = 0.0, Delta_ = 0.0;
  double lambda1_ = 0.0, lambda2_ = 0.0, lambda3_ = 0.0;
  AxisymmetricSpecialCases special_;
  Mat3 constant_ = Mat3::Zero();
};

}  // namespace poinsot::analysis
