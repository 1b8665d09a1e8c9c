// The batched classical Runge–Kutta method (batch.hpp): the free or constant-torque body in its principal
// frame, y = (q, ω) with q̇ = ½ q ⊗ (0, ω) and ω̇ᵢ = gᵢ ωⱼ ωₖ + τᵢ/Iᵢ, gᵢ = (Iⱼ − Iₖ)/Iᵢ, exactly the
// operations of dynamics/rk4.cpp (its principal-frame path), lane by lane. A torque constant in space is
// rotated into the principal frame at every stage, τ = R(q/|q|)ᵀ τ_space (the torque sees the normalised
// attitude, as in dynamics/rk4.cpp).
#include <cmath>

#include "batch_kernels.hpp"
#include "batch_lanes.hpp"
#include "poinsot/dynamics/rk4.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::ensemble::detail {
namespace {

struct Rk4Lanes {
  alignas(64) double y[7][B];
  alignas(64) double g[3][B];          // gyroscopic coefficients (Iⱼ − Iₖ)/Iᵢ
  alignas(64) double tau[3][B];        // τᵢ · (1/Iᵢ), rad/s² (body-frame torque)
  alignas(64) double tau_space[3][B];  // N·m (space-frame torque)
  alignas(64) double inv_I[3][B];      // 1/Iᵢ
  alignas(64) double k[4][7][B];
  alignas(64) double tmp[7][B];
};

// The quaternion increment of lane l, q ⊗ (0, v) with v = a ω, as the sums d with q ⊗ (0, v) = (−d₀, d₁, d₂,
// d₃): the operations of dynamics/rk4.cpp's quaternion_increment.
inline __attribute__((always_inline)) void quaternion_increment(const double (*y)[B], double (*d)[B], int l,
                                                                double a, double w1, double w2, double w3) {
  const double v1 = a * w1, v2 = a * w2, v3 = a * w3;
  d[0][l] = y[1][l] * v1 + y[2][l] * v2 + y[3][l] * v3;
  d[1][l] = y[0][l] * v1 + y[2][l] * v3 - y[3][l] * v2;
  d[2][l] = y[0][l] * v2 + y[3][l] * v1 - y[1][l] * v3;
  d[3][l] = y[0][l] * v3 + y[1][l] * v2 - y[2][l] * v1;
}

// The right-hand sides of a stage: rows 0–3 of d the quaternion increment for the scale a, rows 4–6 ω̇.
inline __attribute__((always_inline)) void rhs(const Rk4Lanes& L, const double (*y)[B], double (*d)[B],
                                               double a) {
  for (int l = 0; l < B; ++l) {
    const double w1 = y[4][l], w2 = y[5][l], w3 = y[6][l];
    quaternion_increment(y, d, l, a, w1, w2, w3);
    d[4][l] = L.g[0][l] * w2 * w3 + L.tau[0][l];
    d[5][l] = L.g[1][l] * w3 * w1 + L.tau[1][l];
    d[6][l] = L.g[2][l] * w1 * w2 + L.tau[2][l];
  }
}

// Torque-free lanes skip the "+ τ" (adding 0 would turn −0 into +0 and the scalar fast path adds nothing).
inline __attribute__((always_inline)) void rhs_free(const Rk4Lanes& L, const double (*y)[B], double (*d)[B],
                                                    double a) {
  for (int l = 0; l < B; ++l) {
    const double w1 = y[4][l], w2 = y[5][l], w3 = y[6][l];
    quaternion_increment(y, d, l, a, w1, w2, w3);
    d[4][l] = L.g[0][l] * w2 * w3;
    d[5][l] = L.g[1][l] * w3 * w1;
    d[6][l] = L.g[2][l] * w1 * w2;
  }
}

// A torque constant in space: ω̇ᵢ = gᵢ ωⱼ ωₖ + (Rᵀ τ_space)ᵢ/Iᵢ with R = R(q/|q|), as dynamics/rk4.cpp
// evaluates it (euler_rhs.hpp): q divided by √|q|² (|q|² in Eigen's order, as renormalise), R by Eigen's
// Quaternion::toRotationMatrix, Rᵀ τ summed in increasing k, then multiplied by 1/Iᵢ.
inline __attribute__((always_inline)) void rhs_space(const Rk4Lanes& L, const double (*y)[B], double (*d)[B],
                                                     double a) {
  for (int l = 0; l < B; ++l) {
    const double w1 = y[4][l], w2 = y[5][l], w3 = y[6][l];
    quaternion_increment(y, d, l, a, w1, w2, w3);
    const double norm =
        std::sqrt((y[0][l] * y[0][l] + y[2][l] * y[2][l]) + (y[1][l] * y[1][l] + y[3][l] * y[3][l]));
    const double qw = y[0][l] / norm, qx = y[1][l] / norm, qy = y[2][l] / norm, qz = y[3][l] / norm;
    const double tx = 2.0 * qx, ty = 2.0 * qy, tz = 2.0 * qz;
    const double twx = tx * qw, twy = ty * qw, twz = tz * qw;
    const double txx = tx * qx, txy = ty * qx, txz = tz * qx;
    const double tyy = ty * qy, tyz = tz * qy, tzz = tz * qz;
    const double R[3][3] = {{1.0 - (tyy + tzz), txy - twz, txz + twy},
                            {txy + twz, 1.0 - (txx + tzz), tyz - twx},
                            {txz - twy, tyz + twx, 1.0 - (txx + tyy)}};
    const double v0 = L.tau_space[0][l], v1 = L.tau_space[1][l], v2 = L.tau_space[2][l];
    double t[3];
    for (int i = 0; i < 3; ++i)
      t[i] = (R[0][i] * v0 + R[1][i] * v1) + R[2][i] * v2;
    d[4][l] = L.g[0][l] * w2 * w3 + t[0] * L.inv_I[0][l];
    d[5][l] = L.g[1][l] * w3 * w1 + t[1] * L.inv_I[1][l];
    d[6][l] = L.g[2][l] * w1 * w2 + t[2] * L.inv_I[2][l];
  }
}

// The stage state y + (quaternion increment, c ω̇) of the stage rates k: q − d₀, q + dᵢ, ω + c ω̇.
inline __attribute__((always_inline)) void stage_state(Rk4Lanes& L, const double (*k)[B], double c) {
  for (int l = 0; l < B; ++l)
    L.tmp[0][l] = L.y[0][l] - k[0][l];
  for (int i = 1; i < 4; ++i)
    for (int l = 0; l < B; ++l)
      L.tmp[i][l] = L.y[i][l] + k[i][l];
  for (int i = 4; i < 7; ++i)
    for (int l = 0; l < B; ++l)
      L.tmp[i][l] = L.y[i][l] + c * k[i][l];
}

// One step of dynamics/rk4.cpp's rk4_step on every lane, in its order of operations: the quaternion
// increments of the stages for the scales h/4, h/4, h/2 and h/12, q ← (q ± (d₁ + 2d₂ + d₃)/3) ± d₄; ω ← (ω +
// h/6 (k₁ + 2(k₂ + k₃))) + h/6 k₄.
template <TorqueMode Mode>
inline __attribute__((always_inline)) void step(Rk4Lanes& L, double h, bool renormalise) {
  const auto f = [&L](const double(*y)[B], double(*d)[B], double a) {
    if constexpr (Mode == TorqueMode::free) {
      rhs_free(L, y, d, a);
    } else if constexpr (Mode == TorqueMode::body) {
      rhs(L, y, d, a);
    } else {
      rhs_space(L, y, d, a);
    }
  };
  const double half = 0.5 * h;
  const double sixth = h / 6;
  constexpr double third = 1.0 / 3;
  f(L.y, L.k[0], 0.5 * half);
  stage_state(L, L.k[0], half);
  f(L.tmp, L.k[1], 0.5 * half);
  stage_state(L, L.k[1], half);
  f(L.tmp, L.k[2], half);
  stage_state(L, L.k[2], h);
  f(L.tmp, L.k[3], 0.5 * sixth);
  const auto& k = L.k;
  for (int l = 0; l < B; ++l)
    L.y[0][l] = (L.y[0][l] - third * ((k[0][0][l] + k[2][0][l]) + 2 * k[1][0][l])) - k[3][0][l];
  for (int i = 1; i < 4; ++i)
    for (int l = 0; l < B; ++l)
      L.y[i][l] = (L.y[i][l] + third * ((k[0][i][l] + k[2][i][l]) + 2 * k[1][i][l])) + k[3][i][l];
  for (int i = 4; i < 7; ++i)
    for (int l = 0; l < B; ++l)
      L.y[i][l] = (L.y[i][l] + sixth * (k[0][i][l] + 2 * (k[1][i][l] + k[2][i][l]))) + sixth * k[3][i][l];
  // q ← q (3 − |q|²)/2 as in dynamics/rk4.cpp, after every kRk4RenormaliseEvery-th step; |q|² summed in the
  // order of Eigen's SSE2 reduction of a 4-vector there, (q₀² + q₂²) + (q₁² + q₃²).
  if (!renormalise) return;
  for (int l = 0; l < B; ++l) {
    const double n2 =
        (L.y[0][l] * L.y[0][l] + L.y[2][l] * L.y[2][l]) + (L.y[1][l] * L.y[1][l] + L.y[3][l] * L.y[3][l]);
    const double c = 0.5 * (3.0 - n2);
    for (int i = 0; i < 4; ++i)
      L.y[i][l] *= c;
  }
}

// The rate ṡ of s = Σ eᵢ ωᵢ from ω̇ (the last right-hand side is not at the new state: recomputed per lane).
template <TorqueMode Mode>
inline __attribute__((always_inline)) void flip_rate(Rk4Lanes& L, const FlipLanes& F, double* r) {
  if constexpr (Mode == TorqueMode::space) {
    rhs_space(L, L.y, L.tmp, 1.0);  // ω̇ at the new state (rows 4–6; rows 0–3 unused)
    for (int l = 0; l < B; ++l)
      r[l] = F.e[0][l] * L.tmp[4][l] + F.e[1][l] * L.tmp[5][l] + F.e[2][l] * L.tmp[6][l];
    return;
  }
  for (int l = 0; l < B; ++l) {
    const double w1 = L.y[4][l], w2 = L.y[5][l], w3 = L.y[6][l];
    r[l] = F.e[0][l] * (L.g[0][l] * w2 * w3 + L.tau[0][l]) + F.e[1][l] * (L.g[1][l] * w3 * w1 + L.tau[1][l]) +
           F.e[2][l] * (L.g[2][l] * w1 * w2 + L.tau[2][l]);
  }
}

template <TorqueMode Mode>
inline __attribute__((always_inline)) void steps(Rk4Lanes& L, FlipLanes& F, long long n, double h,
                                                 int lanes) {
  alignas(64) double s1[B], r1[B];
  flip_component(F, L.y[4], L.y[5], L.y[6], F.s);
  flip_rate<Mode>(L, F, F.r);
  for (long long i = 0; i < n; ++i) {
    step<Mode>(L, h, (i + 1) % dynamics::kRk4RenormaliseEvery == 0);
    flip_component(F, L.y[4], L.y[5], L.y[6], s1);
    flip_rate<Mode>(L, F, r1);
    advance_flips(F, s1, r1, static_cast<double>(i) * h, static_cast<double>(i + 1) * h, lanes);
  }
}

/// The step loop, for run_steps (batch_lanes.hpp).
struct Rk4Kernel {
  template <TorqueMode Mode>
  static inline __attribute__((always_inline)) void steps(Rk4Lanes& L, FlipLanes& F, long long n, double h,
                                                          int lanes) {
    ::poinsot::ensemble::detail::steps<Mode>(L, F, n, h, lanes);
  }
};

}  // namespace

