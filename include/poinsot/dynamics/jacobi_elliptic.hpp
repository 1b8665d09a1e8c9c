#pragma once
/// @file jacobi_elliptic.hpp
/// Jacobi elliptic functions sn, cn, dn and the complete integral K(k) from the *complementary*
/// modulus k' = √(1 − k²). Boost.Math's jacobi_elliptic takes k and forms k' = √(1 − k²) itself, which loses
/// the relative precision of k' near the separatrix (k → 1, k'² ≪ 1) where the free body's tennis-racket
/// flips live: with k'² = 5e-5 that costs 1e-11 in ω at t = 100 s. Here k' is an input, so K(k) and the
/// phases keep full precision for every k' > 0, and sn² + cn² = 1, dn² = cn² + k'² sn² hold to a few ulps.
///
/// Each function keeps its own *relative* precision, also where cn and dn are small (near the separatrix
/// they fall like sech u to √k' at u = K/2 and to 0 and k' at u = K); functions of cn² and dn² (the Carlson
/// form of Π in exact_free_body.cpp, as sensitive to them as a logarithm) need that. Three pieces:
/// - k'² > ½: the arithmetic–geometric mean and the descending Landen transformation (Abramowitz & Stegun
///   16.4; DLMF 22.20(ii)) for |u| ≤ K/2, where cn ≥ √(k'/(1 + k')) > 0.6 and dn ≥ k' > 0.7;
/// - k'² ≤ ½: the ascending Landen transformation (DLMF 22.7(ii)) for |u| ≤ K/2: k'ₙ₊₁ = k'ₙ²/(1 + kₙ)² falls
///   quadratically until sn, cn, dn are tanh, sech, sech of the scaled argument to a relative k'ₙ^{3/2}
///   (DLMF 22.10(ii)), and each step back is a product or quotient, with the one difference dn² − k'ₙ₊₁ of
///   cn bounded away from cancellation (dn² ≥ √k'ₙ₊₁ for |u| ≤ K/2);
/// - K/2 < |u| ≤ K: the quarter-period shift v = K − |u| (DLMF 22.4.3),
///   sn(u) = sign(u)·cn(v)/dn(v), cn(u) = k'·sn(v)/dn(v), dn(u) = k'/dn(v), exact subtraction (Sterbenz).
#include <array>
#include <cmath>
#include <limits>
#include <numbers>

namespace poinsot::dynamics {

/// The AGM of (1, k') (and the ascending moduli) are computed once; evaluate(u) then costs at most 7 sines
/// and 7 arcsines (descending), or a hyperbolic tangent and cosine and ≤ 6 quotients (ascending).
class JacobiElliptic {
 public:
  /// k2 = k², kc2 = k'² = 1 − k² (both given, kc2 > 0, the one computed without cancellation matters).
  JacobiElliptic() = default;
  JacobiElliptic(double k2, double kc2) : kc2_(kc2), kc_(std::sqrt(kc2)) {
    double a = 1.0;
    double b = kc_;
    double c = std::sqrt(k2);
    n_ = 0;
    while (n_ < kMax && c > std::numeric_limits<double>::epsilon() * a) {
      const double a1 = 0.5 * (a + b);
      const double b1 = std::sqrt(a * b);
      c = c * c / (4.0 * a1);  // = (a − b)/2 without cancellation, since c² = a² − b²
      a = a1;
      b = b1;
      ratio_[n_] = c / a;  // c_{n+1}/a_{n+1}
      ++n_;
    }
    a_n_ = a;
    if (kc2 <= 0.5) {
      // Ascending moduli: k'ₙ₊₁ = (1 − kₙ)/(1 + kₙ) = k'ₙ²/(1 + kₙ)², kₙ₊₁² = 4kₙ/(1 + kₙ)², until k'ₙ ≤ 2⁻⁴⁰
      // (the hyperbolic limit's relative error k'^{3/2} is then below 1e-18).
      double kn = std::sqrt(k2), kcn = kc_;
      while (ascending_ < kMax && kcn > 0x1.0p-40) {
        const double one_plus = 1.0 + kn;
        kcn = (kcn / one_plus) * (kcn / one_plus);
        kn = 2.0 * std::sqrt(kn) / one_plus;
        ascending_kc_[ascending_] = kcn;
        ascending_k2_[ascending_] = kn * kn;
        ++ascending_;
      }
    }
  }
  /// K(k) = π/(2 AGM(1, k')).
  double complete() const { return 0.5 * std::numbers::pi / a_n_; }

