// The tabulated torque: its interpolation (local cubics on each arc, jumps at repeated times, zero outside),
// the piece announced by the driver at a breakpoint, its errors, and replays through the simulation driver
// against the closed form of a sphere (J = j I: ω̇ = τ/j about a fixed axis, so the angle is the double
// integral of τ/j).
#include "poinsot/dynamics/tabulated_torque.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot_test.hpp"

namespace poinsot::test {
namespace {

using dynamics::TableInterpolation;
using dynamics::TabulatedTorque;

const Vec3 kAxis = Vec3(1.0, 2.0, 2.0) / 3.0;

/// +u n on [0, T/2), −u n on [T/2, T]: the bang-bang rest-to-rest slew of a sphere about n.
TabulatedTorque bang_bang(double u, double T) {
  return TabulatedTorque({0.0, T / 2, T / 2, T}, {u * kAxis, u * kAxis, -u * kAxis, -u * kAxis}, "bang-bang");
}

Vec3 at(const TabulatedTorque& tau, double t) {
  return tau.torque_body(t, Mat3::Identity(), Vec3::Zero());
}

// Arcs of two rows: the interpolant is the line through them.
TEST(TabulatedTorque, InterpolatesLinearlyJumpsAtRepeatedTimesAndIsZeroOutside) {
  const TabulatedTorque tau({1.0, 2.0, 2.0, 4.0},
                            {Vec3(1, 0, 0), Vec3(3, 0, 0), Vec3(0, 2, 0), Vec3(0, 4, 0)}, "t");
  EXPECT_EQ(at(tau, 1.5), Vec3(2, 0, 0));
  EXPECT_EQ(at(tau, 3.0), Vec3(0, 3, 0));
  EXPECT_EQ(at(tau, 2.0), Vec3(0, 2, 0));  // at a jump: the right-hand value
  EXPECT_EQ(at(tau, 4.0), Vec3(0, 4, 0));
  EXPECT_EQ(at(tau, 0.999), Vec3::Zero());
  EXPECT_EQ(at(tau, 4.001), Vec3::Zero());
  EXPECT_EQ(tau.breakpoints(), (std::vector<double>{1.0, 2.0, 4.0}));
  // A step announced on [1, 2] sees the left piece up to and including t = 2; one on [2, 4] the right one.
  tau.enter_interval(1.25);
  EXPECT_EQ(at(tau, 2.0), Vec3(3, 0, 0));
  EXPECT_EQ(at(tau, 1.0), Vec3(1, 0, 0));
  tau.enter_interval(2.0);
  EXPECT_EQ(at(tau, 2.0), Vec3(0, 2, 0));
  EXPECT_EQ(at(tau, 3.0), Vec3(0, 3, 0));  // away from the piece's ends the announcement changes nothing
  // Before and after the table: zero up to and including its ends.
  tau.enter_interval(0.0);
  EXPECT_EQ(at(tau, 1.0), Vec3::Zero());
  tau.enter_interval(4.0);
  EXPECT_EQ(at(tau, 4.0), Vec3::Zero());
  EXPECT_NE(tau.describe().find("4 rows"), std::string::npos) << tau.describe();
}

// A trapezoid (0, 0), (1, 1), (2, 1), (3, 0) on one arc: linear (the default) keeps the plateau at 1 and is
// exact for the profile; the cubic through the four rows overshoots it, to the Lagrange value at t = 1.5 by
// hand: weights (−1/16, 9/16, 9/16, −1/16), so 9/8.
TEST(TabulatedTorque, LinearIsTheDefaultAndKeepsAPiecewiseLinearProfile) {
  const std::vector<double> t{0.0, 1.0, 2.0, 3.0};
  const std::vector<Vec3> u{Vec3::Zero(), Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3::Zero()};
  const TabulatedTorque linear(t, u, "trapezoid");
  EXPECT_EQ(linear.interpolation(), TableInterpolation::linear);
  for (const double x : {0.25, 0.5, 1.5, 2.5})
    EXPECT_NEAR(at(linear, x).x(), std::min({x, 1.0, 3.0 - x}), 1e-15) << x;
  EXPECT_NE(linear.describe().find("linear"), std::string::npos) << linear.describe();
  const TabulatedTorque cubic(t, u, "trapezoid", TableInterpolation::cubic);
  EXPECT_NEAR(at(cubic, 1.5).x(), 9.0 / 8.0, 1e-15);
  EXPECT_NE(cubic.describe().find("cubic"), std::string::npos) << cubic.describe();
}

// On an arc of at least four rows the interpolant is the cubic through the four rows nearest to the piece:
// a cubic τ(t) sampled at unequal times is reproduced between the rows to round-off, on each side of a jump,
// whose two values stay exact. A smooth τ is reproduced to O(h⁴): halving the spacing divides the largest
// error between the rows by 16 (the cubic's remainder τ⁽⁴⁾(ξ) ∏(t − t_k)/4!, its factor h⁴ exact at the
// piece's centre; the measured ratio is within 10 % of it).
TEST(TabulatedTorque, InterpolatesByLocalCubicsOnEachArc) {
  const auto left = [](double t) { return Vec3(1 - 2 * t + 0.5 * t * t * t, t * t, 3.0); };
  const auto right = [](double t) { return Vec3(-t * t * t, 2.0 + t, -1.0); };
  const std::vector<double> tl{0.0, 0.3, 0.7, 1.2, 1.5, 2.0}, tr{2.0, 2.4, 3.1, 3.3, 4.0};
  std::vector<double> t;
  std::vector<Vec3> u;
  for (const double x : tl) {
    t.push_back(x);
    u.push_back(left(x));
  }
  for (const double x : tr) {
    t.push_back(x);
    u.push_back(right(x));
  }
  const TabulatedTorque tau(t, u, "cubic", TableInterpolation::cubic);
  for (double x = 0.05; x < 2.0; x += 0.1)
    EXPECT_LT((at(tau, x) - left(x)).norm(), 1e-13) << x;
  for (double x = 2.05; x < 4.0; x += 0.1)
    EXPECT_LT((at(tau, x) - right(x)).norm(), 1e-13) << x;
  tau.enter_interval(1.7);
  EXPECT_EQ(at(tau, 2.0), left(2.0));
  tau.enter_interval(2.0);
  EXPECT_EQ(at(tau, 2.0), right(2.0));

  const auto largest_error = [](int n) {
    std::vector<double> ts;
    std::vector<Vec3> us;
    for (int i = 0; i <= n; ++i) {
      ts.push_back(2.0 * i / n);
      us.push_back(Vec3(std::sin(3 * ts.back()), 0, 0));
    }
    const TabulatedTorque s(ts, us, "sine", TableInterpolation::cubic);
    double e = 0.0;
    for (int i = 1; i + 2 < n; ++i) {  // interior pieces: full four-row stencils
      const double x = 0.5 * (ts[i] + ts[i + 1]);
      e = std::max(e, std::abs(at(s, x).x() - std::sin(3 * x)));
    }
    return e;
  };
  EXPECT_NEAR(largest_error(40) / largest_error(80), 16.0, 1.6);
}

// Two times an ulp apart (a switch time computed twice) are one time, a jump: the cubic of the arc after it
// is the one of the same table written with a repeated time, and stays between the rows' values. Kept apart,
// the piece of one ulp would put the cubic through four rows with weights of order 1/ulp.
TEST(TabulatedTorque, TimesThatDifferByRoundingOnlyAreAJump) {
  const double t1 = 1.0, t1_next = std::nextafter(t1, 2.0);
  const std::vector<Vec3> u{Vec3(1, 0, 0), Vec3(1, 0, 0), Vec3(-1, 0, 0), Vec3(-1, 0, 0), Vec3(0, 0, 0)};
  const TabulatedTorque rounded({0.0, t1, t1_next, 2.0, 3.0}, u, "rounded", TableInterpolation::cubic);
  const TabulatedTorque jump({0.0, t1, t1, 2.0, 3.0}, u, "jump", TableInterpolation::cubic);
  EXPECT_EQ(rounded.time(), jump.time());
  EXPECT_EQ(rounded.breakpoints(), (std::vector<double>{0.0, 1.0, 2.0, 3.0}));
  for (const double x : {0.5, 1.0, 1.2, 1.7, 2.5}) {
    EXPECT_EQ(at(rounded, x), at(jump, x)) << x;
    EXPECT_LE(at(rounded, x).norm(), 1.5) << x;
  }
  // Rows at a larger distance stay apart: 1e-9 of the span is a piece, not rounding.
  const TabulatedTorque apart({0.0, t1, t1 + 1e-9, 2.0, 3.0}, u, "apart");
  EXPECT_EQ(apart.breakpoints().size(), 5U);
  // A third row within rounding of a jump is a third row at one time.
  try {
    TabulatedTorque({0.0, t1, t1, t1_next, 3.0}, u, "table.csv");
    ADD_FAILURE() << "a third row an ulp after a jump accepted";
  } catch (const InvalidInput& e) {
    EXPECT_NE(std::string(e.what()).find("at most two rows"), std::string::npos) << e.what();
  }
}

TEST(TabulatedTorque, RejectsMalformedTables) {
  const auto rejects = [](std::vector<double> t, std::vector<Vec3> u, const char* what) {
    try {
      TabulatedTorque(std::move(t), std::move(u), "table.csv");
      ADD_FAILURE() << what << " accepted";
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos);
    }
  };
  const Vec3 z = Vec3::Zero();
  rejects({0.0}, {z}, "at least two rows");
  rejects({0.0, 1.0}, {z}, "one torque per time");
  rejects({0.0, 2.0, 1.0}, {z, z, z}, "ascending");
  rejects({0.0, 1.0, 1.0, 1.0, 2.0}, {z, z, z, z, z}, "at most two rows");
  rejects({0.0, 0.0, 1.0}, {z, z, z}, "starts or ends");
  rejects({0.0, std::nan(""), 1.0}, {z, z, z}, "finite");
  rejects({0.0, 1.0}, {z, Vec3(0, std::numeric_limits<double>::infinity(), 0)}, "row 2");
}

/// Replays `tau` on the sphere J = j I from rest with `method` and returns the final state at t_end.
dynamics::State replay(const std::shared_ptr<const TabulatedTorque>& tau, double j, double t_end,
                       const char* method, double dt) {
  const auto body = dynamics::RigidBody::from_principal_moments(Vec3::Constant(j));
  dynamics::IntegratorOptions opt;
  opt.dt = dt;
  opt.rtol = 1e-13;
  opt.atol = 1e-13;
  auto integrator = dynamics::make_integrator(method, body, tau, opt);
  dynamics::SimulationOptions so;
  so.t_end = t_end;
  so.sample_dt = 0.37;  // sample times unrelated to the switch
  return dynamics::simulate(body, tau, dynamics::State{}, *integrator, so).final_state;
}

TEST(TabulatedTorque, BangBangReplayReachesTheClosedFormSlewWithEveryMethod) {
  // Θ = u T² / (4 j): rest to rest about n; then at rest (τ = 0 after the table) until t_end.
  const double j = 2.0, u = 0.5, T = 3.3;
  const double theta = u * T * T / (4 * j);
  const auto tau = std::make_shared<const TabulatedTorque>(bang_bang(u, T));
  const Mat3 target = so3::exp(theta * kAxis);
  // dop853 and dopri5 at 1e-13 (the switch is a breakpoint: no step straddles it, so the error is the
  // tolerance's); rk4 with dt = 0.01 not dividing T/2 (the driver cuts the steps at the switch): ω is linear
  // in t on each piece, which RK4 integrates exactly, and the attitude's error is O(h⁴) per unit time.
  // Without the breakpoints a stage on the wrong side of the switch costs h·Δτ/(6j) ≈ 1e-3 rad/s.
  for (const auto& [method, dt, tol] :
       {std::tuple{"dop853", 0.1, 1e-11}, std::tuple{"dopri5", 0.1, 1e-10}, std::tuple{"rk4", 0.01, 1e-9}}) {
    const dynamics::State end = replay(tau, j, T + 0.5, method, dt);
    EXPECT_LT(so3::angle_between(end.R_space_body, target), tol) << method;
    EXPECT_LT(end.omega_body.norm(), tol) << method;
  }
}

TEST(TabulatedTorque, LinearPieceReplayMatchesTheCubicAngle) {
  // τ = (a + b t) n on [0, T]: ω = (a t + b t²/2)/j n, angle (a t²/2 + b t³/6)/j at T (then free drift at
  // the final ω until t_end).
  const double j = 1.5, a = 0.2, b = -0.1, T = 2.0, t_end = 2.5;
  const auto tau = std::make_shared<const TabulatedTorque>(
      std::vector<double>{0.0, T}, std::vector<Vec3>{a * kAxis, (a + b * T) * kAxis}, "ramp");
  const double w_T = (a * T + b * T * T / 2) / j;
  const double angle = (a * T * T / 2 + b * T * T * T / 6) / j + w_T * (t_end - T);
  const dynamics::State end = replay(tau, j, t_end, "dop853", 0.1);
  EXPECT_LT(so3::angle_between(end.R_space_body, so3::exp(angle * kAxis)), 1e-11);
  EXPECT_LT((end.omega_body - w_T * kAxis).norm(), 1e-12);
}

}  // namespace
}  // namespace poinsot::test
