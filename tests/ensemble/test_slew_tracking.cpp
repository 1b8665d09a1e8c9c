// Tests of the closed-loop slew replay (slew_tracking.hpp) and of slew ensembles through the runner.
//
// Tolerances: the replay is classical RK4 on a grid with a node at every switch of the control, so its
// global error is O(h⁴): on these motions (|ω| ≲ 2 rad/s, |ω̇| ≲ 2 rad/s², T ≈ 3.2 s) about 1e-12 at
// h = 1e-3 and 1e-8 at h = 1e-2 (measured by the order test below, which checks the ratio 16 of the error
// per halving). The independent oracle, DOP853 at rtol = atol = 1e-12, adds ≲ 1e-11.
#include "poinsot/ensemble/slew_tracking.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/ensemble/runner.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::ensemble {
namespace {

// The minimum-time 180° slew about x of a sphere (J = 1, |u_i| ≤ 1 N·m): the switch times and torques of
// the verified optimum that `poinsot optimize examples/optimal/sphere_slew.toml` writes to control.csv
// (examples/ensemble/sphere_slew_control.csv).
constexpr double kSwitch[] = {0.0,
                              0.4454389949447971,
                              1.1761026437813165,
                              1.621541638726129,
                              2.0669806336709238,
                              2.7976442825074437,
                              3.2430832774522544};
constexpr double kArcTorque[6][3] = {{1, -1, 1},  {1, -1, -1}, {1, 1, -1},
                                     {-1, 1, -1}, {-1, 1, 1},  {-1, -1, 1}};
constexpr double kSlewTime = kSwitch[6];

std::shared_ptr<const dynamics::TabulatedTorque> sphere_plan() {
  std::vector<double> t;
  std::vector<Vec3> u;
  for (int a = 0; a < 6; ++a) {
    for (double ta : {kSwitch[a], kSwitch[a + 1]}) {
      t.push_back(ta);
      u.emplace_back(kArcTorque[a][0], kArcTorque[a][1], kArcTorque[a][2]);
    }
  }
  return std::make_shared<dynamics::TabulatedTorque>(t, u, "sphere plan");
}

SlewSpec sphere_spec(double dt, double kp = 4.0, double kd = 4.0) {
  SlewSpec s;
  s.control = sphere_plan();
  s.target_attitude = so3::rotation_from_axis_angle(Vec3::UnitX(), M_PI);
  s.kp = kp;
  s.kd = kd;
  s.pointing_requirement = 0.01;
  s.t_end = kSlewTime;
  s.dt = dt;
  return s;
}

/// A body that is not a sphere, with axes off the body frame (so J is full), for the replay against DOP853.
Mat3 full_inertia() {
  const Mat3 P = so3::rotation_from_axis_angle(Vec3(1.0, 2.0, -0.5).normalized(), 0.3);
  return P * Vec3(1.0, 1.3, 0.8).asDiagonal() * P.transpose();
}

/// The open-loop replay of the plan by the dynamics layer's DOP853 (the driver ends a step at every row).
dynamics::State dop853_replay(const Mat3& J, const dynamics::State& initial, double t_end) {
  const dynamics::RigidBody body = dynamics::RigidBody::from_inertia(J);
  const auto plan = sphere_plan();
  dynamics::Dop853Integrator dop(body, plan, {.dt = 0.01, .rtol = 1e-12, .atol = 1e-12});
  return dynamics::simulate(body, plan, initial, dop,
                            {.t_end = t_end, .sample_dt = t_end, .locate_flips = false})
      .final_state;
}

TEST(SlewTracking, NominalBodyReproducesTheIndependentOpenLoopReplay) {
  const Mat3 J = full_inertia();
  const dynamics::State start;  // at rest at the identity, the plan's start
  const SlewTracking tracking(sphere_spec(1e-3), J, start);
  const SlewOutcome nominal = tracking.run(J, start);
  const dynamics::State replay = dop853_replay(J, start, kSlewTime);
  // The plan is the sphere's, so this body misses the target (by about a radian): the closed loop on the
  // nominal body is the open-loop replay, the feedback ~0 (its reference is itself on half steps).
  EXPECT_LT(so3::angle_between(nominal.final_state.R_space_body, replay.R_space_body), 1e-10);
  EXPECT_LT((nominal.final_state.omega_body - replay.omega_body).norm(), 1e-10);
  const double replay_error = so3::angle_between(replay.R_space_body, tracking.spec().target_attitude);
  EXPECT_GT(replay_error, 0.1);
  EXPECT_NEAR(nominal.pointing_error, replay_error, 1e-10);
  EXPECT_LT(nominal.peak_feedback_torque, 8.0 * 1e-10);  // (kp + kd) × the RK4 error
  // The wheel momentum from rest: h_w = −J ω, its peak at least that at the replay's end.
  EXPECT_GE(nominal.peak_wheel_momentum, (J * replay.omega_body).norm() - 1e-10);
}

TEST(SlewTracking, SphereOnItsPlanMeetsTheTargetOfTheVerifiedOptimum) {
  const dynamics::State start;
  const SlewTracking tracking(sphere_spec(1e-3), Mat3::Identity(), start);
  const SlewOutcome r = tracking.run(Mat3::Identity(), start);
  // The optimum reaches its target to its verification's DOP853 replay (8e-12 rad); RK4 adds ≲ 1e-12.
  EXPECT_LT(r.pointing_error, 1e-10);
  EXPECT_LT(r.rate_error, 1e-10);
  EXPECT_TRUE(r.meets_requirement);
  EXPECT_NEAR(r.peak_torque, std::sqrt(3.0), 1e-9);  // every arc has |u_i| = 1 on all three axes
  EXPECT_LT(r.peak_feedback_torque, 1e-9);
  // From rest the wheels hold −J ω = −ω; its peak against the DOP853 replay sampled on a fine grid.
  const auto plan = sphere_plan();
  const dynamics::RigidBody sphere = dynamics::RigidBody::from_principal_moments(Vec3::Ones());
  dynamics::Dop853Integrator dop(sphere, plan, {.dt = 0.01, .rtol = 1e-12, .atol = 1e-12});
  double peak = 0.0;
  dynamics::simulate(sphere, plan, start, dop, {.t_end = kSlewTime, .sample_dt = 1e-4, .locate_flips = false},
                     [&](const dynamics::State& x) {
                       peak = std::max(peak, x.omega_body.norm());
                       return true;
                     });
  // |ω| has corners at the switches (ω̇ jumps), where its maximum can lie: the replay at each switch too.
  for (int a = 1; a <= 6; ++a) {
    dynamics::Dop853Integrator to_switch(sphere, plan, {.dt = 0.01, .rtol = 1e-12, .atol = 1e-12});
    const dynamics::State x =
        dynamics::simulate(sphere, plan, start, to_switch,
                           {.t_end = kSwitch[a], .sample_dt = kSwitch[a], .locate_flips = false})
            .final_state;
    peak = std::max(peak, x.omega_body.norm());
  }
  // The replay's maximum over the switches and a 1e-4 grid against the replay's over its 1e-3 grid (with
  // the switches): an interior maximum is flat, missed by O((5e-4)² |d²|ω|/dt²|) ≲ 1e-6.
  EXPECT_NEAR(r.peak_wheel_momentum, peak, 1e-6);
}

// A sphere with no plan (u_ref = 0), the reference at rest at the identity, started θ₀ about a fixed axis n
// with rate θ̇₀ about n: the motion stays a rotation about n, with e_θ = 2 sin(θ/2) n (θ ∈ (−π, π)), so
//     θ̈ = sat(−2 K_p sin(θ/2) − K_d θ̇),
// a scalar equation integrated here by RK4 on a fine step: an independent check of the law's sign, its
// factor 2, the gains' units and the norm saturation.
double pendulum_angle(double theta, double rate, double kp, double kd, double umax, double t_end,
                      double* peak_rate_change) {
  const auto acc = [&](double th, double w) {
    const double u = -2.0 * kp * std::sin(0.5 * th) - kd * w;
    return std::clamp(u, -umax, umax);
  };
  const int n = 200000;
  const double h = t_end / n, w0 = rate;
  *peak_rate_change = 0.0;
  for (int i = 0; i < n; ++i) {
    const double k1 = rate, l1 = acc(theta, rate);
    const double k2 = rate + 0.5 * h * l1, l2 = acc(theta + 0.5 * h * k1, rate + 0.5 * h * l1);
    const double k3 = rate + 0.5 * h * l2, l3 = acc(theta + 0.5 * h * k2, rate + 0.5 * h * l2);
    const double k4 = rate + h * l3, l4 = acc(theta + h * k3, rate + h * l3);
    theta += h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
    rate += h / 6.0 * (l1 + 2 * l2 + 2 * l3 + l4);
    *peak_rate_change = std::max(*peak_rate_change, std::abs(rate - w0));
  }
  return theta;
}

TEST(SlewTracking, FeedbackLawMatchesTheScalarPendulumEquation) {
  const auto zero = std::make_shared<dynamics::TabulatedTorque>(
      std::vector<double>{0.0, 4.0}, std::vector<Vec3>{Vec3::Zero(), Vec3::Zero()}, "no plan");
  const Vec3 n = Vec3(0.3, -0.4, 0.5).normalized();
  for (const double umax : {0.0, 0.5}) {  // 0: no limit; 0.5 N·m on the norm (active at the start)
    SlewSpec s;
    s.control = zero;
    s.kp = 2.0;
    s.kd = 1.5;
    s.limit = umax > 0.0 ? SlewTorqueLimit::norm : SlewTorqueLimit::none;
    s.torque_max = Vec3::Constant(umax);
    s.pointing_requirement = 0.1;
    s.t_end = 4.0;
    s.dt = 1e-3;
    const SlewTracking tracking(s, Mat3::Identity(), dynamics::State{});
    dynamics::State start;
    start.R_space_body = so3::rotation_from_axis_angle(n, 1.2);
    start.omega_body = 0.7 * n;
    const SlewOutcome r = tracking.run(Mat3::Identity(), start);
    double peak_dw = 0.0;
    const double theta = pendulum_angle(1.2, 0.7, s.kp, s.kd, umax > 0.0 ? umax : 1e300, s.t_end, &peak_dw);
    // Unsaturated: both RK4, O(h⁴) at h = 1e-3 (≲ 1e-12). Saturated: the field has a kink where the limit
    // engages or releases, across which an RK4 step is only O(h²) accurate: (1e-3)² (2 K_p + K_d) ≈ 5e-6
    // per crossing at most (3.3e-8 measured).
    EXPECT_NEAR(r.pointing_error, std::abs(theta), umax > 0.0 ? 1e-6 : 1e-10) << "umax " << umax;
    // Rotation about n from ω₀ = θ̇₀ n: L(0) = θ̇₀ n is along the axis, h_w = (θ̇₀ − θ̇) n; the peaks over the
    // 1e-3 grid and the 2e-5 grid differ by O(h²).
    EXPECT_NEAR(r.peak_wheel_momentum, peak_dw, 1e-5) << "umax " << umax;
    if (umax > 0.0) {
      EXPECT_NEAR(r.peak_torque, umax, 1e-12);
    }
    // Without the feedback the sphere keeps spinning: far from the target.
    SlewSpec open = s;
    open.kp = open.kd = 0.0;
    EXPECT_GT(
        SlewTracking(open, Mat3::Identity(), dynamics::State{}).run(Mat3::Identity(), start).pointing_error,
        1.0);
  }
}

// The closed loop of a dispersed body converges at RK4's fourth order: the differences between steps h, h/2
// and h/4 fall by 16 per halving (the reference too is recomputed on each grid).
TEST(SlewTracking, ClosedLoopConvergesAtFourthOrder) {
  const Mat3 J = full_inertia();
  dynamics::State start;
  start.R_space_body = so3::rotation_from_axis_angle(Vec3(0.2, 1.0, 0.1).normalized(), 0.05);
  start.omega_body = Vec3(0.01, -0.02, 0.015);
  std::vector<SlewOutcome> r;
  for (double dt : {0.04, 0.02, 0.01, 0.005})
    r.push_back(SlewTracking(sphere_spec(dt), Mat3::Identity(), dynamics::State{}).run(J, start));
  std::vector<double> d;
  for (std::size_t i = 0; i + 1 < r.size(); ++i)
    d.push_back((r[i].final_state.omega_body - r[i + 1].final_state.omega_body).norm() +
                so3::angle_between(r[i].final_state.R_space_body, r[i + 1].final_state.R_space_body));
  EXPECT_NEAR(d[0] / d[1], 16.0, 3.0);
  EXPECT_NEAR(d[1] / d[2], 16.0, 2.0);
  EXPECT_LT(d[2], 1e-7);
}

// The plan's own rows as the reference (a trajectory.csv): the rows here are the plan's motion on the sphere
// (the plan-replay reference at every m-th step of a 1e-4 grid, both sides of each switch), so the nominal
// body tracks them with a feedback that is the Hermite interpolation's error times the gains, falling by 16
// per halving of the row spacing, and ends where the plan ends.
ReferenceRows plan_rows(int every) {
  const SlewTracking fine(sphere_spec(1e-4, 0.0, 0.0), Mat3::Identity(), dynamics::State{});
  const auto plan = sphere_plan();
  ReferenceRows r;
  for (std::int64_t k = 0; k <= fine.step_count(); ++k) {
    const double t = fine.step_time(k);
    const bool at_switch = std::find(std::begin(kSwitch), std::end(kSwitch), t) != std::end(kSwitch);
    if (!at_switch && k % every != 0) continue;
    for (int side = 0; side < (at_switch && k > 0 && k < fine.step_count() ? 2 : 1); ++side) {
      // The torque just before a switch (side 0) and just after (side 1).
      int arc = 0;
      while (arc < 5 && (side == 0 ? kSwitch[arc + 1] < t : kSwitch[arc + 1] <= t))
        ++arc;
      r.time.push_back(t);
      r.attitude.push_back(fine.reference_attitude(k));
      r.omega.push_back(fine.reference_omega(k));
      r.torque.emplace_back(kArcTorque[arc][0], kArcTorque[arc][1], kArcTorque[arc][2]);
    }
  }
  return r;
}

TEST(SlewTracking, TheOptimizersRowsAsReferenceAreTrackedToTheirInterpolationError) {
  const dynamics::State start;
  const SlewOutcome plan =
      SlewTracking(sphere_spec(1e-3), Mat3::Identity(), start).run(Mat3::Identity(), start);
  std::vector<double> feedback;
  for (int every : {200, 100, 50}) {  // rows every 0.02, 0.01, 0.005 s
    SlewSpec s = sphere_spec(1e-3);
    s.reference = plan_rows(every);
    const SlewOutcome r = SlewTracking(s, Mat3::Identity(), start).run(Mat3::Identity(), start);
    feedback.push_back(r.peak_feedback_torque);
    EXPECT_LT(so3::angle_between(r.final_state.R_space_body, plan.final_state.R_space_body), 1e-9) << every;
  }
  EXPECT_GT(feedback[0], 1e-12) << feedback[0] << " " << feedback[1] << " " << feedback[2];
  EXPECT_NEAR(feedback[0] / feedback[1], 16.0, 5.0);
  EXPECT_NEAR(feedback[1] / feedback[2], 16.0, 5.0);
  EXPECT_LT(feedback[2], 1e-8);
  // Bad rows name the reference.
  SlewSpec s = sphere_spec(1e-3);
  s.reference = plan_rows(100);
  std::swap(s.reference.time[3], s.reference.time[4]);
  EXPECT_THROW(SlewTracking(s, Mat3::Identity(), start), InvalidInput);
  s.reference.omega.pop_back();
  EXPECT_THROW(SlewTracking(s, Mat3::Identity(), start), InvalidInput);
}

TEST(SlewTracking, RefusesBadSpecificationsNamingTheField) {
  const dynamics::State start;
  const auto refuses = [&](SlewSpec s, const char* field) {
    try {
      SlewTracking(s, Mat3::Identity(), start);
      ADD_FAILURE() << "accepted " << field;
    } catch (const InvalidInput& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  SlewSpec s = sphere_spec(1e-3);
  s.kp = -1.0;
  refuses(s, "kp");
  s = sphere_spec(1e-3);
  s.kd = std::nan("");
  refuses(s, "kd");
  s = sphere_spec(1e-3);
  s.limit = SlewTorqueLimit::per_axis;
  s.torque_max = Vec3(1.0, 0.0, 1.0);
  refuses(s, "torque_max");
  s = sphere_spec(1e-3);
  s.pointing_requirement = -0.1;
  refuses(s, "pointing_requirement");
  s = sphere_spec(0.0);
  refuses(s, "dt");
  s = sphere_spec(1e-12);
  refuses(s, "steps");
  s = sphere_spec(1e-3);
  s.control = nullptr;
  refuses(s, "control");
}

Sampler dispersed_sphere(TorqueKind torque = TorqueKind::none) {
  Nominal n;
  n.torque = torque;
  n.torque_value = torque == TorqueKind::none ? Vec3::Zero() : Vec3(0.001, 0.0, 0.0);
  Dispersions d;
  d.moments = {Law::truncated_normal, 0.05, true};
  d.axes = {RotationLaw::cone, 0.0175};
  d.attitude = {RotationLaw::cone, 0.0087};
  d.omega = {Law::normal, 0.001, false};
  return Sampler(n, d, 11);
}

EnsembleOptions slew_options(std::uint64_t samples, unsigned threads, double kp = 4.0, double kd = 4.0) {
  SlewSpec s = sphere_spec(0.01, kp, kd);
  s.limit = SlewTorqueLimit::per_axis;
  s.torque_max = Vec3::Constant(1.2);
  EnsembleOptions o;
  o.samples = samples;
  o.threads = threads;
  o.t_end = s.t_end;
  o.dt = s.dt;
  o.slew = std::make_shared<const SlewTracking>(s, Mat3::Identity(), dynamics::State{});
  return o;
}

TEST(SlewEnsemble, BitIdenticalForAnyThreadsAndTheFeedbackHelps) {
  // Three blocks (the last partial), so that three threads each take one.
  const std::uint64_t n = 2100;
  const EnsembleResult ref = run_ensemble(dispersed_sphere(), slew_options(n, 1));
  EXPECT_EQ(ref.completed, n);
  // A node at each of the 5 switches: ⌈Δ/0.01⌉ steps on each of the 6 arcs.
  std::int64_t steps = 0;
  for (int a = 0; a < 6; ++a)
    steps += static_cast<std::int64_t>(std::ceil((kSwitch[a + 1] - kSwitch[a]) / 0.01));
  EXPECT_EQ(ref.body_steps, static_cast<std::int64_t>(n) * steps);
  EXPECT_EQ(ref.path, "closed-loop slew, scalar rk4");
  for (unsigned threads : {2u, 3u}) {
    EnsembleOptions o = slew_options(n, threads);
    o.keep_rows = threads == 2;
    const EnsembleResult r = run_ensemble(dispersed_sphere(), o);
    for (int q = 0; q < kOutputCount; ++q) {
      const RunningStats &a = r.stats[q], &b = ref.stats[q];
      EXPECT_TRUE(a.count == b.count && a.nan_count == b.nan_count &&
                  std::memcmp(&a.mean, &b.mean, sizeof(double)) == 0 &&
                  std::memcmp(&a.m2, &b.m2, sizeof(double)) == 0 && a.min == b.min && a.max == b.max)
          << kOutputNames[q] << " threads " << threads;
    }
    for (std::size_t i = 0; i < r.rows.size(); ++i)
      ASSERT_EQ(std::memcmp(r.rows[i].out.data(), ref.rows[i].out.data(), sizeof(r.rows[i].out)), 0) << i;
  }
  // The nominal row: the plan's verified end, and no feedback.
  EXPECT_LT(ref.nominal.out[pointing_error], 1e-7);
  EXPECT_LT(ref.nominal.out[peak_feedback_torque], 1e-6);
  EXPECT_EQ(ref.nominal.out[meets_requirement], 1.0);
  // Every slew output defined on every sample; the free-body outputs are not.
  for (Output q : {pointing_error, rate_error, peak_torque, peak_feedback_torque, peak_wheel_momentum,
                   meets_requirement})
    EXPECT_EQ(ref.stats[q].nan_count, 0) << kOutputNames[q];
  EXPECT_EQ(ref.stats[energy_error].nan_count, static_cast<std::int64_t>(n));
  // Per-axis limit 1.2 N·m: the norm never above 1.2 √3.
  EXPECT_LE(ref.stats[peak_torque].max, 1.2 * std::sqrt(3.0) + 1e-12);
  // The same dispersed bodies open loop miss the target by far more than with the feedback.
  const EnsembleResult open = run_ensemble(dispersed_sphere(), slew_options(n, 2, 0.0, 0.0));
  EXPECT_GT(open.stats[pointing_error].mean, 5.0 * ref.stats[pointing_error].mean);
  EXPECT_GT(ref.stats[meets_requirement].mean, open.stats[meets_requirement].mean);
}

TEST(SlewEnsemble, RefusesATorqueBesideTheSlew) {
  EXPECT_THROW(run_ensemble(dispersed_sphere(TorqueKind::body), slew_options(10, 1)), InvalidInput);
}

}  // namespace
}  // namespace poinsot::ensemble