  /// sn, cn, dn at u, |u| ≤ K (amplitude in [−π/2, π/2]), each to a few ulps of itself (plus the
  /// conditioning u·∂/∂u of a rounded u).
  void evaluate(double u, double& sn, double& cn, double& dn) const {
    const double quarter = complete();
    if (std::abs(u) <= 0.5 * quarter) {
      evaluate_inner(u, sn, cn, dn);
      return;
    }
    double sn_v = 0.0, cn_v = 0.0, dn_v = 0.0;
    evaluate_inner(quarter - std::abs(u), sn_v, cn_v, dn_v);
    sn = std::copysign(cn_v / dn_v, u);
    cn = kc_ * sn_v / dn_v;
    dn = kc_ / dn_v;
  }

 private:
  // |u| ≤ K/2: descending Landen for k'² > ½, ascending otherwise (file comment).
  void evaluate_inner(double u, double& sn, double& cn, double& dn) const {
    if (ascending_ == 0) {
      double phi = std::ldexp(a_n_ * u, n_);  // φ_N = 2^N a_N u
      for (int i = n_ - 1; i >= 0; --i)
        phi = 0.5 * (phi + std::asin(ratio_[i] * std::sin(phi)));
      sn = std::sin(phi);
      cn = std::cos(phi);
      dn = std::sqrt(cn * cn + kc2_ * sn * sn);
      return;
    }
    // Down the chain: wₙ₊₁ = wₙ/(1 + k'ₙ₊₁); at the bottom sn = tanh w, cn = dn = sech w.
    double wn = u;
    for (int i = 0; i < ascending_; ++i)
      wn /= 1.0 + ascending_kc_[i];
    sn = std::tanh(wn);
    cn = 1.0 / std::cosh(wn);
    dn = cn;
    // Back up (DLMF 22.7.5–7), from modulus kₙ₊₁ at wₙ₊₁ to kₙ at wₙ:
    //   sn = (1 + k'ₙ₊₁) sn cn/dn,  cn = (1 + k'ₙ₊₁)(dn² − k'ₙ₊₁)/(kₙ₊₁² dn),
    //   dn = (1 − k'ₙ₊₁)(dn² + k'ₙ₊₁)/(kₙ₊₁² dn).
    for (int i = ascending_ - 1; i >= 0; --i) {
      const double kc = ascending_kc_[i], k2 = ascending_k2_[i];
      const double d2 = dn * dn;
      const double sn_up = (1.0 + kc) * sn * cn / dn;
      const double cn_up = (1.0 + kc) * (d2 - kc) / (k2 * dn);
      dn = (1.0 - kc) * (d2 + kc) / (k2 * dn);
      sn = sn_up;
      cn = cn_up;
    }
  }

  static constexpr int kMax = 16;  // quadratic convergence: 7 iterations reach eps even for k' = 1e-300
  std::array<double, kMax> ratio_{};
  std::array<double, kMax> ascending_kc_{};  // k'ₙ₊₁ of the ascending transformation
  std::array<double, kMax> ascending_k2_{};  // kₙ₊₁²
  double a_n_ = 1.0;
  double kc2_ = 1.0;
  double kc_ = 1.0;  // k' = √(k'²)
  int n_ = 0;
  int ascending_ = 0;  // number of ascending steps; 0: the descending transformation is used
};

}  // namespace poinsot::dynamics
