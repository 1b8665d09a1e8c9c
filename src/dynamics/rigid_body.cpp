#include "poinsot/dynamics/rigid_body.hpp"

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/validity.hpp"

namespace poinsot::dynamics {

RigidBody RigidBody::from_principal_moments(const Vec3& moments) {
  require_finite("body: principal_moments", moments);
  for (int i = 0; i < 3; ++i) {
    if (!(moments[i] > 0.0)) {
      throw InvalidInput(
          fmt::format("body: principal_moments {} kg·m²: moment {} is {}; expected every moment > 0",
                      format_vector(moments), i + 1, moments[i]));
    }
  }
  RigidBody b;
  b.inertia_com_ = moments.asDiagonal();
  inertia::require_valid_inertia(b.inertia_com_, "body: principal_moments");
  b.derive();
  return b;
}

RigidBody RigidBody::from_inertia(const Mat3& inertia_com_body) {
  inertia::require_valid_inertia(inertia_com_body, "body: inertia");
  RigidBody b;
  b.inertia_com_ = 0.5 * (inertia_com_body + inertia_com_body.transpose());
  b.derive();
  if (!(b.principal_moments_[0] > 0.0)) {
    throw InvalidInput(
        fmt::format("body: inertia has principal moments {} kg·m²; expected all > 0 (a body with a "
                    "zero moment is a point mass or a thin rod, whose rotation about its axis is "
                    "undefined)",
                    format_vector(b.principal_moments_)));
  }
  return b;
}

RigidBody RigidBody::with_pivot(double mass, const Vec3& pivot_to_com_body) const {
  require_positive("body: mass", mass, "kg");
  require_finite("body: pivot_to_com (m)", pivot_to_com_body);
  RigidBody b = *this;
  b.mass_ = mass;
  b.pivot_to_com_ = pivot_to_com_body;
  b.has_pivot_ = true;
  b.derive();
  return b;
}

void RigidBody::derive() {
  inertia_ =
      has_pivot_ ? inertia::shift_from_com(inertia_com_, mass_, pivot_to_com_, Vec3::Zero()) : inertia_com_;
  inertia_inverse_ = inertia_.inverse();
  poinsot_ = inertia::poinsot_from_inertia(inertia_);
  diagonal_ = inertia_(0, 1) == 0.0 && inertia_(0, 2) == 0.0 && inertia_(1, 2) == 0.0;
  const inertia::PrincipalAxes pa = inertia::principal_axes(inertia_);
  principal_moments_ = pa.moments;
  principal_axes_ = pa.axes;
}

}  // namespace poinsot::dynamics
