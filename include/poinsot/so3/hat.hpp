#pragma once
/// @file hat.hpp
/// The skew-symmetric map of the seeds, `j(u)` (Vallée & Dumitriu 2002, §1), called `hat` here, and its
/// inverse `vee`. Convention (docs/conventions.md): `j(u) v = u × v`, so
///
///     j(u) = [[ 0,  -u3,  u2],
///             [ u3,  0,  -u1],
///             [-u2,  u1,  0 ]].
///
/// With `R` mapping body to space, `Ṙ = R j(ω)` for the body-frame angular velocity ω and `Ṙ = j(Ω) R` for
/// the space-frame Ω = R ω. Both functions are exact (no rounding) and allocate nothing.

#include "poinsot/core/types.hpp"

namespace poinsot::so3 {

/// `j(u)`: the skew-symmetric matrix with `hat(u) * v == u.cross(v)` for every v.
inline Mat3 hat(const Vec3& u) {
  Mat3 m;
  m << 0.0, -u.z(), u.y(),  //
      u.z(), 0.0, -u.x(),   //
      -u.y(), u.x(), 0.0;
  return m;
}

/// `A j(u)` computed by columns, `A (u × e_k)`: 18 multiplications instead of the 27 of a 3 × 3 product (the
/// multibody integrators form `Ṙ = R j(ω)` and the joint Jacobians `R j(X)` at every stage). Equal to
/// `A * hat(u)` up to the rounding of the sums' order.
inline Mat3 times_hat(const Mat3& A, const Vec3& u) {
  Mat3 m;
  m.col(0) = u.z() * A.col(1) - u.y() * A.col(2);
  m.col(1) = u.x() * A.col(2) - u.z() * A.col(0);
  m.col(2) = u.y() * A.col(0) - u.x() * A.col(1);
  return m;
}

/// The inverse of hat on skew-symmetric matrices. For a general matrix it returns the vector of its
/// skew-symmetric part, `vee((M − Mᵀ)/2)`, which is the least-squares inverse of hat.
inline Vec3 vee(const Mat3& m) {
  return Vec3(m(2, 1) - m(1, 2), m(0, 2) - m(2, 0), m(1, 0) - m(0, 1)) * 0.5;
}

}  // namespace poinsot::so3
