#include "poinsot/dynamics/state.hpp"

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::dynamics {

Quat State::quaternion() const {
  return so3::quaternion_from_rotation(R_space_body);
}

double kinetic_energy(const RigidBody& body, const State& s) {
  return 0.5 * s.omega_body.dot(body.inertia() * s.omega_body);
}

Vec3 angular_momentum_body(const RigidBody& body, const State& s) {
  return body.inertia() * s.omega_body;
}

Vec3 angular_momentum_space(const RigidBody& body, const State& s) {
  return s.R_space_body * (body.inertia() * s.omega_body);
}

double potential_energy(const RigidBody& body, const State& s, const Vec3& gravity_space) {
  if (!body.has_pivot()) return 0.0;
  return -body.mass() * gravity_space.dot(s.R_space_body * body.pivot_to_com());
}

double total_energy(const RigidBody& body, const State& s, const Vec3& gravity_space) {
  return kinetic_energy(body, s) + potential_energy(body, s, gravity_space);
}

void validate_state(const State& s, const char* what) {
  require_finite(fmt::format("{}: t (s)", what), s.time);
  require_finite(fmt::format("{}: omega_body (rad/s)", what), s.omega_body);
  require_finite(fmt::format("{}: R", what), s.R_space_body);
  if (!so3::is_rotation(s.R_space_body)) {
    throw InvalidInput(
        fmt::format("{}: R is not a rotation (|R^T R - I| = {:.3g}, det = {:.6g}); expected a proper "
                    "rotation to {:.0e}",
                    what, so3::orthogonality_error(s.R_space_body), s.R_space_body.determinant(),
                    so3::kRotationTolerance));
  }
}

}  // namespace poinsot::dynamics
