// Round-off growth of RᵀR = I under the multibody methods of the registry, on one free body over an ensemble
// of perturbed initial conditions: RATTLE, which never projects, lets the rounding random-walk (Brouwer's
// law, RMS ∝ √N, not ∝ N); the projected RK4 keeps it bounded. The long measurement (10³ to 10⁹ steps, also
// of the momenta and the energy) is bench/brouwer_growth.cpp; figures in docs/benchmarks.md.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "poinsot/multibody/methods.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot_test.hpp"
#include "splitmix_draws.hpp"

namespace poinsot::multibody::test {
namespace {

constexpr double kEps = 0x1.0p-52;
// Unoptimised builds (debug, ASan + UBSan) run 4 members to 10⁴ steps and check the magnitude only.
#ifdef NDEBUG
constexpr int kMembers = 20;
constexpr bool kFull = true;
#else
constexpr int kMembers = 4;
constexpr bool kFull = false;
#endif
constexpr double kDt = 1e-3;  // s

// J = diag(1, 2, 3) kg·m², ω0 = (0.01, 2, 0.01) rad/s + δ, |δᵢ| ≤ 1e-3 rad/s, R0 = exp(j(ε)), |εᵢ| ≤ 1e-3
// rad, drawn by SplitMixDraws (the generator and seed of bench/brouwer_growth.cpp).
// RMS over the ensemble of ‖RᵀR − I‖_F after each checkpoint.
std::vector<double> orthogonality_rms(const MultibodyMethodInfo& info, const std::vector<long>& checkpoints) {
  System system;
  system.add_body_from_inertia("body", 1.0, Vec3(1.0, 2.0, 3.0).asDiagonal());
  std::vector<double> rms(checkpoints.size(), 0.0);
  poinsot::test::SplitMixDraws draws;
  for (int m = 0; m < kMembers; ++m) {
    State s;
    s.bodies.resize(1);
    s.bodies[0].R_space_body = so3::exp(draws.vec(1e-3));
    s.bodies[0].omega_body = Vec3(0.01, 2.0, 0.01) + draws.vec(1e-3);
    const auto integrator = info.make(system, kDt, info.order);
    long done = 0;
    for (std::size_t c = 0; c < checkpoints.size(); ++c) {
      for (; done < checkpoints[c]; ++done)
        integrator->step(s);
      const double e = so3::orthogonality_error(s.bodies[0].R_space_body);
      rms[c] += e * e;
    }
  }
  for (double& x : rms)
    x = std::sqrt(x / kMembers);
  return rms;
}

TEST(MultibodyRoundoffGrowth, RattleRandomWalksAndProjectedRk4StaysBounded) {
  const std::vector<long> checkpoints =
      kFull ? std::vector<long>{1000, 3162, 10000, 31623} : std::vector<long>{1000, 3162, 10000};
  for (const MultibodyMethodInfo& info : multibody_methods()) {
    const std::vector<double> rms = orthogonality_rms(info, checkpoints);
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double k = static_cast<double>(rms.size());
    for (std::size_t i = 0; i < rms.size(); ++i) {
      const double x = std::log(static_cast<double>(checkpoints[i])), y = std::log(rms[i]);
      sx += x, sy += y, sxx += x * x, sxy += x * y;
    }
    const double p = (k * sxy - sx * sy) / (k * sxx - sx * sx);
    const double ratio = rms.back() / (kEps * std::sqrt(static_cast<double>(checkpoints.back())));
    std::printf("%s: |RtR - I| RMS %.3g at %ld steps = %.2f eps sqrt(N), fitted exponent %.2f\n",
                std::string(info.name).c_str(), rms.back(), checkpoints.back(), ratio, p);
    if (info.method == MultibodyMethod::projected_rk4) {
      // A Björck step every step leaves |RᵀR − I| at one step's rounding: bounded (measured 1e-15, 4.5 ε,
      // exponent ≈ 0); 4 ε√10 = 12.6 ε leaves room for the spread and fails for any growth like √N from 10³.
      EXPECT_LT(rms.back(), 4.0 * std::sqrt(10.0) * kEps) << info.name;
    } else {
      // R + R(Q − I) rounds each of the 9 entries of R by ½ ulp a step, unbiased, so the Frobenius norm of
      // RᵀR − I random-walks at a few tenths of ε√N: measured 0.58 ε√N at 10^4.5 steps, exponent 0.57 over
      // 1.5 decades (±0.1 over 20 members). With Q = I + (Q − I) rounded before R Q it was 6.9 ε√N, and with
      // the cheaper Q = c I + j(a) + a aᵀ/(1 + c) it drifted linearly.
      if (kFull) {
        EXPECT_LT(p, 0.75) << info.name;
      }
      EXPECT_LT(ratio, 2.0) << info.name;
    }
  }
}

}  // namespace
}  // namespace poinsot::multibody::test
