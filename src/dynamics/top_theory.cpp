#include "poinsot/dynamics/top_theory.hpp"

#include <fmt/format.h>
#include <algorithm>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <cmath>
#include <numbers>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::dynamics {
namespace {

using Policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

/// The cubic p(x) = f(u0 + x) = c3 x³ + c2 x² + c1 x + c0 (Horner).
struct Cubic {
  double c3, c2, c1, c0;
  double operator()(double x) const { return ((c3 * x + c2) * x + c1) * x + c0; }
};

/// A root of p in [lo, hi] where p(lo) ≤ 0 < p(hi) or p(lo) > 0 ≥ p(hi), by bisection to the last bit.
double bisect(const Cubic& p, double lo, double hi) {
  const bool rising = p(lo) <= 0.0;
  for (int i = 0; i < 2000; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid <= lo || mid >= hi) break;
    if ((p(mid) <= 0.0) == rising) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

}  // namespace

void validate(const HeavyTop& top) {
  require_positive("top: I1 (about the pivot)", top.I1, "kg·m²");
  require_positive("top: I3", top.I3, "kg·m²");
  require_positive("top: mass", top.mass, "kg");
  require_positive("top: length (pivot to centre of mass)", top.length, "m");
  require_positive("top: gravity", top.gravity, "m/s²");
}

double fast_top_precession_rate(const HeavyTop& top, double omega3) {
  validate(top);
  require_finite("top: omega3 (rad/s)", omega3);
  if (omega3 == 0.0) {
    throw InvalidInput("top: omega3 is 0 rad/s; the fast-top formula M g l/(I3 omega3) needs a spinning top");
  }
  return top.mgl() / (top.I3 * omega3);
}

SteadyPrecession steady_precession_rates(const HeavyTop& top, double theta, double omega3) {
  validate(top);
  require_finite("top: theta (rad)", theta);
  require_finite("top: omega3 (rad/s)", omega3);
  const double A = top.I1 * std::cos(theta);
  const double B = -top.I3 * omega3;
  const double C = top.mgl();
  SteadyPrecession r;
  if (std::abs(A) <= 1e-15 * std::abs(B) || A == 0.0) {  // θ = π/2: B φ̇ + C = 0
    if (B == 0.0) return r;
    r.count = 1;
    r.slow = -C / B;
    return r;
  }
  const double disc = B * B - 4.0 * A * C;
  if (disc < 0.0) return r;
  // Stable roots: q = −(B + sign(B)√disc)/2, φ̇ = q/A and C/q.
  const double q = -0.5 * (B + std::copysign(std::sqrt(disc), B == 0.0 ? 1.0 : B));
  const double r1 = q / A;
  const double r2 = C / q;
  r.count = 2;
  r.slow = std::abs(r1) < std::abs(r2) ? r1 : r2;
  r.fast = std::abs(r1) < std::abs(r2) ? r2 : r1;
  return r;
}

double sleeping_top_threshold(const HeavyTop& top) {
  validate(top);
  return std::sqrt(4.0 * top.I1 * top.mgl()) / top.I3;
}

bool is_sleeping_top_stable(const HeavyTop& top, double omega3) {
  validate(top);
  return omega3 * omega3 > 4.0 * top.I1 * top.mgl() / (top.I3 * top.I3);
}

TopMotion top_motion(const HeavyTop& top, double theta0, double theta_dot0, double phi_dot0, double omega3) {
  validate(top);
  require_finite("top: theta0 (rad)", theta0);
  require_finite("top: theta_dot0 (rad/s)", theta_dot0);
  require_finite("top: phi_dot0 (rad/s)", phi_dot0);
  require_finite("top: omega3 (rad/s)", omega3);
  if (!(theta0 > 0.0 && theta0 < std::numbers::pi)) {
    throw InvalidInput(fmt::format(
        "top: theta0 = {} rad; expected 0 < theta0 < pi (the precession angle is undefined on the vertical)",
        theta0));
  }
  const double u0 = std::cos(theta0);
  const double s2 = std::sin(theta0) * std::sin(theta0);
  const double a = top.I3 * omega3 / top.I1;
  const double b = phi_dot0 * s2 + a * u0;
  const double beta = 2.0 * top.mgl() / top.I1;
  const double kin = theta_dot0 * theta_dot0 + phi_dot0 * phi_dot0 * s2;  // α − β u0
  // f(u0 + x) expanded about u0 from the initial data, so that the small roots keep their relative precision.
  const Cubic p{beta, -kin + 2.0 * beta * u0 - a * a, -2.0 * u0 * kin - beta * s2 + 2.0 * a * phi_dot0 * s2,
                s2 * theta_dot0 * theta_dot0};
  double x1 = 0.0;
  double x2 = 0.0;
  if (p.c0 > 0.0) {
    x1 = bisect(p, -1.0 - u0, 0.0);  // p(−1 − u0) = f(−1) = −(b + a)² ≤ 0 < p(0)
    x2 = bisect(p, 0.0, 1.0 - u0);   // p(1 − u0) = f(1) = −(b − a)² ≤ 0
  } else {
    // θ̇0 = 0: u0 is a turning point; the others are the roots of β x² + c2 x + c1.
    const double disc = std::max(0.0, p.c2 * p.c2 - 4.0 * p.c3 * p.c1);
    const double q = -0.5 * (p.c2 + std::copysign(std::sqrt(disc), p.c2));
    const double ra = q != 0.0 ? q / p.c3 : 0.0;
    const double rb = q != 0.0 ? p.c1 / q : 0.0;
    const double lo = std::min(ra, rb);
    const double hi = std::max(ra, rb);
    if (p.c1 > 0.0) {  // f increasing at u0: u0 is the lowest point u1
      x2 = lo;
    } else if (p.c1 < 0.0) {  // u0 is the highest point u2
      x1 = lo;
    }
    (void)hi;
  }
  const double x3 = -p.c2 / p.c3 - x1 - x2;
  TopMotion m;
  m.u1 = u0 + x1;
  m.u2 = u0 + x2;
  m.u3 = u0 + x3;
  m.theta_min = std::acos(std::clamp(m.u2, -1.0, 1.0));
  m.theta_max = std::acos(std::clamp(m.u1, -1.0, 1.0));
  const double w = x2 - x1;
  const double d31 = x3 - x1;
  const double k = std::sqrt(std::clamp(w / d31, 0.0, 1.0));
  const double K = boost::math::ellint_1(k, Policy());
  m.nutation_period = 4.0 * K / std::sqrt(beta * d31);
  m.nutation_frequency = 2.0 * std::numbers::pi / m.nutation_period;
  double bracket = 0.0;
  if (b - a != 0.0) {
    const double n_plus = std::min(w / (1.0 - m.u1), 1.0 - 1e-16);
    bracket += (b - a) * boost::math::ellint_3(k, n_plus, Policy()) / (1.0 - m.u1);
  }
  if (b + a != 0.0) {
    const double n_minus = -w / (1.0 + m.u1);
    bracket += (b + a) * boost::math::ellint_3(k, n_minus, Policy()) / (1.0 + m.u1);
  }
  m.mean_precession_rate = bracket / (2.0 * K);
  m.precession_per_nutation = m.mean_precession_rate * m.nutation_period;
  return m;
}

HeavyTop heavy_top_from(const RigidBody& body, const Vec3& gravity_space) {
  require_finite("top: gravity (m/s²)", gravity_space);
  if (!body.has_pivot() || body.pivot_to_com().norm() == 0.0) {
    throw InvalidInput(
        "top: body has no pivot away from its centre of mass; expected RigidBody::with_pivot(mass, d) with d "
        "!= 0");
  }
  if (gravity_space.norm() == 0.0) {
    throw InvalidInput("top: gravity is (0, 0, 0) m/s²; expected a non-zero gravity vector");
  }
  const Mat3& J = body.inertia();
  const Vec3 e = body.pivot_to_com().normalized();
  HeavyTop top;
  top.I3 = e.dot(J * e);
  top.I1 = 0.5 * (J.trace() - top.I3);
  top.mass = body.mass();
  top.length = body.pivot_to_com().norm();
  top.gravity = gravity_space.norm();
  // Symmetric about e: J = I1 (1 − e⊗e) + I3 e⊗e.
  const Mat3 model = top.I1 * (Mat3::Identity() - e * e.transpose()) + top.I3 * e * e.transpose();
  const double off = (J - model).cwiseAbs().maxCoeff();
  if (off > 1e-9 * J.trace()) {
    throw InvalidInput(
        fmt::format("top: inertia about the pivot {} kg·m² is not symmetric about the "
                    "pivot-to-centre-of-mass axis {} (off by "
                    "{}); expected I1 = I2 about that axis",
                    format_matrix(J), format_vector(e), format_number(off, 3)));
  }
  return top;
}

TopInitialConditions top_initial_conditions(const RigidBody& body, const State& state,
                                            const Vec3& gravity_space) {
  heavy_top_from(body, gravity_space);  // validates
  const Vec3 e = body.pivot_to_com().normalized();
  const Vec3 up = -gravity_space.normalized();
  const Vec3 s = state.R_space_body * e;
  const Vec3 sdot = state.R_space_body * state.omega_body.cross(e);
  TopInitialConditions ic;
  const double sin_theta = up.cross(s).norm();
  ic.theta = std::atan2(sin_theta, up.dot(s));
  ic.theta_dot = sin_theta > 0.0 ? -up.dot(sdot) / sin_theta : 0.0;
  ic.phi_dot = sin_theta > 0.0 ? up.dot(s.cross(sdot)) / (sin_theta * sin_theta) : 0.0;
  ic.omega3 = state.omega_body.dot(e);
  return ic;
}

}  // namespace poinsot::dynamics
