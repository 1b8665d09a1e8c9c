// The closed-form free body (exact_free_body.hpp) at its conditioning limit: the same closed form evaluated
// in 50-digit arithmetic (Boost.Multiprecision cpp_bin_float_50 with Boost.Math's Jacobi elliptic functions
// and elliptic integrals, independent of the double code's AGM, Carlson forms and phase reduction) from the
// same double inputs, at t up to 10⁹ s, on random bodies in both regimes and near the separatrix.
//
// The limit: t itself is known to ½ ulp(t), so no double evaluation can do better than
// ½ ulp(t)·‖∂R/∂t‖ = ½ ulp(t)·|ω| in R (max entry; ‖R j(ω)‖_max ≤ |ω|) and ½ ulp(t)·|ω̇| in ω, plus the
// few ulps of the final arithmetic. The double implementation's error is measured against ulp(t)·|ω| + 8ε
// (and ulp(t)·|ω̇| + 8ε|ω| for ω): within a factor 4 of it, on random bodies and near the separatrix
// (docs/exact.md, "Precision").
#include <gtest/gtest.h>

#include <boost/math/special_functions/ellint_1.hpp>
#include <boost/math/special_functions/ellint_3.hpp>
#include <boost/math/special_functions/jacobi_elliptic.hpp>
#include <boost/multiprecision/cpp_bin_float.hpp>
#include <boost/multiprecision/eigen.hpp>
#include <cmath>
#include <cstdint>
#include <limits>

#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::dynamics {
namespace {

using Real = boost::multiprecision::cpp_bin_float_50;
using Vec3R = Eigen::Matrix<Real, 3, 1>;
using Mat3R = Eigen::Matrix<Real, 3, 3>;

constexpr double kEps = std::numeric_limits<double>::epsilon();

// The closed form of exact_free_body.hpp for a body in its principal frame (J = diag(I1 < I2 < I3)) off the
// separatrix, in 50 digits: ω by sn, cn, dn of u = ω_p t + u0, R = R0 B(n0)ᵀ Rz(φ(t)) B(n(t)) with
// φ = G t/I_c + C1/ω_p [Π(N; am u) − u − (Π(N; am u0) − u0)].
class ExactFreeBody50 {
 public:
  ExactFreeBody50(const Vec3& moments, const Mat3& R0, const Vec3& w0) : I_(moments.cast<Real>()) {
    const Vec3R w = w0.cast<Real>();
    const Real d3 = I_[0] * (I_[2] - I_[0]) * w[0] * w[0] + I_[1] * (I_[2] - I_[1]) * w[1] * w[1];
    const Real d1 = I_[1] * (I_[1] - I_[0]) * w[1] * w[1] + I_[2] * (I_[2] - I_[0]) * w[2] * w[2];
    const Real gap = I_[2] * (I_[2] - I_[1]) * w[2] * w[2] - I_[0] * (I_[1] - I_[0]) * w[0] * w[0];
    const Real I123 = I_[0] * I_[1] * I_[2];
    largest_ = gap > 0;
    Real k2, sn0, cn0;
    const Real a1 = sqrt(d3 / (I_[0] * (I_[2] - I_[0])));
    const Real a3 = sqrt(d1 / (I_[2] * (I_[2] - I_[0])));
    if (largest_) {  // ω1 = a1 cn, ω2 = σ3 a2 sn, ω3 = σ3 a3 dn
      omega_p_ = sqrt((I_[2] - I_[1]) * d1 / I123);
      k2 = (I_[1] - I_[0]) * d3 / ((I_[2] - I_[1]) * d1);
      const Real s3 = w[2] < 0 ? -1 : 1;
      amp_ = Vec3R(a1, s3 * sqrt(d3 / (I_[1] * (I_[2] - I_[1]))), s3 * a3);
      cn0 = w[0] / amp_[0];
    } else {  // ω1 = σ1 a1 dn, ω2 = σ1 a2 sn, ω3 = a3 cn
      omega_p_ = sqrt((I_[1] - I_[0]) * d3 / I123);
      k2 = (I_[2] - I_[1]) * d1 / ((I_[1] - I_[0]) * d3);
      const Real s1 = w[0] < 0 ? -1 : 1;
      amp_ = Vec3R(s1 * a1, s1 * sqrt(d1 / (I_[1] * (I_[1] - I_[0]))), a3);
      cn0 = w[2] / amp_[2];
    }
    sn0 = w[1] / amp_[1];
    k_ = sqrt(k2);
    K_ = boost::math::ellint_1(k_);
    u0_ = boost::math::ellint_1(k_, atan2(sn0, cn0));  // F(am u0 | k), am u0 in (−π, π]
    // The polar axis with the smaller |N| (exact_free_body.hpp).
    const Real q3 = largest_ ? k2 : Real(1), q1 = largest_ ? Real(1) : k2;
    const Real n3 = -I_[2] * d1 * q3 / (I_[0] * d3), n1 = -I_[0] * d3 * q1 / (I_[2] * d1);
    const Real G = sqrt((I_[0] * w[0]) * (I_[0] * w[0]) + (I_[1] * w[1]) * (I_[1] * w[1]) +
                        (I_[2] * w[2]) * (I_[2] * w[2]));
    Real c1;
    if (abs(n3) <= abs(n1)) {
      a_ = 0, b_ = 1, c_ = 2, N_ = n3, c1 = G * (1 / I_[0] - 1 / I_[2]);
    } else {
      a_ = 1, b_ = 2, c_ = 0, N_ = n1, c1 = G * (1 / I_[2] - 1 / I_[0]);
    }
    rate1_ = c1 / omega_p_;
    rate_lin_ = G / I_[c_] + c1;
    pi_complete_ = boost::math::ellint_3(k_, N_);
    Real sn, cn, dn;
    corr0_ = pi_minus_u(u0_, sn, cn, dn);
    left_ = R0.cast<Real>() * frame(w).transpose();
  }

