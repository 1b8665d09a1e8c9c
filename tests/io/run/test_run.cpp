#include "poinsot/io/run/run.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot_test.hpp"

namespace poinsot::io {
namespace {

namespace fs = std::filesystem;

fs::path run_temp_dir(const std::string& name) {
  const auto d = ::poinsot::test::temp_path("poinsot_io_run_" + name);
  fs::remove_all(d);
  return d;
}

long long count_lines(const fs::path& p) {
  std::ifstream in(p);
  return std::count(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>(), '\n');
}

TEST(Run, RacketFlipsAtTheClosedFormIntervalWithAnIndependentIntegrator) {
  // dop853 at rtol 1e-12 finds the flips by root finding on its dense output; the closed form 2K(k)/ω_p comes
  // from the elliptic modulus (dynamics layer). Their agreement is limited by the integrator's tolerance over
  // ~7 flips: 1e-12 per unit time over 20 s, well inside 1e-8.
  Scenario sc = parse_scenario(R"(
[body]
principal_moments = [0.00121, 0.01638, 0.01748]
[initial]
omega_body = [0.05, 6.2832, 0.05]
[integrator]
method = "dop853"
rtol = 1e-12
atol = 1e-14
dt = 0.01
[output]
t_end = 20
sample_dt = 0.01
)");
  const auto dir = run_temp_dir("racket");
  RunOptions o;
  o.out_dir = dir.string();
  const RunSummary s = run_scenario(sc, o);
  ASSERT_TRUE(s.flip_interval_theory);
  ASSERT_GE(s.result.flip_times.size(), 5u);
  const auto& f = s.result.flip_times;
  for (std::size_t i = 1; i < f.size(); ++i)
    EXPECT_NEAR(f[i] - f[i - 1], *s.flip_interval_theory, 1e-8);
  EXPECT_NEAR(*s.period_theory, 2.0 * *s.flip_interval_theory, 1e-12 * *s.period_theory);
  EXPECT_EQ(s.symmetry, "asymmetric");
  EXPECT_EQ(s.samples, 2001);
  EXPECT_EQ(count_lines(dir / "trajectory.csv"), 2 + s.samples);
  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["status"], "completed");
  EXPECT_EQ(j["events"]["flip_times"].size(), f.size());
  EXPECT_EQ(j["final"]["t"], 20.0);
}

TEST(Run, FreeSymmetricTopPrecessesAtLOverI1) {
  // Free axisymmetric body J = diag(A, A, C): the figure axis turns about L at |L|/A exactly (Euler). With
  // the exact method only the unwrapping sum's round-off remains.
  Scenario sc = parse_scenario(R"(
[body]
principal_moments = [2.0, 2.0, 3.0]
[initial]
omega_body = [0.3, 0.0, 1.0]
[integrator]
method = "exact"
[output]
t_end = 10
sample_dt = 0.01
)");
  const RunSummary s = run_scenario(sc, {});
  ASSERT_TRUE(s.top);
  EXPECT_EQ(s.top->kind, dynamics::TopKind::free_symmetric);
  const double L = std::hypot(2.0 * 0.3, 3.0 * 1.0);
  ASSERT_TRUE(s.top->precession_rate_mean);
  EXPECT_NEAR(*s.top->precession_rate_mean, L / 2.0, 1e-10);
  EXPECT_NEAR(*s.top->precession_rate_theory, L / 2.0, 1e-15);
  EXPECT_FALSE(s.top->nutation_frequency);  // constant tilt: no nutation
  EXPECT_FALSE(s.flip_interval_theory);
  ASSERT_TRUE(s.lambda);
  EXPECT_TRUE(s.lambda->closed_form);  // the paper's axisymmetric closed form applies
}

TEST(Run, FastHeavyTopMatchesTheNotesFormulas) {
  // Fast top: A = 0.002 + m l² = 0.0045 kg·m² about the pivot, C = 0.004 kg·m², M g l = 0.4905 J, ω3 = 200
  // rad/s. ε = A M g l/(C ω3)² = 3.4e-3: the fast-top precession M g l/(C ω3) and nutation C ω3/A hold to
  // O(ε), and the mean over 2 s of a precession that nutates at 178 rad/s is off by at most ~1/(ν T) ≈ 0.3 %.
  // Tolerance 2 %.
  Scenario sc = parse_scenario(R"(
[body]
principal_moments = [0.002, 0.002, 0.004]
mass = 1.0
pivot_to_com = [0, 0, 0.05]
[initial]
omega_body = [0, 0, 200]
orientation = { axis_angle = { axis = [1, 0, 0], angle = 0.3 } }
[torque]
type = "gravity"
g = [0, 0, -9.81]
[integrator]
method = "dop853"
rtol = 1e-10
dt = 1e-3
[output]
t_end = 2
sample_dt = 5e-4
)");
  const RunSummary s = run_scenario(sc, {});
  ASSERT_TRUE(s.top);
  EXPECT_EQ(s.top->kind, dynamics::TopKind::heavy);
  const double fast = 0.4905 / (0.004 * 200.0);
  EXPECT_NEAR(*s.top->precession_rate_theory, fast, 1e-12);
  ASSERT_TRUE(s.top->precession_rate_mean);
  EXPECT_NEAR(*s.top->precession_rate_mean, fast, 0.02 * fast);
  ASSERT_TRUE(s.top->nutation_frequency);
  EXPECT_NEAR(*s.top->nutation_frequency, 0.004 * 200.0 / 0.0045, 0.02 * 0.8 / 0.0045);
  // Against the exact heavy-top theory (Goldstein §5.7, dynamics/top_theory.hpp): the nutation frequency is
  // measured from ~60 minima located to O(h²) of the sample interval (1e-6 relative here); the mean
  // precession over 2 s includes a partial nutation cycle, whose wobble in φ (amplitude ~ Ω̄/ν) biases the
  // mean by at most ~Ω̄/(ν² T)/Ω̄·ν = 1/(ν T) ≈ 3e-3 of it.
  ASSERT_TRUE(s.top->precession_rate_exact);
  EXPECT_NEAR(*s.top->precession_rate_mean, *s.top->precession_rate_exact, 3e-3 * fast);
  ASSERT_TRUE(s.top->nutation_frequency_theory);
  EXPECT_NEAR(*s.top->nutation_frequency, *s.top->nutation_frequency_theory,
              1e-4 * *s.top->nutation_frequency_theory);
  EXPECT_NEAR(s.top->theta_max, *s.top->theta_max_theory, 1e-4);
  EXPECT_LT(s.result.errors.energy_rel_max, 1e-8);
}

TEST(Run, StopRequestLeavesCompleteFilesMarkedInterrupted) {
  Scenario sc = parse_scenario(R"(
[body]
principal_moments = [1, 2, 3]
[initial]
omega_body = [0.1, 2, 0.1]
[integrator]
method = "rk4"
dt = 1e-3
[output]
t_end = 100
sample_dt = 0.01
)");
  const auto dir = run_temp_dir("stop");
  RunOptions o;
  o.out_dir = dir.string();
  long long seen = 0;
  o.stop_requested = [&seen] { return ++seen >= 10; };
  const RunSummary s = run_scenario(sc, o);
  EXPECT_TRUE(s.result.interrupted);
  EXPECT_EQ(s.samples, 10);
  EXPECT_EQ(count_lines(dir / "trajectory.csv"), 12);
  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["status"], "interrupted");
  EXPECT_LT(j["final"]["t"].get<double>(), 1.0);
}

