#include "poinsot/io/run/report.hpp"

#include <gtest/gtest.h>

#include <string>

namespace poinsot::io {
namespace {

bool has(const std::string& text, const std::string& piece) {
  return text.find(piece) != std::string::npos;
}

RunSummary racket() {
  RunSummary s;
  s.scenario = "tennis_racket";
  s.source = "examples/tennis_racket.toml";
  s.method = "exact";
  s.torque = "none";
  s.symmetry = "asymmetric";
  s.principal_moments = Vec3(0.00121, 0.01638, 0.01748);
  s.result.flip_times = {1.5, 4.25, 7.0};
  s.flip_interval_theory = 2.75;
  s.period_theory = 5.5;
  s.result.steps = 4000;
  s.result.wall_time_s = 0.04;
  return s;
}

TEST(Report, FlipsStandBesideTheirClosedForm) {
  const std::string r = format_report(racket());
  EXPECT_TRUE(has(r, "flips of the intermediate axis (sign changes of L2, body frame): 3")) << r;
  EXPECT_TRUE(has(r, "at t = 1.5, 4.25, 7 s")) << r;
  EXPECT_TRUE(has(r, "measured 2.75 s (mean), theory 2K(k)/ω_p = 2.75 s, relative difference 0.0e+00")) << r;
  EXPECT_TRUE(has(r, "period of omega: theory 4K(k)/ω_p = 5.5 s")) << r;
  EXPECT_TRUE(has(r, "asymmetric, I1 < I2 < I3")) << r;
  EXPECT_TRUE(has(r, "4000 steps (0 rejected), wall time 0.040 s, 1e+05 steps/s")) << r;
}

TEST(Report, SaysWhenInterruptedOrFailed) {
  RunSummary s = racket();
  s.result.interrupted = true;
  s.result.final_state.time = 3.5;
  EXPECT_TRUE(has(format_report(s), "INTERRUPTED at t = 3.5 s"));
  s.failure = "rk4: non-finite state at t = 3.5 s";
  EXPECT_TRUE(has(format_report(s), "FAILED: rk4: non-finite state"));
}

TEST(Report, TopLinesCompareWithTheory) {
  RunSummary s = racket();
  s.symmetry = "prolate";
  s.result.flip_times.clear();
  TopEvents t;
  t.kind = dynamics::TopKind::heavy;
  t.precession_rate_mean = 0.5;
  t.precession_rate_theory = 0.5;
  t.nutation_frequency = 80.0;
  t.nutation_frequency_fast_top = 81.0;
  t.precession_rate_exact = 0.5;
  t.sleeping = true;
  s.top = t;
  const std::string r = format_report(s);
  EXPECT_TRUE(has(r, "precession about the vertical (−g): measured mean 0.5 rad/s")) << r;
  EXPECT_TRUE(has(r, "exact heavy top (Goldstein §5.7) Δφ/T_nut = 0.5 rad/s (relative difference 0.0e+00)"))
      << r;
  EXPECT_TRUE(has(r, "fast top (the notes) M g l/(I3 omega3) = 0.5 rad/s")) << r;
  EXPECT_TRUE(has(r, "measured frequency 80 rad/s")) << r;
  EXPECT_TRUE(has(r, "fast top I3 omega3/I1 = 81 rad/s (relative difference 1.2e-02)")) << r;
  EXPECT_TRUE(has(r, "sleeping-top criterion omega3² > 4 I1 M g l/I3²: holds")) << r;
}

}  // namespace
}  // namespace poinsot::io
