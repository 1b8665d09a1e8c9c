#include "poinsot/dynamics/exact_free_body.hpp"

#include <fmt/format.h>
#include <boost/math/policies/policy.hpp>
#include <boost/math/special_functions/ellint_rf.hpp>
#include <boost/math/special_functions/ellint_rj.hpp>
#include <cmath>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::dynamics {
namespace {

// Double precision throughout (Boost's default promotes to long double, which costs 3-4x for no gain that
// matters here: Carlson's integrals are accurate to a few ulps in double).
using Policy = boost::math::policies::policy<boost::math::policies::promote_double<false>>;

double sign_of(double x) {
  return x < 0.0 ? -1.0 : 1.0;
}

/// Rotation by angle a about the coordinate axis i (right-hand rule).
Mat3 axis_rotation(int i, double a) {
  const double c = std::cos(a);
  const double s = std::sin(a);
  const int j = (i + 1) % 3;
  const int l = (i + 2) % 3;
  Mat3 r = Mat3::Zero();
  r(i, i) = 1.0;
  r(j, j) = c;
  r(l, l) = c;
  r(j, l) = -s;
  r(l, j) = s;
  return r;
}

/// ExactMethod::elliptic's regime: the free-body theory's, with a symmetric body followed as the limit of the
/// asymmetric one about its symmetry axis. Throws InvalidInput for a body at rest, a sphere, or a symmetric
/// body spinning in its equatorial plane (no component along the symmetry axis to follow).
FreeBodyRegime elliptic_regime(FreeBodyRegime shape, const Vec3& I, const Vec3& w) {
  if (shape == FreeBodyRegime::rest || shape == FreeBodyRegime::sphere) {
    throw InvalidInput(
        fmt::format("exact: method elliptic needs a rotating body with I1 < I3; got moments {} kg·m² and "
                    "omega {} rad/s",
                    format_vector(I), format_vector(w)));
  }
  if (shape != FreeBodyRegime::axisymmetric) return shape;
  if (I[1] - I[0] <= I[2] - I[1] && w[2] != 0.0) return FreeBodyRegime::largest_axis;
  if (I[1] - I[0] > I[2] - I[1] && w[0] != 0.0) return FreeBodyRegime::smallest_axis;
  throw InvalidInput(fmt::format(
      "exact: method elliptic cannot follow a symmetric body (moments {} kg·m²) spinning in its equatorial "
      "plane (omega {} rad/s); expected a non-zero component along the symmetry axis",
      format_vector(I), format_vector(w)));
}

/// The Jacobi-elliptic form of ω(t) in principal axes (free_body_theory.hpp): which axes follow cn and dn,
/// the frequency ω_p, the modulus k² and its complement k'² (from the separatrix gap, without
/// cancellation), the signed amplitudes, and sn, cn at the start.
struct JacobiSetUp {
  int cn_axis = 0, dn_axis = 2;
  double omega_p = 0.0, k2 = 0.0, kc2 = 1.0;
  Vec3 amplitude = Vec3::Zero();
  double sn0 = 0.0, cn0 = 1.0;
};

/// The set-up for moments I (ascending), principal-axis rate w, the regime (largest axis and separatrix:
/// about axis 3; smallest axis: about axis 1) and the gaps gap3 = 2T I3 − |L|², gap1 = |L|² − 2T I1 (both >
/// 0).
JacobiSetUp jacobi_set_up(const Vec3& I, const Vec3& w, FreeBodyRegime shape, double separatrix_gap,
                          double gap1, double gap3) {
  JacobiSetUp out;
  const double I123 = I[0] * I[1] * I[2];
  if (shape != FreeBodyRegime::smallest_axis) {
    out.cn_axis = 0, out.dn_axis = 2;
    out.omega_p = std::sqrt((I[2] - I[1]) * gap1 / I123);
    out.k2 = std::min(1.0, (I[1] - I[0]) * gap3 / ((I[2] - I[1]) * gap1));
    out.kc2 = (I[2] - I[0]) * separatrix_gap / ((I[2] - I[1]) * gap1);
    const double a1 = std::sqrt(gap3 / (I[0] * (I[2] - I[0])));
    const double a2 = std::sqrt(gap3 / (I[1] * (I[2] - I[1])));
    const double a3 = std::sqrt(gap1 / (I[2] * (I[2] - I[0])));
    const double s3 = sign_of(w[2]);
    if (shape == FreeBodyRegime::separatrix) {
      // ω1 = σ1 a1 sech u, ω2 = σ1σ3 a2 tanh u, ω3 = σ3 a3 sech u (Euler's equations fix σ2 = σ1σ3).
      const double s1 = sign_of(w[0]);
      out.amplitude = Vec3(s1 * a1, s1 * s3 * a2, s3 * a3);
      out.sn0 = w[1] / out.amplitude[1];
      out.cn0 = 0.5 * ((a1 > 0.0 ? std::abs(w[0]) / a1 : 0.0) + (a3 > 0.0 ? std::abs(w[2]) / a3 : 0.0));
    } else {
      // ω1 = a1 cn u, ω2 = σ3 a2 sn u, ω3 = σ3 a3 dn u.
      out.amplitude = Vec3(a1, s3 * a2, s3 * a3);
      out.sn0 = w[1] / out.amplitude[1];
      out.cn0 = w[0] / out.amplitude[0];
    }
  } else {
    out.cn_axis = 2, out.dn_axis = 0;
    out.omega_p = std::sqrt((I[1] - I[0]) * gap3 / I123);
    out.k2 = std::min(1.0, (I[2] - I[1]) * gap1 / ((I[1] - I[0]) * gap3));
    out.kc2 = (I[2] - I[0]) * (-separatrix_gap) / ((I[1] - I[0]) * gap3);
    const double a1 = std::sqrt(gap3 / (I[0] * (I[2] - I[0])));
    const double a2 = std::sqrt(gap1 / (I[1] * (I[1] - I[0])));
    const double a3 = std::sqrt(gap1 / (I[2] * (I[2] - I[0])));
    const double s1 = sign_of(w[0]);
    // ω1 = σ1 a1 dn u, ω2 = σ1 a2 sn u, ω3 = a3 cn u.
    out.amplitude = Vec3(s1 * a1, s1 * a2, a3);
    out.sn0 = w[1] / out.amplitude[1];
    out.cn0 = w[2] / out.amplitude[2];
  }
  return out;
}

}  // namespace

