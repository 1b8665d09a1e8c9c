// Detection of a heavy or free symmetric top and its theoretical predictions (see top_prediction.hpp).
#include "poinsot/dynamics/top_prediction.hpp"

#include <cmath>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/top_theory.hpp"
#include "poinsot/inertia/principal_axes.hpp"

namespace poinsot::dynamics {

std::string_view to_string(TopKind kind) {
  return kind == TopKind::heavy ? "heavy top" : "free symmetric top";
}

bool is_heavy_top(const RigidBody& body, bool gravity_torque, const Vec3& gravity_space) {
  return gravity_torque && body.has_pivot() && body.pivot_to_com().norm() > 0.0 && gravity_space.norm() > 0.0;
}

namespace {

/// The heavy top's predictions: the fast-top formulas from I1, I3 about the pivot for any body, and the exact
/// quadrature where the body is symmetric about its axis and the axis is tilted.
void predict_heavy_top(const RigidBody& body, const Vec3& gravity_space, const State& s0,
                       TopPrediction& top) {
  const HeavyTop fast{.I1 = top.moment_transverse,
                      .I3 = top.moment_axial,
                      .mass = body.mass(),
                      .length = body.pivot_to_com().norm(),
                      .gravity = gravity_space.norm()};
  if (std::abs(top.spin) > 0.0) {
    top.precession_rate_theory = fast_top_precession_rate(fast, top.spin);
    top.nutation_frequency_fast_top = top.moment_axial * std::abs(top.spin) / top.moment_transverse;
  }
  top.sleeping = is_sleeping_top_stable(fast, top.spin);
  try {
    const HeavyTop symmetric = heavy_top_from(body, gravity_space);
    const TopInitialConditions ic = top_initial_conditions(body, s0, gravity_space);
    if (std::abs(ic.omega3) > 0.0)
      top.precession_rate_theory = fast_top_precession_rate(symmetric, ic.omega3);
    top.sleeping = is_sleeping_top_stable(symmetric, ic.omega3);
    const TopMotion m = top_motion(symmetric, ic.theta, ic.theta_dot, ic.phi_dot, ic.omega3);
    top.precession_rate_exact = m.mean_precession_rate;
    top.nutation_frequency_theory = m.nutation_frequency;
    top.theta_min_theory = m.theta_min;
    top.theta_max_theory = m.theta_max;
  } catch (const InvalidInput&) {
    // Not symmetric about its axis, or upright: only the fast-top formulas apply.
  }
}

}  // namespace

std::optional<TopPrediction> predict_top(const RigidBody& body, const TorqueModel& torque,
                                         const Vec3& gravity_space, const State& s0) {
  TopPrediction top;
  if (is_heavy_top(body, torque.is_gravity(), gravity_space)) {
    top.kind = TopKind::heavy;
    top.axis_body = body.pivot_to_com().normalized();
    top.direction_space = -gravity_space.normalized();
  } else if (torque.is_zero() && !body.has_pivot()) {
    const inertia::Symmetry sym = inertia::classify(body.principal_moments());
    if (sym != inertia::Symmetry::oblate && sym != inertia::Symmetry::prolate) return std::nullopt;
    const Vec3 L = angular_momentum_space(body, s0);
    if (!(L.norm() > 0.0)) return std::nullopt;
    top.kind = TopKind::free_symmetric;
    top.axis_body = body.principal_axes().col(sym == inertia::Symmetry::oblate ? 2 : 0);
    top.direction_space = L.normalized();
  } else {
    return std::nullopt;
  }
  const Mat3& J = body.inertia();
  top.spin = s0.omega_body.dot(top.axis_body);
  top.moment_axial = top.axis_body.dot(J * top.axis_body);
  top.moment_transverse = 0.5 * (J.trace() - top.moment_axial);
  if (top.kind == TopKind::heavy) {
    predict_heavy_top(body, gravity_space, s0, top);
  } else {
    top.precession_rate_theory = angular_momentum_space(body, s0).norm() / top.moment_transverse;
  }
  return top;
}

}  // namespace poinsot::dynamics
