// Heavy symmetric top theory (top_theory.hpp) against independent oracles: a direct long-double integration
// of Lagrange's equations over one nutation period, Gauss–Kronrod/tanh-sinh quadrature of the energy
// equation, the figures of docs/conventions.md B3 (obtained there by a full 3-D DOP853 simulation), and the
// limits of the theory.
#include "poinsot/dynamics/top_theory.hpp"

#include <gtest/gtest.h>
#include <array>
#include <boost/math/quadrature/tanh_sinh.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_fehlberg78.hpp>
#include <cmath>
#include <numbers>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/rigid_body.hpp"

namespace poinsot::dynamics {
namespace {

// The disc top of docs/conventions.md B3: M = 1 kg, l = 0.1 m, disc radius 5 cm: I3 = M r²/2, I1 = M r²/4 + M
// l² (pivot).
HeavyTop disc_top() {
  HeavyTop t;
  t.mass = 1.0;
  t.length = 0.1;
  t.I3 = 0.5 * 0.05 * 0.05;
  t.I1 = 0.25 * 0.05 * 0.05 + 0.1 * 0.1;
  t.gravity = 9.81;
  return t;
}

/// f(u) of the energy equation, from the initial data.
struct EnergyCubic {
  double a, b, alpha, beta;
  EnergyCubic(const HeavyTop& top, double theta0, double theta_dot0, double phi_dot0, double omega3) {
    const double s2 = std::sin(theta0) * std::sin(theta0);
    a = top.I3 * omega3 / top.I1;
    b = phi_dot0 * s2 + a * std::cos(theta0);
    beta = 2.0 * top.mgl() / top.I1;
    alpha = theta_dot0 * theta_dot0 + phi_dot0 * phi_dot0 * s2 + beta * std::cos(theta0);
  }
  double operator()(double u) const { return (1 - u * u) * (alpha - beta * u) - (b - a * u) * (b - a * u); }
};

/// Lagrange's equations of the top, reduced by the conserved p_φ and ω3: y = (θ, θ̇, φ), long double.
struct Lagrange {
  long double a, b, half_beta;
  using Y = std::array<long double, 3>;
  void operator()(const Y& y, Y& dy, long double) const {
    const long double s = std::sin(y[0]), c = std::cos(y[0]);
    const long double phid = (b - a * c) / (s * s);
    dy[0] = y[1];
    dy[1] = s * (phid * phid * c - a * phid + half_beta);  // I1 θ̈ = I1 φ̇² sinθ cosθ − I3ω3 φ̇ sinθ + Mgl sinθ
    dy[2] = phid;
  }
};

TEST(TopTheory, MatchesDirectIntegrationOverOneNutationPeriod) {
  const HeavyTop top = disc_top();
  struct Case {
    double theta0, theta_dot0, phi_dot0, omega3;
  };
  for (const Case& c : {Case{1.0471975511965976, 0.0, 0.0, 200.0}, Case{0.8, 0.7, 1.5, 30.0},
                        Case{2.0, -0.3, -2.0, 60.0}, Case{0.5, 0.2, 0.0, -120.0}}) {
    const TopMotion m = top_motion(top, c.theta0, c.theta_dot0, c.phi_dot0, c.omega3);
    const EnergyCubic f(top, c.theta0, c.theta_dot0, c.phi_dot0, c.omega3);
    Lagrange ode{f.a, f.b, 0.5L * f.beta};
    Lagrange::Y y{c.theta0, c.theta_dot0, 0.0L};
    boost::numeric::odeint::runge_kutta_fehlberg78<Lagrange::Y, long double> stepper;
    // 10000 steps per period: h·(fastest rate) ≤ 0.01, RKF78's error ~ (0.01)⁸ per unit phase: < 1e-14.
    const int steps = 10000;
    const long double h = static_cast<long double>(m.nutation_period) / steps;
    double theta_lo = c.theta0, theta_hi = c.theta0;
    for (int i = 0; i < steps; ++i) {
      stepper.do_step(ode, y, i * h, h);
      theta_lo = std::min(theta_lo, static_cast<double>(y[0]));
      theta_hi = std::max(theta_hi, static_cast<double>(y[0]));
    }
    SCOPED_TRACE(c.omega3);
    // After exactly T_nut the axis is back where it started (θ and θ̇): T_nut is right to ~1e-10 relative.
    EXPECT_NEAR(static_cast<double>(y[0]), c.theta0, 1e-9);
    EXPECT_NEAR(static_cast<double>(y[1]), c.theta_dot0, 1e-9 * (1.0 + std::abs(f.a)));
    // The precession over that period: the mean rate to 1e-9 relative (the target is 1e-6).
    EXPECT_NEAR(static_cast<double>(y[2]), m.precession_per_nutation,
                1e-9 * std::abs(m.precession_per_nutation));
    // The turning points bound the motion (sampled every step, so to within the step's reach).
    EXPECT_NEAR(theta_lo, m.theta_min, 1e-6);
    EXPECT_NEAR(theta_hi, m.theta_max, 1e-6);
    EXPECT_LE(std::abs(f(m.u1)), 1e-10 * (f.alpha * f.alpha + f.a * f.a + f.beta));
    EXPECT_LE(std::abs(f(m.u2)), 1e-10 * (f.alpha * f.alpha + f.a * f.a + f.beta));
    EXPECT_LE(m.u1, std::cos(c.theta0) + 1e-15);
    EXPECT_GE(m.u2, std::cos(c.theta0) - 1e-15);
    EXPECT_GE(m.u3, 1.0);
  }
}

TEST(TopTheory, MatchesQuadratureOfTheEnergyEquation) {
  const HeavyTop top = disc_top();
  const double th0 = 0.9, thd0 = 0.4, phd0 = 0.8, w3 = 45.0;
  const TopMotion m = top_motion(top, th0, thd0, phd0, w3);
  const EnergyCubic f(top, th0, thd0, phd0, w3);
  boost::math::quadrature::tanh_sinh<double> ts;
  // tanh-sinh handles the inverse-square-root singularities at both turning points.
  const double half_period =
      ts.integrate([&](double u) { return 1.0 / std::sqrt(std::max(f(u), 1e-300)); }, m.u1, m.u2);
  const double half_phi = ts.integrate(
      [&](double u) { return (f.b - f.a * u) / ((1 - u * u) * std::sqrt(std::max(f(u), 1e-300))); }, m.u1,
      m.u2);
  // Near a turning point f(u) ≈ f'(u_i)(u − u_i) is evaluated with an absolute error δ ~ eps·(α² + a²), which
  // changes ∫du/√f by ~√δ/f': the quadrature is good to ~√eps ≈ 1e-8 relative (measured 1.3e-8 here), hence
  // 1e-7. The direct integration above checks the same quantities to 1e-9 without that limitation.
  EXPECT_NEAR(2.0 * half_period, m.nutation_period, 1e-7 * m.nutation_period);
  EXPECT_NEAR(2.0 * half_phi, m.precession_per_nutation, 1e-7 * std::abs(m.precession_per_nutation));
}

// docs/conventions.md B3: the fast-top formula's relative error against the exact mean precession for the
// disc top released at θ0 = 60° with pure spin: −3.1 %, −1.8 %, −0.51 %, −0.13 % at ω3 = 200, 400, 800, 1600
// rad/s (figures rounded to two digits there, hence the tolerance of half a unit in the last digit).
TEST(TopTheory, FastTopErrorMatchesErrataAndFallsAsInverseSquare) {
  const HeavyTop top = disc_top();
  const double theta0 = std::numbers::pi / 3.0;
  struct Row {
    double omega3, percent, tol;
  };
  double previous = 0.0;
  for (const Row& r :
       {Row{200, -3.1, 0.05}, Row{400, -1.8, 0.05}, Row{800, -0.51, 0.005}, Row{1600, -0.13, 0.005}}) {
    const double exact = top_motion(top, theta0, 0.0, 0.0, r.omega3).mean_precession_rate;
    const double fast = fast_top_precession_rate(top, r.omega3);
    const double rel = (fast - exact) / exact;
    EXPECT_NEAR(100.0 * rel, r.percent, r.tol) << r.omega3;
    if (r.omega3 >= 800) {
      EXPECT_NEAR(previous / rel, 4.0, 0.5) << r.omega3;  // 1/ω3² in the fast regime
    }
    previous = rel;
  }
  // Deeper in the fast regime the ratio per doubling tends to 4.
  const auto rel_at = [&](double w) {
    const double exact = top_motion(top, theta0, 0.0, 0.0, w).mean_precession_rate;
    return (fast_top_precession_rate(top, w) - exact) / exact;
  };
  EXPECT_NEAR(rel_at(6400) / rel_at(12800), 4.0, 0.05);
  // The nutation frequency tends to a = I3 ω3/I1.
  const double w = 12800;
  EXPECT_NEAR(top_motion(top, theta0, 0.0, 0.0, w).nutation_frequency / (top.I3 * w / top.I1), 1.0, 1e-4);
}

TEST(TopTheory, SteadyPrecessionRoots) {
  const HeavyTop top = disc_top();
  for (double theta : {0.3, 1.0, 2.5}) {
    for (double w3 : {200.0, 700.0}) {
      const SteadyPrecession r = steady_precession_rates(top, theta, w3);
      ASSERT_EQ(r.count, 2);
      for (double pd : {r.slow, r.fast}) {
        const double residual = top.I1 * std::cos(theta) * pd * pd - top.I3 * w3 * pd + top.mgl();
        EXPECT_LE(std::abs(residual), 1e-12 * top.I3 * w3 * std::abs(pd));
        // Started at the root with θ̇ = 0 the top precesses steadily: no nutation, Ω̄ = the root.
        const TopMotion m = top_motion(top, theta, 0.0, pd, w3);
        EXPECT_LE(m.u2 - m.u1, 1e-9);
        EXPECT_NEAR(m.mean_precession_rate, pd, 1e-9 * std::abs(pd));
      }
      // The slow root approaches the gyroscopic formula as 1/ω3².
      EXPECT_NEAR(r.slow / fast_top_precession_rate(top, w3), 1.0,
                  2.0 * top.I1 * top.mgl() / std::pow(top.I3 * w3, 2));
    }
  }
  const SteadyPrecession horizontal = steady_precession_rates(top, std::numbers::pi / 2, 300.0);
  EXPECT_EQ(horizontal.count, 1);
  EXPECT_NEAR(horizontal.slow, fast_top_precession_rate(top, 300.0), 1e-15);
  // Upright-ish and too slow: no steady precession (I3²ω3² < 4 I1 M g l cos θ).
  EXPECT_EQ(steady_precession_rates(top, 0.2, 50.0).count, 0);
}

// A top started almost upright with pure spin stays up above the threshold and falls below it (to
// u = a²/β − 1, the other root of f when θ0 → 0).
TEST(TopTheory, SleepingTopCriterion) {
  const HeavyTop top = disc_top();
  const double thr = sleeping_top_threshold(top);
  EXPECT_NEAR(thr * thr, 4.0 * top.I1 * top.mgl() / (top.I3 * top.I3), 1e-12 * thr * thr);
  EXPECT_TRUE(is_sleeping_top_stable(top, 1.01 * thr));
  EXPECT_FALSE(is_sleeping_top_stable(top, 0.99 * thr));
  EXPECT_LT(top_motion(top, 1e-4, 0.0, 0.0, 1.05 * thr).theta_max, 0.01);
  const double w = 0.9 * thr;
  const TopMotion fall = top_motion(top, 1e-4, 0.0, 0.0, w);
  const double a = top.I3 * w / top.I1, beta = 2.0 * top.mgl() / top.I1;
  EXPECT_NEAR(fall.u1, a * a / beta - 1.0, 1e-6);
  EXPECT_GT(fall.theta_max, 0.5);
}

// A RigidBody disc top and a state built from Euler angles (z-x-z: R = Rz(φ) Rx(θ) Rz(ψ)) and their rates
// (body-frame ω of the z-x-z sequence) give back the parameters and initial data of the theory.
TEST(TopTheory, FromRigidBodyAndState) {
  const HeavyTop ref = disc_top();
  const double r = 0.05, m = 1.0, l = 0.1;
  const RigidBody body =
      RigidBody::from_principal_moments(Vec3(0.25 * m * r * r, 0.25 * m * r * r, 0.5 * m * r * r))
          .with_pivot(m, Vec3(0, 0, l));
  const Vec3 g(0.0, 0.0, -9.81);
  const HeavyTop top = heavy_top_from(body, g);
  EXPECT_NEAR(top.I1, ref.I1, 1e-15);
  EXPECT_NEAR(top.I3, ref.I3, 1e-15);
  EXPECT_NEAR(top.mgl(), ref.mgl(), 1e-15);
  const double phi = 0.4, theta = 1.1, psi = -0.7, phid = 0.8, thetad = -0.3, psid = 150.0;
  const auto Rz = [](double a) { return Eigen::AngleAxisd(a, Vec3::UnitZ()).toRotationMatrix(); };
  const auto Rx = [](double a) { return Eigen::AngleAxisd(a, Vec3::UnitX()).toRotationMatrix(); };
  State s;
  s.R_space_body = Rz(phi) * Rx(theta) * Rz(psi);
  s.omega_body =
      Vec3(phid * std::sin(theta) * std::sin(psi) + thetad * std::cos(psi),
           phid * std::sin(theta) * std::cos(psi) - thetad * std::sin(psi), phid * std::cos(theta) + psid);
  const TopInitialConditions ic = top_initial_conditions(body, s, g);
  EXPECT_NEAR(ic.theta, theta, 1e-14);
  EXPECT_NEAR(ic.theta_dot, thetad, 1e-13);
  EXPECT_NEAR(ic.phi_dot, phid, 1e-13);
  EXPECT_NEAR(ic.omega3, phid * std::cos(theta) + psid, 1e-12);
  EXPECT_THROW(heavy_top_from(RigidBody::from_principal_moments(Vec3(1, 2, 2.5)), g), InvalidInput);
  EXPECT_THROW(
      heavy_top_from(RigidBody::from_principal_moments(Vec3(1, 2, 2.5)).with_pivot(1.0, Vec3(0, 0, 0.1)), g),
      InvalidInput);
}

TEST(TopTheory, RejectsInvalidInput) {
  HeavyTop bad = disc_top();
  bad.I3 = -1.0;
  EXPECT_THROW(validate(bad), InvalidInput);
  EXPECT_THROW(top_motion(disc_top(), 0.0, 0.0, 0.0, 100.0), InvalidInput);
  EXPECT_THROW(top_motion(disc_top(), 1.0, std::nan(""), 0.0, 100.0), InvalidInput);
  EXPECT_THROW(fast_top_precession_rate(disc_top(), 0.0), InvalidInput);
}

}  // namespace
}  // namespace poinsot::dynamics
