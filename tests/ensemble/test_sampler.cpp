#include "poinsot/ensemble/sampler.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "ks.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/inertia/validity.hpp"
#include "poinsot/so3/distance.hpp"
#include "poinsot_test.hpp"

namespace poinsot::ensemble {
namespace {

Nominal racket() {
  Nominal n;
  n.moments = Vec3(1.0, 2.0, 2.5);
  n.omega_body = Vec3(0.01, 3.0, 0.0);
  return n;
}

TEST(Sampler, SamplesArePureFunctionsOfSeedAndIndex) {
  Dispersions d;
  d.moments = {Law::normal, 0.02, true};
  d.axes = {RotationLaw::cone, 0.03};
  d.omega = {Law::uniform, 0.1, false};
  d.attitude = {RotationLaw::normal, 0.01};
  const Sampler s(racket(), d, 42);
  const Sample a = s.draw(777);
  s.draw(3);  // other samples in between change nothing
  const Sample b = Sampler(racket(), d, 42).draw(777);
  EXPECT_EQ(a.moments, b.moments);
  EXPECT_EQ(a.axes, b.axes);
  EXPECT_EQ(a.initial.omega_body, b.initial.omega_body);
  EXPECT_EQ(a.initial.R_space_body, b.initial.R_space_body);
  EXPECT_NE(a.moments, s.draw(778).moments);
  // Adding a dispersion of another quantity leaves the moments' draws alone (separate streams).
  Dispersions d2 = d;
  d2.torque = {};
  d2.omega = {Law::normal, 0.5, false};
  EXPECT_EQ(Sampler(racket(), d2, 42).draw(777).moments, a.moments);
}

TEST(Sampler, MomentsAndAxesFollowTheRequestedLaws) {
  Dispersions d;
  d.moments = {Law::normal, 0.02, true};
  d.axes = {RotationLaw::cone, 2.0 * std::numbers::pi / 180};
  const Nominal n = racket();
  const Sampler s(n, d, 2024);
  const std::size_t N = 4000;
  std::vector<std::vector<double>> z(3);
  std::vector<double> angle;
  for (std::size_t i = 0; i < N; ++i) {
    const Sample x = s.draw(i);
    ASSERT_EQ(x.rejected, 0);  // ±2 % (1σ) of (1, 2, 2.5) is 25σ away from the triangle inequality
    for (int k = 0; k < 3; ++k)
      z[static_cast<std::size_t>(k)].push_back((x.moments[k] - n.moments[k]) / (0.02 * n.moments[k]));
    angle.push_back(so3::angle_between(x.axes, n.axes));
    for (int k = 0; k < 3; ++k)  // no principal axis leaves the cone
      EXPECT_LE(std::acos(std::clamp(x.axes.col(k).dot(n.axes.col(k)), -1.0, 1.0)), d.axes.angle + 1e-7);
  }
  for (const auto& zk : z)
    EXPECT_LT(test::ks_statistic(zk, test::normal_cdf), test::ks_critical_0001(N));
  const double a = d.axes.angle;
  EXPECT_LT(test::ks_statistic(angle, [&](double t) { return (t - std::sin(t)) / (a - std::sin(a)); }),
            test::ks_critical_0001(N));
}

// ±50 % dispersions: every sample is valid under both policies, and the counts agree with an independent
// count of the first draws that fail check_inertia.
TEST(Sampler, AggressiveDispersionsStayValidAndTheCountsMatch) {
  Nominal n;
  n.moments = Vec3(1.0, 1.2, 1.5);
  Dispersions d;
  d.moments = {Law::uniform, 0.5, true};
  d.axes = {RotationLaw::cone, 0.5};
  const std::size_t N = 2000;
  Dispersions dr = d;
  dr.policy = ValidityPolicy::repair;
  const Sampler reject(n, d, 9), repair(n, dr, 9);
  long long invalid_first = 0, rejected_samples = 0, repaired = 0, redraws = 0;
  for (std::size_t i = 0; i < N; ++i) {
    // Independent count: the first draw of the moments, straight from the stream, tested by check_inertia.
    SampleStream st(9, i, Stream::moments);
    Vec3 I;
    for (int k = 0; k < 3; ++k)
      I[k] = disperse(d.moments, n.moments[k], n.moments[k], st);
    invalid_first += inertia::check_inertia(Mat3(I.asDiagonal())).valid ? 0 : 1;

    const Sample a = reject.draw(i), b = repair.draw(i);
    for (const Sample* x : {&a, &b}) {
      const inertia::InertiaCheck c = inertia::check_inertia(x->inertia_com());
      EXPECT_TRUE(c.valid) << "sample " << i << ": " << c.message;
      EXPECT_GT(x->moments.minCoeff(), 0.0);
    }
    rejected_samples += a.rejected > 0 ? 1 : 0;
    redraws += a.rejected;
    repaired += b.repaired ? 1 : 0;
    EXPECT_EQ(b.rejected, 0);  // uniform ±50 % keeps every moment ≥ 0.5 I0 > 0: a repair always suffices
    if (!b.repaired) {
      EXPECT_EQ(a.moments, b.moments);  // the same first draw
    }
  }
  EXPECT_GT(invalid_first, 0);
  EXPECT_EQ(rejected_samples, invalid_first);
  EXPECT_EQ(repaired, invalid_first);
  // The fraction of invalid draws against a Monte Carlo estimate with another generator (mt19937): the
  // rejections form a geometric count with success probability 1 − p per sample, so the redraws per sample
  // average p/(1 − p); both estimates agree within 5 binomial standard deviations of the smaller sample (N =
  // 2000).
  std::mt19937_64 g(1);
  std::uniform_real_distribution<double> u(0.5, 1.5);
  const int M = 40000;
  int bad = 0;
  for (int i = 0; i < M; ++i) {
    const Vec3 I(u(g) * n.moments[0], u(g) * n.moments[1], u(g) * n.moments[2]);
    bad += inertia::check_inertia(Mat3(I.asDiagonal())).valid ? 0 : 1;
  }
  const double p = static_cast<double>(bad) / M;
  const double p_first = static_cast<double>(invalid_first) / N;
  EXPECT_NEAR(p_first, p, 5.0 * std::sqrt(p * (1 - p) / N));
  EXPECT_NEAR(static_cast<double>(redraws) / N, p / (1 - p), 5.0 * std::sqrt(p / N) / (1 - p));
}

TEST(Sampler, NormalDispersionsBeyondZeroAreRepairedOrRedrawnAndCounted) {
  Nominal n;
  n.moments = Vec3(1.0, 1.0, 1.0);
  Dispersions d;
  d.moments = {Law::normal, 0.5, true};  // 2.3 % of the moments drawn below zero
  d.policy = ValidityPolicy::repair;
  const Sampler s(n, d, 3);
  int repaired = 0, rejected = 0;
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const Sample x = s.draw(i);
    EXPECT_TRUE(usable_moments(x.moments));
    EXPECT_TRUE(inertia::check_inertia(x.inertia_com()).valid);
    repaired += x.repaired;
    rejected += x.rejected;
  }
  EXPECT_GT(repaired, 0);
  EXPECT_GT(rejected, 0);
}

TEST(Sampler, RefusesAnInvalidNominalBodyAndReportsAnExhaustedRejectLoop) {
  Nominal n;
  n.moments = Vec3(1.0, 1.0, 5.0);
  POINSOT_EXPECT_THROWS_MESSAGE(Sampler(n, Dispersions{}, 1), InvalidInput, "nominal principal moments",
                                "(1, 1, 5)", "triangle");
  // Two moments that nearly violate the triangle inequality and a huge dispersion: most draws are invalid,
  // and a cap of 2 draws is exhausted by some sample, with a message naming it.
  n.moments = Vec3(1.0, 1.0, 1.999);
  Dispersions d;
  d.moments = {Law::normal, 3.0, true};
  d.max_tries = 2;
  const Sampler s(n, d, 1);
  test::expect_has(test::message_of<InvalidInput>(
                       [&] {
                         for (std::uint64_t i = 0; i < 50; ++i)
                           s.draw(i);
                       },
                       "one of 50 draws"),
                   {"sample ", "after 2 draws", "policy reject"});
  d.max_tries = 0;
  EXPECT_THROW(Sampler(racket(), d, 1), InvalidInput);
  Dispersions neg;
  neg.omega = {Law::normal, -1.0, false};
  EXPECT_THROW(Sampler(racket(), neg, 1), InvalidInput);
}

TEST(Sampler, TopsDisperseMassAndCentreOfMass) {
  Nominal n;
  n.moments = Vec3(0.5, 0.5, 0.8);
  n.has_pivot = true;
  n.mass = 1.0;
  n.pivot_to_com = Vec3(0, 0, 0.1);
  n.torque = TorqueKind::gravity;
  n.torque_value = Vec3(0, 0, -9.81);
  Dispersions d;
  d.center_of_mass = {Law::normal, 0.01, false};
  d.mass = {Law::uniform, 0.1, true};
  const Sampler s(n, d, 5);
  const Sample x = s.draw(4);
  EXPECT_NE(x.pivot_to_com, n.pivot_to_com);
  EXPECT_NEAR(x.mass, 1.0, 0.1);
  const dynamics::RigidBody b = x.body();
  EXPECT_TRUE(b.has_pivot());
  EXPECT_EQ(b.pivot_to_com(), x.pivot_to_com);
  EXPECT_TRUE(x.torque_model(b)->is_gravity());
  Nominal free = racket();
  EXPECT_THROW(Sampler(free, d, 1), InvalidInput);  // a mass dispersion without a pivot
}

}  // namespace
}  // namespace poinsot::ensemble
