#include "poinsot/dynamics/rk4.hpp"

#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::dynamics {
namespace {

/// ẏ of the torque-free body in a principal body frame, y = (q, ω), q̇ = ½ q ⊗ (0, ω), ω̇_i = g_i ω_j ω_k with
/// g_i = (I_j − I_k)/I_i: the hot path, in scalars so that the compiler keeps everything in registers. The
/// quaternion part is returned as the sums S with q̇ = (−S₀, S₁, S₂, S₃)/2, so that the factor ½ joins the
/// step's coefficient (a product by a power of two is exact: (c·½)·S rounds as c·(½·S), bit for bit, for any
/// S above the subnormal range), one multiplication less in the chain of dependent operations.
struct FreePrincipalRhs {
  double g1, g2, g3;
  inline __attribute__((always_inline)) void operator()(const double* y, double* d) const {
    const double w1 = y[4], w2 = y[5], w3 = y[6];
    d[0] = y[1] * w1 + y[2] * w2 + y[3] * w3;
    d[1] = y[0] * w1 + y[2] * w3 - y[3] * w2;
    d[2] = y[0] * w2 + y[3] * w1 - y[1] * w3;
    d[3] = y[0] * w3 + y[1] * w2 - y[2] * w1;
    d[4] = g1 * w2 * w3;
    d[5] = g2 * w3 * w1;
    d[6] = g3 * w1 * w2;
  }
};

/// One classical RK4 step of the torque-free body in a principal frame, in place on y = (q, ω):
/// y ← (y + h/6 (k₁ + 2(k₂ + k₃))) + h/6 k₄ with the stages y + h/2 k₁, y + h/2 k₂, y + h k₃, the quaternion
/// rates kept as the sums of FreePrincipalRhs (coefficient c becomes ±c/2).
inline __attribute__((always_inline)) void free_principal_step(double* y, const FreePrincipalRhs& f,
                                                               const double h) {
  const double half = 0.5 * h;
  const double sixth = h / 6;
  // The coefficients of the stages and of the sum, for the quaternion sums (±½ folded in) and for ω.
  const double c_half[7] = {-0.5 * half, 0.5 * half, 0.5 * half, 0.5 * half, half, half, half};
  const double c_full[7] = {-0.5 * h, 0.5 * h, 0.5 * h, 0.5 * h, h, h, h};
  const double c_sum[7] = {-0.5 * sixth, 0.5 * sixth, 0.5 * sixth, 0.5 * sixth, sixth, sixth, sixth};
  double k1[7], k2[7], k3[7], k4[7], tmp[7];
  f(y, k1);
  for (int i = 0; i < 7; ++i)
    tmp[i] = y[i] + c_half[i] * k1[i];
  f(tmp, k2);
  for (int i = 0; i < 7; ++i)
    tmp[i] = y[i] + c_half[i] * k2[i];
  f(tmp, k3);
  for (int i = 0; i < 7; ++i)
    tmp[i] = y[i] + c_full[i] * k3[i];
  f(tmp, k4);
  // y + h/6 (k₁ + 2(k₂ + k₃)) is formed while k₄ is computed; k₄ joins last (two dependent operations after
  // it, not three).
  for (int i = 0; i < 7; ++i)
    y[i] = (y[i] + c_sum[i] * (k1[i] + 2 * (k2[i] + k3[i]))) + c_sum[i] * k4[i];
}

/// Renormalises q = y[0..3] (every kRk4RenormaliseEvery steps): |q|² = 1 + δ with δ of the order of the
/// steps' truncation error in |q| (a step scales |q|² by 1 − (h|ω|/2)⁶/72 + …) plus round-off, and
/// q ← q (3 − |q|²)/2 is the Newton step for 1/√|q|², which leaves |q| − 1 = O(δ²) without a square root or a
/// division. |q| itself never enters the motion: the quaternion equation is linear and homogeneous in q, the
/// torque sees R(q/|q|), and the State gets R of the normalised q. |q|² is summed as (q₀² + q₂²) + (q₁² +
/// q₃²), the order of Eigen's SSE2 reduction of a 4-vector, which the batched kernels of the ensemble layer
/// repeat.
inline __attribute__((always_inline)) void renormalise_quaternion(double* y) {
  const double n2 = (y[0] * y[0] + y[2] * y[2]) + (y[1] * y[1] + y[3] * y[3]);
  const double c = 0.5 * (3.0 - n2);
  for (int i = 0; i < 4; ++i)
    y[i] *= c;
}

}  // namespace

struct Rk4Integrator::Impl {
  detail::EulerRhs f;
  detail::Vec7 y;  // (q, ω), |q| = 1 to O(δ) (renormalise_quaternion)
  detail::ResumeCheck resume;
  int since_renormalised = 0;  // steps since y was converted from a State or q renormalised
  bool fast = false;           // torque-free body in a principal frame
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
  return advance(state, dt, 1, nullptr);
}

StepResult Rk4Integrator::advance(State& state, double dt, long long n, StepWatcher* watcher) {
  require_step_count(name(), n);
  Impl& m = *impl_;
  // The state is converted to y = (q, ω) only when it is not the one this integrator produced last, and back
  // once at the end: between the n steps y is all there is.
  if (!m.resume.matches(state)) {
    m.y = detail::vec7_of(state);
    m.since_renormalised = 0;
  }
  double t = state.time;
  const double h = dt;
  // q is renormalised after every kRk4RenormaliseEvery-th step counted from the conversion, so that the
  // results do not depend on how the steps are split into advances.
  int since = m.since_renormalised;
  const auto renormalise_due = [&since] {
    if (++since < kRk4RenormaliseEvery) return false;
    since = 0;
    return true;
  };
  if (m.fast) {
    // A local copy, so that the compiler keeps y in registers across the steps.
    double y[7];
    for (int i = 0; i < 7; ++i)
      y[i] = m.y[i];
    const FreePrincipalRhs f{m.gyro[0], m.gyro[1], m.gyro[2]};
    for (long long k = 0; k < n; ++k) {
      free_principal_step(y, f, h);
      if (renormalise_due()) renormalise_quaternion(y);
      t = t + h;
      if (watcher) watcher->after_step(k, t, Vec3(y[4], y[5], y[6]));
    }
    for (int i = 0; i < 7; ++i)
      m.y[i] = y[i];
  } else {
    detail::Vec7& y = m.y;
    const double h2 = 0.5 * h;
    for (long long k = 0; k < n; ++k) {
      const detail::Vec7 k1 = m.f(t, y);
      const detail::Vec7 k2 = m.f(t + h2, y + h2 * k1);
      const detail::Vec7 k3 = m.f(t + h2, y + h2 * k2);
      const detail::Vec7 k4 = m.f(t + h, y + h * k3);
      y = (y + (h / 6.0) * (k1 + 2.0 * (k2 + k3))) + (h / 6.0) * k4;  // as free_principal_step
      if (renormalise_due()) renormalise_quaternion(y.data());
      t = t + h;
      if (watcher) watcher->after_step(k, t, y.tail<3>());
    }
  }
  m.since_renormalised = since;
  state.time = t;
  state.R_space_body = detail::rotation_of(m.y);
  state.omega_body = m.y.tail<3>();
  m.resume.remember(state);
  return {h, dt_, 0};
}

}  // namespace poinsot::dynamics
