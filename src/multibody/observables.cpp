// Energy, momenta and constraint violation of a multibody state (observables.hpp).
#include "poinsot/multibody/observables.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::multibody {

double kinetic_energy(const System& system, const State& state) {
  double T = 0.0;
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    const Body& b = system.bodies()[i];
    const BodyState& s = state.bodies[i];
    T += 0.5 * b.mass * s.v_space.squaredNorm() + 0.5 * s.omega_body.dot(b.inertia * s.omega_body);
  }
  return T;
}

double total_energy(const System& system, const State& state) {
  return kinetic_energy(system, state) + potential_energy(system, state.bodies);
}

Vec3 linear_momentum(const System& system, const State& state) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < state.bodies.size(); ++i)
    p += system.bodies()[i].mass * state.bodies[i].v_space;
  return p;
}

Vec3 angular_momentum(const System& system, const State& state) {
  Vec3 L = Vec3::Zero();
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    const Body& b = system.bodies()[i];
    const BodyState& s = state.bodies[i];
    L += s.x_space.cross(b.mass * s.v_space) + s.R_space_body * (b.inertia * s.omega_body);
  }
  return L;
}

ConstraintViolation constraint_violation(const System& system, const State& state) {
  ConstraintViolation v;
  for (const BodyState& s : state.bodies)
    v.orthogonality = std::max(v.orthogonality, so3::orthogonality_error(s.R_space_body));
  for (const Joint& joint : system.joints()) {
    const BodyState& a = side_state(state.bodies, joint.body_a);
    const BodyState& b = side_state(state.bodies, joint.body_b);
    const int t = joint.translation_rows();
    const JointVector g = joint_value(joint, a, b);
    v.joint_gap = std::max(v.joint_gap, g.head(t).norm());
    for (int k = 0; k < joint.perpendicular_count; ++k)
      v.joint_angle = std::max(v.joint_angle, std::abs(g(t + k)));
    v.joint_velocity = std::max(v.joint_velocity, joint_velocity(joint, a, b).head(t).norm());
  }
  return v;
}

void check_body_count(const System& system, const State& state) {
  if (state.bodies.size() != static_cast<std::size_t>(system.body_count())) {
    throw InvalidInput(
        fmt::format("multibody: state has {} bodies; expected {}", state.bodies.size(), system.body_count()));
  }
}

void check_consistent(const System& system, const State& state) {
  check_body_count(system, state);
  for (std::size_t i = 0; i < state.bodies.size(); ++i) {
    const BodyState& s = state.bodies[i];
    const std::string what = fmt::format("multibody body '{}'", system.bodies()[i].name);
    require_finite(what + ": position", s.x_space);
    require_finite(what + ": rotation", s.R_space_body);
    require_finite(what + ": velocity", s.v_space);
    require_finite(what + ": angular velocity", s.omega_body);
  }
  const ConstraintViolation v = constraint_violation(system, state);
  const double L = system.length_scale();
  for (const BodyState& s : state.bodies) {
    if (!so3::is_rotation(s.R_space_body)) {
      throw InvalidInput(
          fmt::format("multibody: a rotation has |RᵀR − I| = {:.3g}; expected a rotation (< {:.0e})",
                      so3::orthogonality_error(s.R_space_body), so3::kRotationTolerance));
    }
  }
  if (v.joint_gap > 1e-9 * L || v.joint_angle > 1e-9) {
    throw InvalidInput(
        fmt::format("multibody: the initial state violates a joint (gap {:.3g} m, angle {:.3g}); expected "
                    "assembled joints "
                    "(< 1e-9 relative)",
                    v.joint_gap, v.joint_angle));
  }
}

}  // namespace poinsot::multibody