State axisymmetric_free_motion(double A, double C, const Vec3& axis_body, const State& initial, double t) {
  const double dt = t - initial.time;
  const Vec3& w0 = initial.omega_body;
  const double mu = axis_body.dot(w0);
  const double nu =
      (C / A - 1.0) * mu;  // rad/s: ω precesses about the axis at ν (docs/conventions.md C11: not (A − C)/A)
  const Mat3 E = so3::exp((nu * dt) * axis_body);
  const Vec3 l_over_a = w0 + nu * axis_body;  // J ω0 / A
  State s;
  s.time = t;
  s.omega_body = E * w0;
  s.R_space_body = initial.R_space_body * so3::exp(dt * l_over_a) *
                   E.transpose();  // order R·E (docs/conventions.md, "order of factors")
  return s;
}

ExactFreeBody::ExactFreeBody(const RigidBody& body, const State& initial, ExactMethod method)
    : initial_(initial) {
  validate_state(initial, "exact: initial state");
  axes_ = body.principal_axes();
  const Vec3 w = axes_.transpose() * initial.omega_body;
  theory_ = free_body_theory(body.principal_moments(), w);
  moments_ = theory_.moments;
  const Vec3& I = theory_.moments;

  const FreeBodyRegime shape =
      method == ExactMethod::elliptic ? elliptic_regime(theory_.regime, I, w) : theory_.regime;
  theory_.regime = shape;

  switch (shape) {
    case FreeBodyRegime::rest:
    case FreeBodyRegime::sphere:
    case FreeBodyRegime::principal_rotation:
      kind_ = Kind::steady;
      return;
    case FreeBodyRegime::axisymmetric: {
      kind_ = Kind::axisymmetric;
      const bool oblate = I[1] - I[0] <= I[2] - I[1];  // I1 = I2: symmetry axis 3; else I2 = I3: axis 1
      axis_ = oblate ? 2 : 0;
      const double A = oblate ? 0.5 * (I[0] + I[1]) : 0.5 * (I[1] + I[2]);
      moments_ = Vec3(A, A, A);
      moments_[axis_] = I[axis_];
      return;
    }
    case FreeBodyRegime::separatrix:
      kind_ = Kind::separatrix;
      break;
    case FreeBodyRegime::largest_axis:
    case FreeBodyRegime::smallest_axis:
      kind_ = Kind::elliptic;
      break;
  }

  // Jacobi-elliptic set-up (free_body_theory.hpp): gaps without cancellation, amplitudes, signs, phase u0.
  const double d3 = I[0] * (I[2] - I[0]) * w[0] * w[0] + I[1] * (I[2] - I[1]) * w[1] * w[1];  // 2T I3 − |L|²
  const double d1 = I[1] * (I[1] - I[0]) * w[1] * w[1] + I[2] * (I[2] - I[0]) * w[2] * w[2];  // |L|² − 2T I1
  if (d3 == 0.0 || d1 == 0.0) {  // a steady rotation about axis 3 or 1 (reached by ExactMethod::elliptic)
    kind_ = Kind::steady;
    return;
  }
  const bool largest = shape != FreeBodyRegime::smallest_axis;  // the separatrix is followed from axis 3
  const JacobiSetUp jac = jacobi_set_up(I, w, shape, theory_.separatrix_gap, d1, d3);
  cn_axis_ = jac.cn_axis, dn_axis_ = jac.dn_axis;
  omega_p_ = jac.omega_p;
  kc2_ = jac.kc2;
  amplitude_ = jac.amplitude;
  const double k2 = jac.k2;
  double sn0 = jac.sn0;
  double cn0 = jac.cn0;
  // The polar axis c of the attitude frame B(n): 3 or 1, both valid in both regimes (n never reaches ±e_c:
  // the component that follows dn never vanishes). With L_c² = P − Q sn² (Q = P k² when L_c follows dn, Q = P
  // when it follows cn), φ̇ = G/I_c + C1/(1 − N sn²), C1 = G(2T − G²/I_c)/(G² − P), N = −Q/(G² − P):
  //   c = 3: C1 = G(1/I1 − 1/I3), N = −I3 d1 q/(I1 d3);   c = 1: C1 = G(1/I3 − 1/I1), N = −I1 d3 q/(I3 d1),
  // q = k² or 1. The two N multiply to k²; the one of smaller magnitude keeps Π well conditioned (|N| → ∞
  // for a nearly symmetric body otherwise).
  const double q3 = largest ? k2 : 1.0;  // L3 follows dn (axis-3 regime and separatrix) or cn
  const double q1 = largest ? 1.0 : k2;
  const double n3 = -I[2] * d1 * q3 / (I[0] * d3);
  const double n1 = -I[0] * d3 * q1 / (I[2] * d1);
  const double G = theory_.momentum;
  double c1 = 0.0;
  if (std::abs(n3) <= std::abs(n1)) {
    a_ = 0, b_ = 1, c_ = 2;
    n_ = n3;
    c1 = G * (1.0 / I[0] - 1.0 / I[2]);
  } else {
    a_ = 1, b_ = 2, c_ = 0;
    n_ = n1;
    c1 = G * (1.0 / I[2] - 1.0 / I[0]);
  }
  rate1_ = c1 / omega_p_;
  rate_lin_ = G / I[c_] + c1;  // the linear part of Π(u), moved out of the bracket
  if (kind_ == Kind::separatrix) {
    u0_ = std::asinh(sn0 / cn0);
  } else {
    jacobi_ = JacobiElliptic(k2, kc2_);
    const double K = jacobi_.complete();
    two_k_ = 2.0 * K;
    // Π(N) − K = (N/3) R_J(0, k'², 1, 1 − N) (Carlson; DLMF §19.25(i)).
    pi_shift_ = 2.0 * (n_ / 3.0) * boost::math::ellint_rj(0.0, kc2_, 1.0, 1.0 - n_, Policy());
    // u0 = F(am0 | k) = sn0 R_F(cn0², dn0², 1), continued through F(π − x) = 2K − F(x) when cn0 < 0.
    const double r = std::hypot(sn0, cn0);
    sn0 /= r;
    cn0 /= r;
    const double dn0 = std::sqrt(cn0 * cn0 + kc2_ * sn0 * sn0);
    const double f = sn0 * boost::math::ellint_rf(cn0 * cn0, dn0 * dn0, 1.0, Policy());
    u0_ = cn0 >= 0.0 ? f : sign_of(sn0) * two_k_ - f;
  }
  corr0_ = phase(u0_).pi_minus_u;
  if (kind_ == Kind::elliptic) {  // keep theory_ consistent when ExactMethod::elliptic overrode the regime
    theory_.modulus = std::sqrt(k2);
    theory_.modulus_complement2 = kc2_;
    theory_.omega_p = omega_p_;
    theory_.quarter_period = 0.5 * two_k_;
  }
  const Mat3 r0 = initial.R_space_body * axes_;  // R_principal(t0)
  left_ = r0 * attitude_frame(w).transpose();
}

