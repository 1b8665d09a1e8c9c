// Tests of the heavy-top outputs of the runner (precession_rate, nutation_frequency, nutation_amplitude)
// against the closed form of the symmetric heavy top (dynamics/top_theory.hpp: the roots of the cubic and
// elliptic integrals; an independent formulation) of each sample, whose mass is dispersed.
#include <cmath>
#include <cstring>

#include <gtest/gtest.h>

#include "poinsot/dynamics/top_theory.hpp"
#include "poinsot/ensemble/runner.hpp"
#include "poinsot/so3/axis_angle.hpp"

namespace poinsot::ensemble {
namespace {

const Vec3 kGravity(0.0, 0.0, -9.81);

Sampler top_sampler(double spin) {
  Nominal n;
  n.moments = Vec3(0.0020, 0.0020, 0.0035);  // about the centre of mass, symmetric about z
  n.mass = 0.5;
  n.pivot_to_com = Vec3(0.0, 0.0, 0.04);
  n.has_pivot = true;
  n.omega_body = Vec3(0.0, 0.0, spin);
  n.R = so3::rotation_from_axis_angle(Vec3::UnitX(), 0.3);
  n.torque = TorqueKind::gravity;
  n.torque_value = kGravity;
  Dispersions d;
  d.mass = {Law::normal, 0.05, true};  // the top stays symmetric about its axis: the closed form applies
  return Sampler(n, d, 5);
}

TEST(RunnerTops, PrecessionAndNutationMatchTheClosedFormOfEachSample) {
  EnsembleOptions o;
  o.samples = 6;
  o.method = "dlm";
  o.t_end = 1.0;
  o.dt = 2.5e-4;
  const Sampler sampler = top_sampler(60.0);
  const EnsembleResult r = run_ensemble(sampler, o);
  ASSERT_EQ(r.rows.size(), 6u);
  for (const SampleRow& row : r.rows) {
    const Sample s = sampler.draw(row.index);
    const dynamics::RigidBody body = s.body();
    const dynamics::HeavyTop ht = dynamics::heavy_top_from(body, kGravity);
    const dynamics::TopInitialConditions ic = dynamics::top_initial_conditions(body, s.initial, kGravity);
    const dynamics::TopMotion m = dynamics::top_motion(ht, ic.theta, ic.theta_dot, ic.phi_dot, ic.omega3);
    // The mean rate covers whole nutation periods (exact up to the method's error) and a fraction of one, in
    // which φ − Ω̄t strays by less than one period's precession Ω̄T: |error| ≤ Ω̄T/t_end = Ω̄/N.
    const double periods = o.t_end / m.nutation_period;
    ASSERT_GT(periods, 10.0);
    EXPECT_NEAR(row.out[precession_rate], m.mean_precession_rate, std::abs(m.mean_precession_rate) / periods);
    // The minima of θ located by the parabola through three samples, and the method's phase error (dlm,
    // O(h²), (ω₃h)² = 2e-4): measured 1.5e-5 relative.
    EXPECT_NEAR(row.out[nutation_frequency], m.nutation_frequency, 1e-4 * m.nutation_frequency);
    // θ_max − θ_min from the samples: they miss the extremes by O((ω_nut h)²/8) = 4e-5 relative; measured
    // 1e-4 with the method's error.
    EXPECT_NEAR(row.out[nutation_amplitude], m.theta_max - m.theta_min, 1e-3 * (m.theta_max - m.theta_min));
  }
}

TEST(RunnerTops, OutputsAreNaNForOtherBodiesAndTheSameForAnyThreads) {
  EnsembleOptions o;
  o.samples = 4;
  o.method = "rk4";
  o.t_end = 0.1;
  o.dt = 1e-3;
  const EnsembleResult one = run_ensemble(top_sampler(60.0), o);
  o.threads = 2;
  const EnsembleResult two = run_ensemble(top_sampler(60.0), o);
  for (std::size_t i = 0; i < one.rows.size(); ++i)
    for (Output q : {precession_rate, nutation_frequency, nutation_amplitude})
      EXPECT_EQ(std::memcmp(&one.rows[i].out[q], &two.rows[i].out[q], sizeof(double)), 0);
  // A free body is no top.
  Nominal free;
  free.moments = Vec3(1.0, 2.0, 3.0);
  free.omega_body = Vec3(0.1, 1.0, 0.1);
  const EnsembleResult f = run_ensemble(Sampler(free, Dispersions{}, 1), o);
  for (Output q : {precession_rate, nutation_frequency, nutation_amplitude})
    EXPECT_TRUE(std::isnan(f.rows[0].out[q]));
}

}  // namespace
}  // namespace poinsot::ensemble
