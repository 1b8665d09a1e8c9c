#pragma once
/// @file exact_free_body.hpp
/// The torque-free rigid body in closed form: ω(t) by Jacobi elliptic functions and R(t) from the invariant
/// L_space and the rotation angle about it (incomplete elliptic integral of the third kind; Celledoni, Fassò,
/// Säfström & Zanna 2008, with Leroy's corrections), at any time t for a cost independent of t. Covers both
/// regimes |L|² ≷ 2 T I2, the separatrix, symmetric bodies and the sphere; for axisymmetric bodies also the
/// paper's eq. (4.2), R(t) = exp[t j(L/A)] E(t)ᵀ.

#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"

namespace poinsot::dynamics {

/// Evaluates the exact free motion from an initial state. Construction does the set-up (principal frame,
/// regime, elliptic modulus, constants); state_at(t) costs the same for every t.
class ExactFreeBody {
 public:
  /// Throws InvalidInput for a body with a pivot (gravity is not torque-free).
  ExactFreeBody(const RigidBody& body, const State& initial);
  /// The state at time t (s), any t (also before the initial time).
  State state_at(double t) const;

  /// For an asymmetric body (I1 < I2 < I3) away from the separatrix: the period of ω(t) (s), 4K(k)/ω_p.
  /// 0 when ω is constant or the motion is on the separatrix (infinite period).
  double omega_period() const;
  /// The interval between two successive flips of the intermediate axis (sign changes of ω2), 2K(k)/ω_p (s);
  /// 0 when ω2 never changes sign (steady rotation about a principal axis, symmetric bodies, the separatrix).
  double flip_interval() const;
};

}  // namespace poinsot::dynamics