ExactFreeBody::Phase ExactFreeBody::phase(double u) const {
  Phase p{};
  if (kind_ == Kind::separatrix) {
    // ∫₀^u du/(1 − N tanh²u) = [u + √−N atan(√−N tanh u)]/(1 − N).
    p.sn = std::tanh(u);
    p.cn = 1.0 / std::cosh(u);
    p.dn = p.cn;
    const double s = std::sqrt(-n_);
    p.pi_minus_u = (n_ * u + s * std::atan(s * p.sn)) / (1.0 - n_);
    return p;
  }
  // Reduce u to [−K, K]: sn, cn change sign and am advances by π every 2K; Π − F advances by 2(Π(N) − K).
  const double m = std::nearbyint(u / two_k_);
  const double ur = u - m * two_k_;
  jacobi_.evaluate(ur, p.sn, p.cn, p.dn);
  const double s2 = p.sn * p.sn;
  // Π(N; am ur) − ur = (N/3) sn³ R_J(cn², dn², 1, 1 − N sn²)  (DLMF §19.25(i), with F = ur).
  p.pi_minus_u = (n_ / 3.0) * p.sn * s2 *
                     boost::math::ellint_rj(p.cn * p.cn, p.dn * p.dn, 1.0, 1.0 - n_ * s2, Policy()) +
                 m * pi_shift_;
  if (std::fmod(m, 2.0) != 0.0) {
    p.sn = -p.sn;
    p.cn = -p.cn;
  }
  return p;
}