void run_rk4_batch(std::span<const Sample> samples, double t_end, long long n, bool avx2,
                   std::span<LaneResult> results) {
  auto L = std::make_unique<Rk4Lanes>();
  auto F = std::make_unique<FlipLanes>();
  const int lanes = static_cast<int>(samples.size());
  const TorqueMode mode = torque_mode(samples);
  for (int l = 0; l < B; ++l) {
    const Sample& s = samples[static_cast<std::size_t>(l < lanes ? l : 0)];  // idle lanes repeat lane 0
    const bool aligned = s.axes == Mat3::Identity();
    const Mat3 Rp = aligned ? s.initial.R_space_body : Mat3(s.initial.R_space_body * s.axes);
    const Vec3 w = aligned ? s.initial.omega_body : Vec3(s.axes.transpose() * s.initial.omega_body);
    const Quat q = so3::quaternion_from_rotation(Rp);
    const double y0[7] = {q.w(), q.x(), q.y(), q.z(), w[0], w[1], w[2]};
    for (int i = 0; i < 7; ++i)
      L->y[i][l] = y0[i];
    const Vec3& I = s.moments;
    const Vec3 g((I[1] - I[2]) / I[0], (I[2] - I[0]) / I[1], (I[0] - I[1]) / I[2]);
    const Vec3 tau_body = s.torque == TorqueKind::body ? s.torque_value : Vec3::Zero();
    const Vec3 tau = aligned ? tau_body : Vec3(s.axes.transpose() * tau_body);
    const Vec3 tau_over_I = tau.cwiseProduct(I.cwiseInverse());
    const Vec3 tau_space = s.torque == TorqueKind::space ? s.torque_value : Vec3::Zero();
    for (int i = 0; i < 3; ++i) {
      L->g[i][l] = g[i];
      L->tau[i][l] = tau_over_I[i];
      L->tau_space[i][l] = tau_space[i];
      L->inv_I[i][l] = 1.0 / I[i];
    }
    const double moments[3] = {I[0], I[1], I[2]};
    set_flip_weights(*F, l, moments);
  }
  const double h = t_end / static_cast<double>(n);
  run_steps<Rk4Kernel>(avx2, *L, *F, n, h, lanes, mode);
  for (int l = 0; l < lanes; ++l) {
    const Sample& s = samples[static_cast<std::size_t>(l)];
    const bool aligned = s.axes == Mat3::Identity();
    LaneResult& r = results[static_cast<std::size_t>(l)];
    r.final_state.time = t_end;
    Quat q(L->y[0][l], L->y[1][l], L->y[2][l], L->y[3][l]);
    q.normalize();  // as dynamics/rk4.cpp forms R
    const Mat3 Rp = q.toRotationMatrix();
    const Vec3 w(L->y[4][l], L->y[5][l], L->y[6][l]);
    r.final_state.R_space_body = aligned ? Rp : Mat3(Rp * s.axes.transpose());
    r.final_state.omega_body = aligned ? w : Vec3(s.axes * w);
    r.first_flip = F->first[l];
    r.second_flip = F->second[l];
    r.flips = F->count[l];
  }
}

}  // namespace poinsot::ensemble::detail