  // ω (rad/s) and R at time t (s), rounded to double at the end.
  void at(double t, Vec3& omega, Mat3& R) const {
    const Real tt = t;
    const Real u = omega_p_ * tt + u0_;
    Real sn, cn, dn;
    const Real pmu = pi_minus_u(u, sn, cn, dn);
    Vec3R w;
    const int cn_axis = largest_ ? 0 : 2, dn_axis = largest_ ? 2 : 0;
    w[cn_axis] = amp_[cn_axis] * cn;
    w[1] = amp_[1] * sn;
    w[dn_axis] = amp_[dn_axis] * dn;
    const Real phi = rate_lin_ * tt + rate1_ * (pmu - corr0_);
    Mat3R Rz = Mat3R::Zero();
    Rz(0, 0) = cos(phi), Rz(0, 1) = -sin(phi), Rz(1, 0) = sin(phi), Rz(1, 1) = cos(phi), Rz(2, 2) = 1;
    const Mat3R Rr = left_ * Rz * frame(w);
    for (int i = 0; i < 3; ++i) {
      omega[i] = static_cast<double>(w[i]);
      for (int j = 0; j < 3; ++j)
        R(i, j) = static_cast<double>(Rr(i, j));
    }
  }

 private:
  // Π(N; am u | k) − u with sn, cn, dn at u: u = ur + 2K m, |ur| ≤ K, am u = am ur + mπ.
  Real pi_minus_u(const Real& u, Real& sn, Real& cn, Real& dn) const {
    const Real m = round(u / (2 * K_));
    const Real ur = u - 2 * K_ * m;
    sn = boost::math::jacobi_elliptic(k_, ur, &cn, &dn);
    const Real am = atan2(sn, cn);
    const Real result = boost::math::ellint_3(k_, N_, am) - ur + 2 * m * (pi_complete_ - K_);
    if (boost::multiprecision::fmod(m, Real(2)) != 0) sn = -sn, cn = -cn;
    return result;
  }
  // B(n) of exact_free_body.hpp in the cyclic frame (a, b, c).
  Mat3R frame(const Vec3R& w) const {
    const Vec3R m = I_.cwiseProduct(w);
    const Vec3R n = m / m.norm();
    const Real na = n[a_], nb = n[b_], nc = n[c_];
    const Real s = sqrt(na * na + nb * nb);
    Mat3R B = Mat3R::Zero();
    B(0, a_) = nb / s, B(0, b_) = -na / s;
    B(1, a_) = nc * na / s, B(1, b_) = nc * nb / s, B(1, c_) = -s;
    B(2, a_) = na, B(2, b_) = nb, B(2, c_) = nc;
    return B;
  }

