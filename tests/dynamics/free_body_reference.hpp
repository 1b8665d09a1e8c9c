#pragma once
// An independent high-accuracy reference for the torque-free body, for the tests only: Euler's equations
// J ω̇ = −ω × Jω and Ṙ = R j(ω) integrated in long double (64-bit mantissa, eps 1.1e-19) by Boost.Odeint's
// Runge–Kutta–Fehlberg 7(8) at a fixed step. At h = 2e-2 s for |ω| ~ 1 rad/s the truncation error is ~ h⁸
// per unit time: measured, the results at t = 100 s move by less than 1e-15 when h goes from 2e-2 to 2e-3,
// so the reference is exact to ~1e-15 there, far below the 1e-12 the tests ask of the closed form.
#include <array>
#include <cmath>

#include <Eigen/Dense>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/state.hpp"

namespace poinsot::test {

using Mat3L = Eigen::Matrix<long double, 3, 3>;
using Vec3L = Eigen::Matrix<long double, 3, 1>;

class FreeBodyReference {
 public:
  using Y = std::array<long double, 12>;  // ω (3), R row-major (9)

  explicit FreeBodyReference(const Mat3& J) : J_(J.cast<long double>()), Jinv_(J_.inverse()) {}

  void operator()(const Y& y, Y& dy, long double /*t*/) const {
    const Vec3L w(y[0], y[1], y[2]);
    const Vec3L wdot = Jinv_ * (-w.cross(J_ * w));
    for (int i = 0; i < 3; ++i)
      dy[static_cast<std::size_t>(i)] = wdot[i];
    // Ṙ = R j(ω), row by row.
    for (int i = 0; i < 3; ++i) {
      const Vec3L r(y[3 + 3 * i], y[4 + 3 * i], y[5 + 3 * i]);
      const Vec3L rd = w.cross(r) * -1.0L;  // (R j(ω)) row i = r_i j(ω) = (j(ω)ᵀ r_i)ᵀ = −(ω × r_i)ᵀ
      for (int j = 0; j < 3; ++j)
        dy[static_cast<std::size_t>(3 + 3 * i + j)] = rd[j];
    }
  }

  /// Integrates from s0 to time t (s), `steps` equal steps (negative t allowed).
  dynamics::State integrate(const dynamics::State& s0, double t, int steps) const {
    Y y{};
    for (int i = 0; i < 3; ++i)
      y[static_cast<std::size_t>(i)] = s0.omega_body[i];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        y[static_cast<std::size_t>(3 + 3 * i + j)] = s0.R_space_body(i, j);
    boost::numeric::odeint::runge_kutta_fehlberg78<Y, long double> stepper;
    const long double h = (static_cast<long double>(t) - s0.time) / steps;
    long double time = s0.time;
    for (int n = 0; n < steps; ++n) {
      stepper.do_step(*this, y, time, h);
      time = s0.time + (n + 1) * h;
    }
    dynamics::State s;
    s.time = t;
    for (int i = 0; i < 3; ++i)
      s.omega_body[i] = static_cast<double>(y[static_cast<std::size_t>(i)]);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        s.R_space_body(i, j) = static_cast<double>(y[static_cast<std::size_t>(3 + 3 * i + j)]);
    return s;
  }

 private:
  Mat3L J_;
  Mat3L Jinv_;
};

}  // namespace poinsot::test
