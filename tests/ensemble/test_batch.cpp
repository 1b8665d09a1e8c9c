#include "poinsot/ensemble/batch.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot_test.hpp"

namespace poinsot::ensemble {
namespace {

std::vector<Sample> draw(const Nominal& n, const Dispersions& d, int count) {
  const Sampler s(n, d, 31);
  std::vector<Sample> out;
  for (int i = 0; i < count; ++i)
    out.push_back(s.draw(static_cast<std::uint64_t>(i)));
  return out;
}

// The scalar integrator of dynamics/ on the same sample with the same steps.
dynamics::State scalar_run(std::string_view method, const Sample& s, double t_end, double dt) {
  const dynamics::RigidBody body = s.body();
  const long long n = batch_step_count(t_end, dt);
  const double h = t_end / static_cast<double>(n);
  auto integrator = dynamics::make_integrator(method, body, s.torque_model(body), {.dt = h});
  dynamics::State x = s.initial;
  for (long long i = 0; i < n; ++i)
    integrator->step(x, h);
  return x;
}

Nominal racket(TorqueKind torque) {
  Nominal n;
  n.moments = Vec3(2.0, 1.0, 3.0);  // not ascending: the body frame is not RigidBody's sorted frame
  n.omega_body = Vec3(0.02, 3.0, 0.05);
  n.R = test::random_rotation();
  n.torque = torque;
  n.torque_value = torque == TorqueKind::body    ? Vec3(0.01, -0.02, 0.03)
                   : torque == TorqueKind::space ? Vec3(-0.02, 0.01, 0.04)
                                                 : Vec3::Zero();
  return n;
}

// Bit for bit against the scalar integrators: rk4 for aligned axes (its principal-frame path), dlm always;
// free, under a torque constant in the body frame and one constant in space.
TEST(Batch, LanesEqualTheScalarIntegratorsBitForBit) {
  for (TorqueKind torque : {TorqueKind::none, TorqueKind::body, TorqueKind::space}) {
    Dispersions d;
    d.moments = {Law::normal, 0.05, true};
    d.omega = {Law::normal, 0.1, false};
    d.attitude = {RotationLaw::cone, 0.5};
    const auto aligned = draw(racket(torque), d, 37);  // 37: one full batch and a partial one
    d.axes = {RotationLaw::cone, 0.1};
    const auto misaligned = draw(racket(torque), d, 20);
    const double t_end = 1.0, dt = 0.01;
    for (const auto* set : {&aligned, &misaligned}) {
      for (const char* method : {"rk4", "dlm"}) {
        const bool bitwise = std::string_view(method) == "dlm" || set == &aligned;
        for (std::size_t first = 0; first < set->size(); first += kBatchLanes) {
          const std::size_t count = std::min<std::size_t>(kBatchLanes, set->size() - first);
          std::vector<LaneResult> r(count);
          run_batch(method, std::span(*set).subspan(first, count), t_end, dt, Simd::automatic, r);
          for (std::size_t l = 0; l < count; ++l) {
            const dynamics::State x = scalar_run(method, (*set)[first + l], t_end, dt);
            if (bitwise) {
              EXPECT_EQ(r[l].final_state.R_space_body, x.R_space_body)
                  << method << " sample " << first + l << " torque " << static_cast<int>(torque);
              EXPECT_EQ(r[l].final_state.omega_body, x.omega_body)
                  << method << " sample " << first + l << " torque " << static_cast<int>(torque);
            } else {
              // Another frame, another rounding: agreement to round-off amplified over 100 steps (1e-12),
              // far below rk4's error at this step (~1e-8).
              EXPECT_LT(test::max_abs_diff(r[l].final_state.R_space_body, x.R_space_body), 1e-12) << method;
              EXPECT_LT(test::max_abs_diff(r[l].final_state.omega_body, x.omega_body), 1e-11) << method;
            }
          }
        }
      }
    }
  }
}

TEST(Batch, SimdAndPortablePathsAndBatchCompositionGiveIdenticalResults) {
  Dispersions d;
  d.moments = {Law::uniform, 0.2, true};
  d.axes = {RotationLaw::normal, 0.05};
  d.omega = {Law::normal, 0.5, false};
  for (TorqueKind torque : {TorqueKind::body, TorqueKind::space}) {
    const auto samples = draw(racket(torque), d, kBatchLanes);
    for (const char* method : {"rk4", "dlm"}) {
      std::vector<LaneResult> a(kBatchLanes), b(kBatchLanes), c(5);
      run_batch(method, samples, 1.0, 0.01, Simd::automatic, a);
      run_batch(method, samples, 1.0, 0.01, Simd::off, b);
      run_batch(method, std::span(samples).subspan(7, 5), 1.0, 0.01, Simd::off, c);
      for (int l = 0; l < kBatchLanes; ++l) {
        const auto i = static_cast<std::size_t>(l);
        EXPECT_EQ(a[i].final_state.R_space_body, b[i].final_state.R_space_body) << method;
        EXPECT_EQ(a[i].final_state.omega_body, b[i].final_state.omega_body) << method;
        if (l >= 7 && l < 12) {
          EXPECT_EQ(a[i].final_state.R_space_body, c[i - 7].final_state.R_space_body) << method;
        }
      }
    }
  }
}

// The flip interval measured by the batched integrators is 2K(k)/ω_p of each sample (free_body_theory), to
// the methods' error: rk4 at h = 1e-3 is accurate to ~1e-10 s over a few periods, dlm (order 2) to ~1e-5 s
// (its error constant times h² ω_p² over the interval); the Hermite root adds O(h⁴).
TEST(Batch, FlipIntervalsMatchTheClosedForm) {
  Dispersions d;
  d.moments = {Law::normal, 0.02, true};
  d.omega = {Law::normal, 0.05, false};
  d.axes = {RotationLaw::cone, 0.03};
  Nominal n = racket(TorqueKind::none);
  n.omega_body = Vec3(0.05, 2.0, 0.05);
  const auto samples = draw(n, d, 16);
  for (const auto& [method, tol] : {std::pair{"rk4", 1e-7}, std::pair{"dlm", 2e-4}}) {
    std::vector<LaneResult> r(samples.size());
    run_batch(method, samples, 12.0, 1e-3, Simd::automatic, r);
    for (std::size_t l = 0; l < samples.size(); ++l) {
      const double theory =
          dynamics::free_body_theory(samples[l].body(), samples[l].initial.omega_body).flip_interval();
      ASSERT_GT(r[l].flips, 1) << method;
      EXPECT_NEAR(r[l].second_flip - r[l].first_flip, theory, tol * theory) << method << " sample " << l;
    }
  }
}

TEST(Batch, RefusesWhatItCannotRun) {
  Nominal n = racket(TorqueKind::none);
  const auto samples = draw(n, {}, 2);
  std::vector<LaneResult> r(2);
  EXPECT_THROW(run_batch("dop853", samples, 1.0, 0.1, Simd::automatic, r), InvalidInput);
  EXPECT_THROW(run_batch("rk4", samples, -1.0, 0.1, Simd::automatic, r), InvalidInput);
  EXPECT_TRUE(batchable("rk4", Sampler(racket(TorqueKind::space), {}, 1).nominal()));
  Nominal top = racket(TorqueKind::gravity);
  top.torque_value = Vec3(0.0, 0.0, -9.81);
  top.mass = 1.0;
  top.has_pivot = true;
  top.pivot_to_com = Vec3(0.0, 0.0, 0.1);
  EXPECT_FALSE(batchable("dlm", Sampler(top, {}, 1).nominal()));
  // One kind of torque per batch: body-frame and space-frame lanes together are refused.
  const std::vector<Sample> mixed = {draw(racket(TorqueKind::body), {}, 1)[0],
                                     draw(racket(TorqueKind::space), {}, 1)[0]};
  EXPECT_THROW(run_batch("dlm", mixed, 1.0, 0.1, Simd::automatic, r), InvalidInput);
}

}  // namespace
}  // namespace poinsot::ensemble
