// The batched splitting of Dullweber, Leimkuhler & McLachlan (batch.hpp): in the principal frame of
// RigidBody::principal_axes() (P, ascending moments), the free flow φ₁(h/2) φ₂(h/2) φ₃(h) φ₂(h/2) φ₁(h/2) of
// planar rotations of Π and of the columns of Rp = R P, with Strang kicks Π ← Π + (h/2) τ for a constant
// torque, and one Björck step every 16 steps: the operations of dynamics/dlm.cpp, lane by lane. A body-frame
// torque is τ = Pᵀ τ_body once; a space-frame one is rotated at every kick as the scalar integrator does:
// τ = Pᵀ (R_bodyᵀ τ_space), R_body = Rp Pᵀ (the attitude at the start of the step for the opening kick, after
// the free flow for the closing one), with Eigen's orders of summation.
#include <algorithm>
#include <cmath>

#include "batch_kernels.hpp"
#include "batch_lanes.hpp"
#include "poinsot/dynamics/sin_cos.hpp"

namespace poinsot::ensemble::detail {
namespace {

constexpr int kReorthogonalizeEvery = 16;  // as dynamics/dlm.cpp (dynamics/euler_rhs.hpp)

struct DlmLanes {
  alignas(64) double R[3][3][B];  // R[row][col]: Rp = R P, principal frame → space
  alignas(64) double Pi[3][B];    // body momentum, principal frame (kg·m²/s)
  alignas(64) double inv_I[3][B];
  alignas(64) double tau[3][B];  // principal-frame torque (N·m); space mode: the latest kick's
  alignas(64) double w[3][B];    // ω = Π/I, for the flip test
  // Space mode: the torque in space (N·m), the principal axes P (body frame) and whether P = I.
  alignas(64) double tau_space[3][B];
  alignas(64) double P[3][3][B];
  alignas(64) double P_identity[B];    // 1 or 0
  alignas(64) double R_open[3][3][B];  // R_body at the start of the step (space mode)
};

inline __attribute__((always_inline)) void rotate(DlmLanes& L, int i, double h) {
  const int j = (i + 1) % 3;
  const int k = (i + 2) % 3;
  alignas(64) double s[B], cm1[B], theta[B];  // sin θ, cos θ − 1
  for (int l = 0; l < B; ++l) {
    theta[l] = h * L.Pi[i][l] * L.inv_I[i][l];
    dynamics::sin_cosm1_polynomial(theta[l], s[l], cm1[l]);
  }
  int library = 0;  // angles beyond 1/4 rad: the C library, as dynamics::sin_cosm1 does
  for (int l = 0; l < B; ++l)
    library |= !dynamics::sin_cos_uses_polynomial(theta[l]);
  if (library) {
    for (int l = 0; l < B; ++l)
      if (!dynamics::sin_cos_uses_polynomial(theta[l])) dynamics::sin_cosm1(theta[l], s[l], cm1[l]);
  }
  // The rotation as increments, written as dynamics/dlm.cpp writes it.
  for (int l = 0; l < B; ++l) {
    const double pj = L.Pi[j][l];
    const double pk = L.Pi[k][l];
    L.Pi[j][l] = pj + (cm1[l] * pj + s[l] * pk);
    L.Pi[k][l] = pk + (cm1[l] * pk - s[l] * pj);
  }
  for (int r = 0; r < 3; ++r) {
    for (int l = 0; l < B; ++l) {
      const double rj = L.R[r][j][l];
      const double rk = L.R[r][k][l];
      L.R[r][j][l] = rj + (cm1[l] * rj + s[l] * rk);
      L.R[r][k][l] = rk + (cm1[l] * rk - s[l] * rj);
    }
  }
}

// R_body = Rp Pᵀ, summed as Eigen's 3×3 lazy product in dynamics/dlm.cpp: rows 0 and 1 in increasing k, row 2
// as x₀ + (x₁ + x₂) (its scalar tail); Rp itself where P = I.
inline __attribute__((always_inline)) void body_attitude(const DlmLanes& L, double (*Rb)[3][B]) {
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      for (int l = 0; l < B; ++l) {
        const double x0 = L.R[a][0][l] * L.P[b][0][l], x1 = L.R[a][1][l] * L.P[b][1][l],
                     x2 = L.R[a][2][l] * L.P[b][2][l];
        const double product = a < 2 ? (x0 + x1) + x2 : x0 + (x1 + x2);
        Rb[a][b][l] = L.P_identity[l] != 0.0 ? L.R[a][b][l] : product;
      }
    }
  }
}

