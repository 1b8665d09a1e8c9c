#include "poinsot/dynamics/rk4.hpp"

#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::dynamics {
namespace {

/// ẏ of the torque-free body in a principal body frame, y = (q, ω), q̇ = ½ q ⊗ (0, ω), ω̇_i = g_i ω_j ω_k with
/// g_i = (I_j − I_k)/I_i: the hot path, in scalars so that the compiler keeps everything in registers.
struct FreePrincipalRhs {
  double g1, g2, g3;
  inline void operator()(const double* y, double* d) const {
    const double w1 = y[4], w2 = y[5], w3 = y[6];
    d[0] = -0.5 * (y[1] * w1 + y[2] * w2 + y[3] * w3);
    d[1] = 0.5 * (y[0] * w1 + y[2] * w3 - y[3] * w2);
    d[2] = 0.5 * (y[0] * w2 + y[3] * w1 - y[1] * w3);
    d[3] = 0.5 * (y[0] * w3 + y[1] * w2 - y[2] * w1);
    d[4] = g1 * w2 * w3;
    d[5] = g2 * w3 * w1;
    d[6] = g3 * w1 * w2;
  }
};

/// One classical RK4 step of the torque-free body in a principal frame, in place on y = (q, ω).
inline void free_principal_step(double* y, const FreePrincipalRhs& f, const double h) {
  double k1[7], k2[7], k3[7], k4[7], tmp[7];
  f(y, k1);
  for (int i = 0; i < 7; ++i)
    tmp[i] = y[i] + 0.5 * h * k1[i];
  f(tmp, k2);
  for (int i = 0; i < 7; ++i)
    tmp[i] = y[i] + 0.5 * h * k2[i];
  f(tmp, k3);
  for (int i = 0; i < 7; ++i)
    tmp[i] = y[i] + h * k3[i];
  f(tmp, k4);
  for (int i = 0; i < 7; ++i)
    y[i] += h / 6 * (k1[i] + 2 * (k2[i] + k3[i]) + k4[i]);
}

}  // namespace

struct Rk4Integrator::Impl {
  detail::EulerRhs f;
  detail::Vec7 y;  // (q, ω), q of unit norm
  detail::ResumeCheck resume;
  bool fast = false;  // torque-free body in a principal frame
  Vec3 gyro = Vec3::Zero();
};

Rk4Integrator::Rk4Integrator(const RigidBody& body, std::shared_ptr<const TorqueModel> torque,
                             const IntegratorOptions& options)
    : impl_(
          std::make_unique<Impl>(Impl{detail::EulerRhs(body, std::move(torque)), detail::Vec7::Zero(), {}})),
      dt_(options.dt) {
  require_positive("rk4: dt", options.dt, "s");
  impl_->fast = impl_->f.torque_free() && body.is_diagonal();
  const Vec3 I = body.inertia().diagonal();
  impl_->gyro = Vec3((I[1] - I[2]) / I[0], (I[2] - I[0]) / I[1], (I[0] - I[1]) / I[2]);
}

Rk4Integrator::~Rk4Integrator() = default;

StepResult Rk4Integrator::step(State& state, double dt) {
  Impl& m = *impl_;
  detail::Vec7& y = m.y;
  if (!m.resume.matches(state)) {
    y = detail::vec7_of(state);
  }
  const double t = state.time;
  const double h = dt;
  const double h2 = 0.5 * h;
  if (m.fast) {
    free_principal_step(y.data(), FreePrincipalRhs{m.gyro[0], m.gyro[1], m.gyro[2]}, h);
  } else {
    const detail::Vec7 k1 = m.f(t, y);
    const detail::Vec7 k2 = m.f(t + h2, y + h2 * k1);
    const detail::Vec7 k3 = m.f(t + h2, y + h2 * k2);
    const detail::Vec7 k4 = m.f(t + h, y + h * k3);
    y += (h / 6.0) * (k1 + 2.0 * (k2 + k3) + k4);
  }
  // Renormalise: |q|² = 1 + δ with δ = O(h⁵) + round-off, and q ← q (3 − |q|²)/2 is the Newton step for
  // 1/√|q|², which leaves |q| − 1 = O(δ²) (round-off) without a square root or a division in the chain
  // of dependent operations. R(q) is then orthogonal to round-off.
  y.head<4>() *= 0.5 * (3.0 - y.head<4>().squaredNorm());
  state.time = t + h;
  state.R_space_body = Quat(y[0], y[1], y[2], y[3]).toRotationMatrix();
  state.omega_body = y.tail<3>();
  m.resume.remember(state);
  return {h, dt_, 0};
}

}  // namespace poinsot::dynamics
