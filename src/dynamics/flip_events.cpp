#include "poinsot/dynamics/flip_events.hpp"

#include <cmath>
#include <cstdint>

#include <boost/math/tools/toms748_solve.hpp>

namespace poinsot::dynamics {

FlipDetector::FlipDetector(const RigidBody& body, std::shared_ptr<const TorqueModel> torque)
    : J_(body.inertia()), e2_(body.principal_axes().col(1)), torque_(std::move(torque)) {
  const Vec3& I = body.principal_moments();
  const double tol = 1e-12 * I[2];
  applicable_ = (I[1] - I[0] > tol) && (I[2] - I[1] > tol);
}

double FlipDetector::component(const Vec3& omega_body) const {
  return e2_.dot(J_ * omega_body);
}

double FlipDetector::rate(const State& s) const {
  if (!torque_ || torque_->is_zero()) return free_rate(s.omega_body);
  Vec3 rhs = -s.omega_body.cross(J_ * s.omega_body);
  rhs += torque_->torque_body(s.time, s.R_space_body, s.omega_body);
  return e2_.dot(rhs);
}

double FlipDetector::free_rate(const Vec3& omega_body) const {
  const Vec3 rhs = -omega_body.cross(J_ * omega_body);
  return e2_.dot(rhs);
}

double locate_sign_change(double (*g)(double, const void*), const void* context, double t0, double t1,
                          double g0, double g1) {
  if (g1 == 0.0) return t1;
  if (g0 == 0.0) return t0;
  std::uintmax_t max_iter = 100;
  const auto f = [&](double t) { return g(t, context); };
  const auto r = boost::math::tools::toms748_solve(f, t0, t1, g0, g1,
                                                   boost::math::tools::eps_tolerance<double>(52), max_iter);
  return 0.5 * (r.first + r.second);
}

double FlipDetector::hermite_root(double t0, double t1, double s0, double s1, double r0, double r1) {
  struct Cubic {
    double t0, h, s0, s1, m0, m1;
  };
  const double h = t1 - t0;
  const Cubic c{t0, h, s0, s1, h * r0, h * r1};
  const auto eval = [](double t, const void* ctx) {
    const auto& q = *static_cast<const Cubic*>(ctx);
    const double x = (t - q.t0) / q.h;
    const double x2 = x * x;
    const double x3 = x2 * x;
    return (2 * x3 - 3 * x2 + 1) * q.s0 + (x3 - 2 * x2 + x) * q.m0 + (-2 * x3 + 3 * x2) * q.s1 +
           (x3 - x2) * q.m1;
  };
  return locate_sign_change(eval, &c, t0, t1, s0, s1);
}

}  // namespace poinsot::dynamics