  Vec3R I_, amp_;
  bool largest_ = true;
  Real omega_p_, k_, K_, u0_, N_, rate1_, rate_lin_, pi_complete_, corr0_;
  int a_ = 0, b_ = 1, c_ = 2;
  Mat3R left_;
};

struct SplitMix {
  std::uint64_t s;
  double uniform() {  // [0, 1)
    std::uint64_t z = (s += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    return static_cast<double>(z >> 11) * 0x1.0p-53;
  }
};

// The largest error of the double evaluation relative to its limit, over the times checked.
struct Factors {
  double R = 0.0, omega = 0.0;
  FreeBodyRegime regime = FreeBodyRegime::rest;
};

Factors error_factors(const Vec3& moments, const Mat3& R0, const Vec3& w0) {
  const RigidBody body = RigidBody::from_principal_moments(moments);
  EXPECT_EQ(body.principal_axes(), Mat3::Identity());  // the reference works in the principal frame
  State s0;
  s0.R_space_body = R0;
  s0.omega_body = w0;
  const ExactFreeBody exact(body, s0);
  const ExactFreeBody50 reference(moments, R0, w0);
  Factors f;
  f.regime = exact.regime();
  for (const double t : {1.0, 1e3, 1e6, 123456789.123, 1e9}) {
    const State d = exact.state_at(t);
    Vec3 w;
    Mat3 R;
    reference.at(t, w, R);
    const double ulp_t = std::nextafter(t, 2 * t) - t;
    const Vec3 Jw = moments.cwiseProduct(w);
    const double w_dot = (Jw.cross(w)).cwiseQuotient(moments).norm();  // |ω̇| = |J⁻¹(Jω × ω)|
    const double limit_R = ulp_t * w.norm() + 8 * kEps;
    const double limit_w = ulp_t * w_dot + 8 * kEps * w.norm();
    f.R = std::max(f.R, (d.R_space_body - R).cwiseAbs().maxCoeff() / limit_R);
    f.omega = std::max(f.omega, (d.omega_body - w).cwiseAbs().maxCoeff() / limit_w);
  }
  return f;
}

Mat3 random_rotation(SplitMix& rng) {
  return so3::exp(Vec3(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5) * 6.0);
}

TEST(ExactFreeBodyPrecision, RandomBodiesStayAtTheConditioningLimit) {
  SplitMix rng{2008};
  Factors worst;
  int largest = 0, smallest = 0;
  for (int i = 0; i < 12; ++i) {
    // Ascending, distinct, and I3 < I1 + I2 (the triangle inequality of a real body).
    const double I1 = 1.0 + rng.uniform();
    const double I2 = I1 + 0.05 + rng.uniform();
    const Vec3 I(I1, I2, I2 + (0.05 + 0.9 * rng.uniform()) * I1);
    const Vec3 w(rng.uniform() - 0.5, rng.uniform() - 0.5, rng.uniform() - 0.5);
    const Factors f = error_factors(I, random_rotation(rng), 2.0 * w);
    worst.R = std::max(worst.R, f.R);
    worst.omega = std::max(worst.omega, f.omega);
    largest += f.regime == FreeBodyRegime::largest_axis;
    smallest += f.regime == FreeBodyRegime::smallest_axis;
  }
  EXPECT_GT(largest, 0);  // both regimes drawn
  EXPECT_GT(smallest, 0);
  std::printf("random bodies: error / limit: R %.2f, omega %.2f\n", worst.R, worst.omega);
  EXPECT_LE(worst.R, 4.0);
  EXPECT_LE(worst.omega, 4.0);
}

TEST(ExactFreeBodyPrecision, NearTheSeparatrix) {
  // |L|² − 2T I2 = I3(I3 − I2)ω3² − I1(I2 − I1)ω1² set to δ·I1(I2 − I1)ω1² by the choice of ω3, δ = ±1e-4 …
  // ±1e-13: k'² ∝ |δ|.
  SplitMix rng{1997};
  for (const double delta : {1e-4, -1e-4, 1e-7, -1e-7, 1e-10, -1e-10, 1e-13, -1e-13}) {
    const Vec3 I(1.0, 2.0, 3.0);
    const double w1 = 0.1 + 0.2 * rng.uniform();
    const double w3 = std::sqrt(I[0] * (I[1] - I[0]) * w1 * w1 * (1.0 + delta) / (I[2] * (I[2] - I[1])));
    const Factors f = error_factors(I, random_rotation(rng), Vec3(w1, 2.0, w3));
    std::printf("separatrix gap %g: error / limit: R %.2f, omega %.2f\n", delta, f.R, f.omega);
    // The phase u = ω_p t + u0 is as accurate as anywhere once k'² is (the separatrix gap is evaluated in
    // double-double; in plain double the factors were 1e2 to 1e13), and R's precession angle φ is as accurate
    // as its Π(N; am u) − u, whose Carlson form takes cn² and dn² near u = ±K, where they are O(k'²): it
    // needs their relative precision (jacobi_elliptic.hpp; with cn and dn to a few ulps of 1 R's factor was
    // 38 at |δ| = 1e-10). Measured factors ≤ 2.3 (R) and 2.4 (ω).
    EXPECT_LE(f.omega, 4.0) << "gap " << delta;
    EXPECT_LE(f.R, 4.0) << "gap " << delta;
  }
}

}  // namespace
}  // namespace poinsot::dynamics