TEST(Run, UnwritableOutputIsRefusedBeforeSimulating) {
  const auto dir = run_temp_dir("unwritable");
  fs::create_directories(dir);
  std::ofstream(dir / "a_file") << "x";
  Scenario sc = parse_scenario(
      "[body]\nprincipal_moments = [1, 2, 3]\n[initial]\nomega_body = [1, 1, 1]\n"
      "[output]\nt_end = 1\n");
  RunOptions o;
  o.out_dir = (dir / "a_file" / "run").string();
  bool sampled = false;
  o.on_sample = [&sampled](double) { sampled = true; };
  EXPECT_THROW(run_scenario(sc, o), InvalidInput);
  EXPECT_FALSE(sampled);
  EXPECT_THROW(prepare_output_dir((dir / "a_file").string()), InvalidInput);
}

TEST(Run, SymmetryClasses) {
  EXPECT_EQ(symmetry_class(Vec3(1, 2, 3)), "asymmetric");
  EXPECT_EQ(symmetry_class(Vec3(1, 1, 2)), "oblate");
  EXPECT_EQ(symmetry_class(Vec3(1, 2, 2)), "prolate");
  EXPECT_EQ(symmetry_class(Vec3(2, 2, 2)), "spherical");
}

}  // namespace
}  // namespace poinsot::io