// τ (principal frame) = Pᵀ (R_bodyᵀ τ_space), each product summed in increasing k as Eigen's Mat3ᵀ · Vec3.
inline __attribute__((always_inline)) void space_torque(DlmLanes& L, const double (*Rb)[3][B]) {
  for (int l = 0; l < B; ++l) {
    double tb[3];
    for (int i = 0; i < 3; ++i)
      tb[i] = (Rb[0][i][l] * L.tau_space[0][l] + Rb[1][i][l] * L.tau_space[1][l]) +
              Rb[2][i][l] * L.tau_space[2][l];
    for (int i = 0; i < 3; ++i) {
      const double tp = (L.P[0][i][l] * tb[0] + L.P[1][i][l] * tb[1]) + L.P[2][i][l] * tb[2];
      L.tau[i][l] = L.P_identity[l] != 0.0 ? tb[i] : tp;
    }
  }
}

inline __attribute__((always_inline)) void kick(DlmLanes& L, double h) {
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < B; ++l)
      L.Pi[i][l] = L.Pi[i][l] + (0.5 * h) * L.tau[i][l];
}

// R ← R − ½ R (RᵀR − I), the products summed over k in increasing order as Eigen's 3×3 lazy product does.
inline __attribute__((always_inline)) void reorthogonalize(DlmLanes& L) {
  for (int l = 0; l < B; ++l) {
    double E[3][3], RE[3][3];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        E[a][b] = L.R[0][a][l] * L.R[0][b][l] + L.R[1][a][l] * L.R[1][b][l] + L.R[2][a][l] * L.R[2][b][l] -
                  (a == b ? 1.0 : 0.0);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        RE[a][b] = L.R[a][0][l] * E[0][b] + L.R[a][1][l] * E[1][b] + L.R[a][2][l] * E[2][b];
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b)
        L.R[a][b][l] = L.R[a][b][l] - 0.5 * RE[a][b];
  }
}

inline __attribute__((always_inline)) void update_omega(DlmLanes& L) {
  for (int i = 0; i < 3; ++i)
    for (int l = 0; l < B; ++l)
      L.w[i][l] = L.Pi[i][l] * L.inv_I[i][l];
}

// ṡ = e·ω̇ with ω̇ᵢ = ((Iⱼ − Iₖ)/Iᵢ) ωⱼ ωₖ + τᵢ/Iᵢ written with 1/I: Iᵢ ω̇ᵢ = (1/Iₖ − 1/Iⱼ) Πⱼ Πₖ + τᵢ.
inline __attribute__((always_inline)) void flip_rate(const DlmLanes& L, const FlipLanes& F, double* r) {
  for (int l = 0; l < B; ++l) {
    double sum = 0.0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3, k = (i + 2) % 3;
      const double Ii_wdot = (L.inv_I[k][l] - L.inv_I[j][l]) * L.Pi[j][l] * L.Pi[k][l] + L.tau[i][l];
      sum += F.e[i][l] * L.inv_I[i][l] * Ii_wdot;
    }
    r[l] = sum;
  }
}

template <TorqueMode Mode>
inline __attribute__((always_inline)) void steps(DlmLanes& L, FlipLanes& F, long long n, double h,
                                                 int lanes) {
  alignas(64) double s1[B], r1[B];
  alignas(64) double Rb[3][3][B];
  update_omega(L);
  if constexpr (Mode == TorqueMode::space) space_torque(L, L.R_open);  // the initial attitude, as given
  flip_component(F, L.w[0], L.w[1], L.w[2], F.s);
  flip_rate(L, F, F.r);
  int since_projection = 0;
  for (long long step = 0; step < n; ++step) {
    if constexpr (Mode == TorqueMode::space) {
      if (step > 0) {  // the attitude the previous step handed over (after its Björck step)
        body_attitude(L, Rb);
        space_torque(L, Rb);
      }
    }
    if constexpr (Mode != TorqueMode::free) kick(L, h);
    rotate(L, 0, 0.5 * h);
    rotate(L, 1, 0.5 * h);
    rotate(L, 2, h);
    rotate(L, 1, 0.5 * h);
    rotate(L, 0, 0.5 * h);
    if constexpr (Mode == TorqueMode::space) {
      body_attitude(L, Rb);
      space_torque(L, Rb);
    }
    if constexpr (Mode != TorqueMode::free) kick(L, h);
    if (++since_projection >= kReorthogonalizeEvery) {
      reorthogonalize(L);
      since_projection = 0;
    }
    update_omega(L);
    flip_component(F, L.w[0], L.w[1], L.w[2], s1);
    flip_rate(L, F, r1);
    advance_flips(F, s1, r1, static_cast<double>(step) * h, static_cast<double>(step + 1) * h, lanes);
  }
}

