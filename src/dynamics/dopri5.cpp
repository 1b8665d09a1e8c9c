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
  Impl(detail::EulerRhs rhs, const IntegratorOptions& o) : f(std::move(rhs)), opt(o) {}
  detail::EulerRhs f;
  IntegratorOptions opt;
  Vec7 y = Vec7::Zero();
  Vec7 k1 = Vec7::Zero();  // f(t, y), first stage of the next step (FSAL)
  bool k1_valid = false;
  detail::ResumeCheck resume;
  detail::StepController control{0.2 - 0.04 * 0.75, 0.04, 10.0, 5.0};
  std::array<Vec7, 5> rcont{};  // dense output coefficients of the last step
  double t_old = 0.0;
  double h_old = 0.0;
  bool has_step = false;
};

Dopri5Integrator::Dopri5Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                                   const IntegratorOptions& options)
    : impl_(std::make_unique<Impl>(detail::EulerRhs(body, std::move(torque)), options)) {
  detail::require_adaptive_options("dopri5", options);
}

Dopri5Integrator::~Dopri5Integrator() = default;

double Dopri5Integrator::nominal_step() const {
  return impl_->opt.dt;
}

StepResult Dopri5Integrator::step(State& state, double dt) {
  Impl& m = *impl_;
  if (!m.resume.matches(state)) {
    m.y = detail::vec7_of(state);
    m.k1_valid = false;
  }
  const double t = state.t;
  const Vec7& y = m.y;
  if (!m.k1_valid) m.k1 = m.f(t, y);
  const Vec7& k1 = m.k1;
  double h = std::min(dt, m.opt.dt);
  if (!(h > 0.0)) {
    throw InvalidInput(fmt::format("dopri5: step dt = {} s at t = {} s; expected dt > 0", h, t));
  }
  int rejected = 0;
  for (;;) {
    if (rejected > 0 && !(h > 1e-14 * std::max(1.0, std::abs(t)))) {
      throw ComputationFailed(fmt::format(
          "dopri5: step size {:.3g} s too small at t = {} s after {} rejections; expected a step that "
          "meets rtol = {:.3g}, atol = {:.3g} (stiff or singular motion?)",
          h, t, rejected, m.opt.rtol, m.opt.atol));
    }
    const Vec7 k2 = m.f(t + c2 * h, y + h * (a21 * k1));
    const Vec7 k3 = m.f(t + c3 * h, y + h * (a31 * k1 + a32 * k2));
    const Vec7 k4 = m.f(t + c4 * h, y + h * (a41 * k1 + a42 * k2 + a43 * k3));
    const Vec7 k5 = m.f(t + c5 * h, y + h * (a51 * k1 + a52 * k2 + a53 * k3 + a54 * k4));
    const Vec7 k6 = m.f(t + h, y + h * (a61 * k1 + a62 * k2 + a63 * k3 + a64 * k4 + a65 * k5));
    const Vec7 y1 = y + h * (a71 * k1 + a73 * k3 + a74 * k4 + a75 * k5 + a76 * k6);
    const Vec7 k7 = m.f(t + h, y1);
    const Vec7 e = h * (e1 * k1 + e3 * k3 + e4 * k4 + e5 * k5 + e6 * k6 + e7 * k7);
    const Vec7 sk = detail::error_scale(y, y1, m.opt.rtol, m.opt.atol);
    const double err = std::sqrt(e.cwiseQuotient(sk).squaredNorm() / 7.0);
    if (err <= 1.0 && y1.allFinite()) {
      const double h_next = std::min(m.control.accept(h, err), m.opt.dt);
      const Vec7 ydiff = y1 - y;
      const Vec7 bspl = h * k1 - ydiff;
      m.rcont[0] = y;
      m.rcont[1] = ydiff;
      m.rcont[2] = bspl;
      m.rcont[3] = ydiff - h * k7 - bspl;
      m.rcont[4] = h * (d1 * k1 + d3 * k3 + d4 * k4 + d5 * k5 + d6 * k6 + d7 * k7);
      m.t_old = t;
      m.h_old = h;
      m.has_step = true;
      m.y = y1;
      m.k1 = k7;
      m.k1_valid = detail::accept_step(m.y, t + h, state, m.resume);
      return {h, h_next, rejected};
    }
    ++rejected;
    h = m.control.reject(h, err);
  }
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
  out.t = t;
  out.R = detail::rotation_of(y);
  out.omega_body = y.tail<3>();
  return out;
}

}  // namespace poinsot::dynamics
