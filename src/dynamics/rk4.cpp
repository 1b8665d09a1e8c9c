#include "poinsot/dynamics/rk4.hpp"

#include "euler_rhs.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::dynamics {
namespace {

/// The quaternion increment of a stage, q ⊗ (0, v) with v = a ω, for the stage state s = (q, ω): returned as
/// the sums d with q ⊗ (0, v) = (−d₀, d₁, d₂, d₃). With a = c/2 it is c q̇ (q̇ = ½ q ⊗ (0, ω)): the stage
/// coefficient c and the ½ scale ω (three products off the quaternion's chain of dependent operations, whose
/// ω is ready before its q) instead of the sums (four products on it). The ensemble layer's batched rk4
/// repeats these operations in this order.
inline __attribute__((always_inline)) void quaternion_increment(const double* s, double a, double* d) {
  const double v1 = a * s[4], v2 = a * s[5], v3 = a * s[6];
  d[0] = s[1] * v1 + s[2] * v2 + s[3] * v3;
  d[1] = s[0] * v1 + s[2] * v3 - s[3] * v2;
  d[2] = s[0] * v2 + s[3] * v1 - s[1] * v3;
  d[3] = s[0] * v3 + s[1] * v2 - s[2] * v1;
}

/// ω̇ᵢ = gᵢ ωⱼ ωₖ, gᵢ = (Iⱼ − Iₖ)/Iᵢ (rad/s²): the torque-free body in a principal frame, the hot path.
struct FreePrincipalOmegaRate {
  double g1, g2, g3;
  inline __attribute__((always_inline)) void operator()(double /*t*/, const double* s, double* wd) const {
    const double w1 = s[4], w2 = s[5], w3 = s[6];
    wd[0] = g1 * w2 * w3;
    wd[1] = g2 * w3 * w1;
    wd[2] = g3 * w1 * w2;
  }
};

/// ω̇ of Euler's equations with any inertia and torque (euler_rhs.hpp); the torque sees R(q/|q|).
struct GeneralOmegaRate {
  const detail::EulerRhs& f;
  void operator()(double t, const double* s, double* wd) const {
    const Vec3 w(s[4], s[5], s[6]);
    const Vec3 r = f.torque_free()
                       ? f.free_omega_dot(w)
                       : f.omega_dot(t, detail::rotation_of(Eigen::Map<const detail::Vec7>(s)), w);
    wd[0] = r[0];
    wd[1] = r[1];
    wd[2] = r[2];
  }
};

/// One classical RK4 step, in place on y = (q, ω) at time t:
///   y ← y + h/6 (k₁ + 2k₂ + 2k₃ + k₄),  stages y + h/2 k₁, y + h/2 k₂, y + h k₃.
/// ω: (ω + h/6 (k₁ + 2(k₂ + k₃))) + h/6 k₄, with k the rates of `rate`. q: the increments dₛ = cₛ q̇ₛ of
/// quaternion_increment (c = h/2, h/2, h for the stages, h/6 for k₄), and q ← (q + (d₁ + 2d₂ + d₃)/3) + d₄,
/// since h/6 (q̇₁ + 2q̇₂ + 2q̇₃) = (d₁ + 2d₂ + d₃)/3 (the product by the rounded 1/3 adds an ulp of an increment
/// of size h|ω|/2); the sum with the last stage's term is formed while k₄ is computed, so that k₄ has two
/// dependent operations after it, not three. One sequence of operations for the principal-frame path and the
/// general one; the ensemble layer's batched rk4 repeats it lane by lane.
template <class OmegaRate>
inline __attribute__((always_inline)) void rk4_step(double* y, double t, const double h,
                                                    const OmegaRate& rate) {
  const double half = 0.5 * h;
  const double sixth = h / 6;
  constexpr double third = 1.0 / 3;
  double d1[4], d2[4], d3[4], d4[4], w1[3], w2[3], w3[3], w4[3], s[7];
  quaternion_increment(y, 0.5 * half, d1);
  rate(t, y, w1);
  s[0] = y[0] - d1[0];
  for (int i = 1; i < 4; ++i)
    s[i] = y[i] + d1[i];
  for (int i = 0; i < 3; ++i)
    s[4 + i] = y[4 + i] + half * w1[i];
  quaternion_increment(s, 0.5 * half, d2);
  rate(t + half, s, w2);
  s[0] = y[0] - d2[0];
  for (int i = 1; i < 4; ++i)
    s[i] = y[i] + d2[i];
  for (int i = 0; i < 3; ++i)
    s[4 + i] = y[4 + i] + half * w2[i];
  quaternion_increment(s, half, d3);
  rate(t + half, s, w3);
  s[0] = y[0] - d3[0];
  for (int i = 1; i < 4; ++i)
    s[i] = y[i] + d3[i];
  for (int i = 0; i < 3; ++i)
    s[4 + i] = y[4 + i] + h * w3[i];
  quaternion_increment(s, 0.5 * sixth, d4);
  rate(t + h, s, w4);
  y[0] = (y[0] - third * ((d1[0] + d3[0]) + 2 * d2[0])) - d4[0];
  for (int i = 1; i < 4; ++i)
    y[i] = (y[i] + third * ((d1[i] + d3[i]) + 2 * d2[i])) + d4[i];
  for (int i = 0; i < 3; ++i)
    y[4 + i] = (y[4 + i] + sixth * (w1[i] + 2 * (w2[i] + w3[i]))) + sixth * w4[i];
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
  // One sequence of operations for both paths, with the ω̇ of the principal frame or the general one.
  const auto run = [&](double* y, const auto& rate) __attribute__((always_inline)) {
    for (long long k = 0; k < n; ++k) {
      rk4_step(y, t, h, rate);
      if (renormalise_due()) renormalise_quaternion(y);
      t = t + h;
      if (watcher) watcher->after_step(k, t, Vec3(y[4], y[5], y[6]));
    }
  };
  if (m.fast) {
    // A local copy, so that the compiler keeps y in registers across the steps.
    double y[7];
    for (int i = 0; i < 7; ++i)
      y[i] = m.y[i];
    run(y, FreePrincipalOmegaRate{m.gyro[0], m.gyro[1], m.gyro[2]});
    for (int i = 0; i < 7; ++i)
      m.y[i] = y[i];
  } else {
    run(m.y.data(), GeneralOmegaRate{m.f});
  }
  m.since_renormalised = since;
  state.time = t;
  state.R_space_body = detail::rotation_of(m.y);
  state.omega_body = m.y.tail<3>();
  m.resume.remember(state);
  return {h, dt_, 0};
}

}  // namespace poinsot::dynamics