Mat3 ExactFreeBody::attitude_frame(const Vec3& w) const {
  // Rows: B(n) of the header in the cyclic frame (a, b, c), written in principal coordinates.
  const Vec3 m = moments_.cwiseProduct(w);
  const Vec3 n = m / m.norm();
  const double na = n[a_], nb = n[b_], nc = n[c_];
  const double s = std::hypot(na, nb);
  Mat3 B = Mat3::Zero();
  if (s > 0.0) {
    B(0, a_) = nb / s, B(0, b_) = -na / s;
    B(1, a_) = nc * na / s, B(1, b_) = nc * nb / s, B(1, c_) = -s;
  } else {  // n = ±e_c (not reached by the elliptic regimes, kept for safety)
    B(0, a_) = 1.0;
    B(1, b_) = nc;
  }
  B(2, a_) = na, B(2, b_) = nb, B(2, c_) = nc;
  return B;
}

State ExactFreeBody::state_at(double t) const {
  const double dt = t - initial_.time;
  switch (kind_) {
    case Kind::steady: {
      State s;
      s.time = t;
      s.omega_body = initial_.omega_body;
      s.R_space_body = initial_.R_space_body * so3::exp(dt * initial_.omega_body);
      return s;
    }
    case Kind::axisymmetric:
      return axisymmetric_free_motion(moments_[(axis_ + 1) % 3], moments_[axis_], axes_.col(axis_), initial_,
                                      t);
    case Kind::elliptic:
    case Kind::separatrix:
      break;
  }
  const Phase p = phase(omega_p_ * dt + u0_);
  Vec3 w;
  w[cn_axis_] = amplitude_[cn_axis_] * p.cn;
  w[1] = amplitude_[1] * p.sn;
  w[dn_axis_] = amplitude_[dn_axis_] * p.dn;
  const double phi = rate_lin_ * dt + rate1_ * (p.pi_minus_u - corr0_);
  State s;
  s.time = t;
  s.omega_body = axes_ * w;
  s.R_space_body = left_ * axis_rotation(2, phi) * attitude_frame(w) * axes_.transpose();
  return s;
}

}  // namespace poinsot::dynamics