/// The step loop, for run_steps (batch_lanes.hpp).
struct DlmKernel {
  template <TorqueMode Mode>
  static inline __attribute__((always_inline)) void steps(DlmLanes& L, FlipLanes& F, long long n, double h,
                                                          int lanes) {
    ::poinsot::ensemble::detail::steps<Mode>(L, F, n, h, lanes);
  }
};

}  // namespace

void run_dlm_batch(std::span<const Sample> samples, double t_end, long long n, bool avx2,
                   std::span<LaneResult> results) {
  auto L = std::make_unique<DlmLanes>();
  auto F = std::make_unique<FlipLanes>();
  const int lanes = static_cast<int>(samples.size());
  std::vector<Mat3> axes(static_cast<std::size_t>(lanes));
  const TorqueMode mode = torque_mode(samples);
  for (int l = 0; l < B; ++l) {
    const Sample& s = samples[static_cast<std::size_t>(l < lanes ? l : 0)];  // idle lanes repeat lane 0
    const dynamics::RigidBody body = s.body();
    const Mat3& P = body.principal_axes();
    const bool identity = P == Mat3::Identity();
    if (l < lanes) axes[static_cast<std::size_t>(l)] = P;
    // As DlmIntegrator::step converts a State.
    const Mat3 Rp = identity ? s.initial.R_space_body : Mat3(s.initial.R_space_body * P);
    const Vec3 inv_I = body.principal_moments().cwiseInverse();
    const Vec3 w = identity ? s.initial.omega_body : Vec3(P.transpose() * s.initial.omega_body);
    const Vec3 Pi = w.cwiseQuotient(inv_I);
    const Vec3 tau_body = s.torque == TorqueKind::body ? s.torque_value : Vec3::Zero();
    const Vec3 tau = identity ? tau_body : Vec3(P.transpose() * tau_body);
    const Vec3 tau_space = s.torque == TorqueKind::space ? s.torque_value : Vec3::Zero();
    L->P_identity[l] = identity ? 1.0 : 0.0;
    for (int a = 0; a < 3; ++a) {
      L->tau_space[a][l] = tau_space[a];
      for (int b = 0; b < 3; ++b) {
        L->R[a][b][l] = Rp(a, b);
        L->P[a][b][l] = P(a, b);
        L->R_open[a][b][l] = s.initial.R_space_body(a, b);
      }
      L->Pi[a][l] = Pi[a];
      L->inv_I[a][l] = inv_I[a];
      L->tau[a][l] = tau[a];
    }
    const double moments[3] = {body.principal_moments()[0], body.principal_moments()[1],
                               body.principal_moments()[2]};
    set_flip_weights(*F, l, moments);
  }
  const double h = t_end / static_cast<double>(n);
  run_steps<DlmKernel>(avx2, *L, *F, n, h, lanes, mode);
  for (int l = 0; l < lanes; ++l) {
    const Mat3& P = axes[static_cast<std::size_t>(l)];
    const bool identity = P == Mat3::Identity();
    Mat3 Rp;
    Vec3 Pi, inv_I;
    for (int a = 0; a < 3; ++a) {
      for (int b = 0; b < 3; ++b)
        Rp(a, b) = L->R[a][b][l];
      Pi[a] = L->Pi[a][l];
      inv_I[a] = L->inv_I[a][l];
    }
    LaneResult& r = results[static_cast<std::size_t>(l)];
    r.final_state.time = t_end;
    r.final_state.R_space_body = identity ? Rp : Mat3(Rp * P.transpose());
    const Vec3 w = Pi.cwiseProduct(inv_I);
    r.final_state.omega_body = identity ? w : Vec3(P * w);
    r.first_flip = F->first[l];
    r.second_flip = F->second[l];
    r.flips = F->count[l];
  }
}

}  // namespace poinsot::ensemble::detail
