#include "poinsot/dynamics/free_body_theory.hpp"

#include <fmt/format.h>
#include <cmath>
#include <limits>
#include <numbers>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/jacobi_elliptic.hpp"

namespace poinsot::dynamics {
namespace {

// Double-double arithmetic (Dekker 1971; Knuth's TwoSum): hi + lo carries ~106 bits, each operation
// accurate to ~ε² relative.
struct DoubleDouble {
  double hi, lo;
};
DoubleDouble two_sum(double a, double b) {
  const double s = a + b;
  const double bb = s - a;
  return {s, (a - (s - bb)) + (b - bb)};
}
DoubleDouble times(const DoubleDouble& a, double b) {
  const double p = a.hi * b;
  const double e = std::fma(a.hi, b, -p) + a.lo * b;
  const double s = p + e;
  return {s, e - (s - p)};
}

// I_i (I_i − I_j) ω_i², exactly up to ~ε² relative.
DoubleDouble gap_term(double Ii, double Ij, double wi) {
  return times(times(times(two_sum(Ii, -Ij), Ii), wi), wi);
}

// |L|² − 2T I2 = I3(I3 − I2)ω3² − I1(I2 − I1)ω1², the only gap with a cancellation: in double-double, so that
// near the separatrix, where it decides k'² (and the period through ln(1/k')), it is accurate to a few ulps
// of itself rather than of its terms (plain double lost ε·|terms|/|gap| relative: a phase error growing like
// t·1e-6 at |gap| ~ 1e-10 |terms|).
double separatrix_gap(const Vec3& I, const Vec3& w) {
  const DoubleDouble a = gap_term(I[2], I[1], w[2]);
  const DoubleDouble b = gap_term(I[0], I[1], w[0]);  // I1 (I1 − I2) ω1² ≤ 0
  const DoubleDouble s = two_sum(a.hi, b.hi);
  return s.hi + (s.lo + (a.lo + b.lo));
}

}  // namespace

const char* to_string(FreeBodyRegime regime) {
  switch (regime) {
    case FreeBodyRegime::rest:
      return "rest";
    case FreeBodyRegime::sphere:
      return "sphere";
    case FreeBodyRegime::axisymmetric:
      return "axisymmetric";
    case FreeBodyRegime::principal_rotation:
      return "principal rotation";
    case FreeBodyRegime::largest_axis:
      return "largest axis";
    case FreeBodyRegime::separatrix:
      return "separatrix";
    case FreeBodyRegime::smallest_axis:
      return "smallest axis";
  }
  return "unknown";
}

double FreeBodyTheory::flip_interval() const {
  if (regime != FreeBodyRegime::largest_axis && regime != FreeBodyRegime::smallest_axis) return 0.0;
  return 2.0 * quarter_period / omega_p;
}

double FreeBodyTheory::omega_period() const {
  if (regime == FreeBodyRegime::axisymmetric) {
    return omega_p > 0.0 ? 2.0 * std::numbers::pi / omega_p : 0.0;
  }
  return 2.0 * flip_interval();
}

FreeBodyTheory free_body_theory(const Vec3& principal_moments, const Vec3& omega_principal) {
  require_finite("free body: principal moments (kg·m²)", principal_moments);
  require_finite("free body: omega (rad/s)", omega_principal);
  const Vec3& I = principal_moments;
  if (!(I[0] > 0.0) || I[1] < I[0] || I[2] < I[1]) {
    throw InvalidInput(fmt::format(
        "free body: principal moments {} kg·m²; expected positive moments in ascending order I1 <= I2 <= I3",
        format_vector(I)));
  }
  FreeBodyTheory th;
  th.moments = I;
  th.omega = omega_principal;
  const Vec3& w = omega_principal;
  th.energy = 0.5 * (I[0] * w[0] * w[0] + I[1] * w[1] * w[1] + I[2] * w[2] * w[2]);
  th.momentum = Vec3(I[0] * w[0], I[1] * w[1], I[2] * w[2]).norm();
  th.separatrix_gap = separatrix_gap(I, w);

  const double tol = kSymmetryTolerance * I[2];
  const bool sym12 = I[1] - I[0] <= tol;
  const bool sym23 = I[2] - I[1] <= tol;
  const int nonzero = (w[0] != 0.0) + (w[1] != 0.0) + (w[2] != 0.0);
  if (nonzero == 0) {
    th.regime = FreeBodyRegime::rest;
    return th;
  }
  if (I[2] - I[0] <= tol) {
    th.regime = FreeBodyRegime::sphere;
    return th;
  }
  if (sym12 || sym23) {
    // J = A·1 + (C − A) e⊗e with e the symmetry axis; ω precesses about e at (C/A − 1)μ, μ = e·ω
    // (docs/conventions.md C11).
    const double A = sym12 ? 0.5 * (I[0] + I[1]) : 0.5 * (I[1] + I[2]);
    const double C = sym12 ? I[2] : I[0];
    const double mu = sym12 ? w[2] : w[0];
    th.regime = FreeBodyRegime::axisymmetric;
    th.omega_p = std::abs((C / A - 1.0) * mu);
    return th;
  }
  if (nonzero == 1) {
    th.regime = FreeBodyRegime::principal_rotation;
    return th;
  }
  // Gaps 2T I_j − |L|² = Σ_i I_i (I_j − I_i) ω_i², each a sum of terms of one sign (no cancellation).
  const double d3 = I[0] * (I[2] - I[0]) * w[0] * w[0] + I[1] * (I[2] - I[1]) * w[1] * w[1];  // 2T I3 − |L|²
  const double d1 = I[1] * (I[1] - I[0]) * w[1] * w[1] + I[2] * (I[2] - I[0]) * w[2] * w[2];  // |L|² − 2T I1
  const double gap = th.separatrix_gap;
  const double I123 = I[0] * I[1] * I[2];
  if (gap >= 0.0) {
    th.omega_p = std::sqrt((I[2] - I[1]) * d1 / I123);
    th.modulus = std::sqrt(std::min(1.0, (I[1] - I[0]) * d3 / ((I[2] - I[1]) * d1)));
    th.modulus_complement2 = (I[2] - I[0]) * gap / ((I[2] - I[1]) * d1);
  } else {
    th.omega_p = std::sqrt((I[1] - I[0]) * d3 / I123);
    th.modulus = std::sqrt(std::min(1.0, (I[2] - I[1]) * d1 / ((I[1] - I[0]) * d3)));
    th.modulus_complement2 = (I[2] - I[0]) * (-gap) / ((I[1] - I[0]) * d3);
  }
  // k' = 0 exactly: the separatrix. Any k' > 0 is followed by the elliptic form, which takes k' itself
  // (jacobi_elliptic.hpp), so the precision holds however close to the separatrix the data are.
  if (!(th.modulus_complement2 > 0.0)) {
    th.regime = FreeBodyRegime::separatrix;
    th.modulus = 1.0;
    th.modulus_complement2 = 0.0;
    th.omega_p = std::sqrt((I[2] - I[1]) * d1 / I123);
    return th;
  }
  th.regime = gap > 0.0 ? FreeBodyRegime::largest_axis : FreeBodyRegime::smallest_axis;
  th.quarter_period = JacobiElliptic(th.modulus * th.modulus, th.modulus_complement2).complete();
  return th;
}

FreeBodyTheory free_body_theory(const RigidBody& body, const Vec3& omega_body) {
  return free_body_theory(body.principal_moments(), body.principal_axes().transpose() * omega_body);
}

}  // namespace poinsot::dynamics
