#include "poinsot/dynamics/dopri5.hpp"

#include <array>
#include <cmath>

#include <fmt/format.h>

#include "adaptive_control.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::dynamics {
namespace {
using detail::Vec7;

// Butcher tableau of Dormand & Prince (1980), RK5(4)7M.
constexpr double c2 = 1.0 / 5, c3 = 3.0 / 10, c4 = 4.0 / 5, c5 = 8.0 / 9;
constexpr double a21 = 1.0 / 5;
constexpr double a31 = 3.0 / 40, a32 = 9.0 / 40;
constexpr double a41 = 44.0 / 45, a42 = -56.0 / 15, a43 = 32.0 / 9;
constexpr double a51 = 19372.0 / 6561, a52 = -25360.0 / 2187, a53 = 64448.0 / 6561, a54 = -212.0 / 729;
constexpr double a61 = 9017.0 / 3168, a62 = -355.0 / 33, a63 = 46732.0 / 5247, a64 = 49.0 / 176,
                 a65 = -5103.0 / 18656;
constexpr double a71 = 35.0 / 384, a73 = 500.0 / 1113, a74 = 125.0 / 192, a75 = -2187.0 / 6784,
                 a76 = 11.0 / 84;
// e = b − b̂ (the difference of the 5th- and 4th-order weights).
constexpr double e1 = 71.0 / 57600, e3 = -71.0 / 16695, e4 = 71.0 / 1920, e5 = -17253.0 / 339200,
                 e6 = 22.0 / 525, e7 = -1.0 / 40;
// Dense output of order 4 (Shampine 1986, as in Hairer's DOPRI5).
constexpr double d1 = -12715105075.0 / 11282082432.0, d3 = 87487479700.0 / 32700410799.0,
                 d4 = -10690763975.0 / 1880347072.0, d5 = 701980252875.0 / 199316789632.0,
                 d6 = -1453857185.0 / 822651844.0, d7 = 69997945.0 / 29380423.0;
}  // namespace

struct Dopri5Integrator::Impl {
  Impl(detail::EulerRhs rhs, const IntegratorOptions& o)
      : loop(kName, std::move(rhs), o, detail::StepController{0.2 - 0.04 * 0.75, 0.04, 10.0, 5.0}) {}
  detail::AdaptiveLoop loop;
  std::array<Vec7, 7> k{};      // the stages of the attempt; k[0] = f(t, y) (first same as last)
  Vec7 y1 = Vec7::Zero();       // the attempt's result
  std::array<Vec7, 5> rcont{};  // dense output coefficients of the last step
  double t_old = 0.0;
  double h_old = 0.0;
  bool has_step = false;

  /// One attempt of step h from (t, y): the stages k[1..6], y1 and k[6] = f(t + h, y1); the scaled error.
  double attempt(double t, const Vec7& y, double h) {
    const detail::EulerRhs& f = loop.f;
    const Vec7& k1 = k[0];
    k[1] = f(t + c2 * h, y + h * (a21 * k1));
    k[2] = f(t + c3 * h, y + h * (a31 * k1 + a32 * k[1]));
    k[3] = f(t + c4 * h, y + h * (a41 * k1 + a42 * k[1] + a43 * k[2]));
    k[4] = f(t + c5 * h, y + h * (a51 * k1 + a52 * k[1] + a53 * k[2] + a54 * k[3]));
    k[5] = f(t + h, y + h * (a61 * k1 + a62 * k[1] + a63 * k[2] + a64 * k[3] + a65 * k[4]));
    y1 = y + h * (a71 * k1 + a73 * k[2] + a74 * k[3] + a75 * k[4] + a76 * k[5]);
    k[6] = f(t + h, y1);
    const Vec7 e = h * (e1 * k1 + e3 * k[2] + e4 * k[3] + e5 * k[4] + e6 * k[5] + e7 * k[6]);
    const Vec7 sk = detail::error_scale(y, y1, loop.opt.rtol, loop.opt.atol);
    return std::sqrt(e.cwiseQuotient(sk).squaredNorm() / 7.0);
  }

  /// Keeps the dense output of the accepted step and the first stage of the next.
  void accept(double t, const Vec7& y, double h) {
    const Vec7 ydiff = y1 - y;
    const Vec7 bspl = h * k[0] - ydiff;
    rcont[0] = y;
    rcont[1] = ydiff;
    rcont[2] = bspl;
    rcont[3] = ydiff - h * k[6] - bspl;
    rcont[4] = h * (d1 * k[0] + d3 * k[2] + d4 * k[3] + d5 * k[4] + d6 * k[5] + d7 * k[6]);
    t_old = t;
    h_old = h;
    has_step = true;
    k[0] = k[6];
  }
};

Dopri5Integrator::Dopri5Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                   const IntegratorOptions& options)
    : impl_(std::make_unique<Impl>(detail::EulerRhs(body, std::move(torque)), options)) {}

Dopri5Integrator::~Dopri5Integrator() = default;

double Dopri5Integrator::nominal_step() const {
  return impl_->loop.opt.dt;
}

StepResult Dopri5Integrator::step(State& state, double dt) {
  Impl& m = *impl_;
  return m.loop.step(
      state, dt, m.k[0], m.y1, [&m](double t, const Vec7& y, double h) { return m.attempt(t, y, h); },
      [&m](double t, const Vec7& y, double h) { m.accept(t, y, h); });
}

State Dopri5Integrator::dense_output(double t) const {
  const Impl& m = *impl_;
  if (!m.has_step) {
    throw InvalidInput(fmt::format("dopri5: dense output at t = {} s asked before any step", t));
  }
  const double s = (t - m.t_old) / m.h_old;
  const double s1 = 1.0 - s;
  const Vec7 y = m.rcont[0] + s * (m.rcont[1] + s1 * (m.rcont[2] + s * (m.rcont[3] + s1 * m.rcont[4])));
  State out;
  out.time = t;
  out.R_space_body = detail::rotation_of(y);
  out.omega_body = y.tail<3>();
  return out;
}

}  // namespace poinsot::dynamics
