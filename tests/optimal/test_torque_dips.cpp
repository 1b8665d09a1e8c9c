// Dips of the direct torque: u_i leaving its bound towards 0 for a few samples and returning to the same
// bound without a switch (is_torque_dip, src/optimal/switching_structure.*), the collocation's stand-in for a
// singular arc or a pulse of the other sign shorter than its mesh resolves.
//
// The readings, on direct solutions made by hand: 201 samples over T = 2 s (every 10 ms), u1 = +ū1 and
// u3 = −ū3 throughout, u2 as given near t = 1 s and +ū2 elsewhere, ū = 1 N·m, an inertia off its principal
// frame (so that no arc is refused as of order two). A stretch inside the bound shorter than
// kShortestSingularArc of T (40 ms here) is a singular arc only with read_arc_structure's `dips`, and only
// where u2 keeps its sign from the sample before it to the sample after it; the collocation's passage through
// a switch changes sign and stays a switch. with_switch_pairs_at_dips puts a pair of switches at a dip, as
// wide as the impulse the dip lacks. Oracles: the sample times, and the trapezoidal integrals of the deficit.
//
// Then a problem whose optimum has such a pulse: the shooting reaches it only from the pair of switches.
#include "../../src/optimal/arc_structure.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <vector>

#include "../../src/optimal/switching_structure.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/verification.hpp"
#include "poinsot_test.hpp"

namespace poinsot::optimal::detail {
namespace {

using Kind = ArcEvent::Kind;
using Arc = ArcEvent::Arc;

constexpr int kSamples = 201;
constexpr double kStep = 0.01;  // s

ReorientationProblem off_principal_slew() {
  ReorientationProblem p;
  p.inertia_body << 2.0, 0.2, 0.05,  //
      0.2, 2.5, 0.1,                 //
      0.05, 0.1, 3.0;
  p.torque_max = Vec3::Ones();
  p.attitude_final = Quat(Eigen::AngleAxisd(1.0, Vec3(1.0, 2.0, 2.0).normalized()));
  return p;
}

/// The direct solution with u2 at sample k (t = k × 10 ms) from `u2` where given, +1 elsewhere.
DirectSolution direct_with_u2(const std::map<int, double>& u2) {
  DirectSolution d;
  d.nlp_solved = true;
  d.final_time = kStep * (kSamples - 1);
  for (int k = 0; k < kSamples; ++k) {
    d.time.push_back(kStep * k);
    d.attitude.push_back(Quat::Identity());
    d.omega_body.push_back(Vec3::Zero());
    const auto it = u2.find(k);
    d.torque_body.emplace_back(1.0, it == u2.end() ? 1.0 : it->second, -1.0);
  }
  return d;
}

std::vector<ArcEvent> events_of_u2(const ArcStructure& s) {
  std::vector<ArcEvent> out;
  for (const ArcEvent& e : s.events)
    if (e.axis == 1) out.push_back(e);
  return out;
}

TEST(ArcStructureDips, ADipOfThreeSamplesIsASingularArcOnlyWithDips) {
  const ReorientationProblem p = off_principal_slew();
  const DirectSolution d = direct_with_u2({{100, 0.6}, {101, 0.3}, {102, 0.7}});
  const ArcStructure without = read_arc_structure(p, d);
  ASSERT_TRUE(without.refused.empty()) << without.refused;
  EXPECT_TRUE(events_of_u2(without).empty());

  const ArcStructure with = read_arc_structure(p, d, kShortestSingularArc, 0.0, 0.0, true);
  ASSERT_TRUE(with.refused.empty()) << with.refused;
  const std::vector<ArcEvent> u2 = events_of_u2(with);
  ASSERT_EQ(u2.size(), 2u);
  EXPECT_EQ(u2[0].kind, Kind::entry);
  EXPECT_EQ(u2[0].arc, Arc::singular);
  EXPECT_DOUBLE_EQ(u2[0].time, 1.00);
  EXPECT_EQ(u2[1].kind, Kind::exit);
  EXPECT_DOUBLE_EQ(u2[1].time, 1.02);
  EXPECT_EQ(u2[1].sign_after, 1.0);
  EXPECT_EQ(with.initial_sign[1], 1.0);
}

TEST(ArcStructureDips, ADipOfOneSampleSpansTheMidpointsAroundIt) {
  const ReorientationProblem p = off_principal_slew();
  const ArcStructure s =
      read_arc_structure(p, direct_with_u2({{100, 0.8}}), kShortestSingularArc, 0.0, 0.0, true);
  ASSERT_TRUE(s.refused.empty()) << s.refused;
  const std::vector<ArcEvent> u2 = events_of_u2(s);
  ASSERT_EQ(u2.size(), 2u);
  EXPECT_EQ(u2[0].kind, Kind::entry);
  EXPECT_NEAR(u2[0].time, 0.995, 1e-15);
  EXPECT_EQ(u2[1].kind, Kind::exit);
  EXPECT_NEAR(u2[1].time, 1.005, 1e-15);
}

TEST(ArcStructureDips, ThePassageThroughASwitchStaysASwitch) {
  const ReorientationProblem p = off_principal_slew();
  std::map<int, double> u2{{100, 0.4}, {101, -0.4}};
  for (int k = 102; k < kSamples; ++k)
    u2[k] = -1.0;
  const ArcStructure s = read_arc_structure(p, direct_with_u2(u2), kShortestSingularArc, 0.0, 0.0, true);
  ASSERT_TRUE(s.refused.empty()) << s.refused;
  const std::vector<ArcEvent> events = events_of_u2(s);
  ASSERT_EQ(events.size(), 1u);
  EXPECT_EQ(events[0].kind, Kind::sign_change);
  EXPECT_NEAR(events[0].time, 1.005, 1e-15);  // the zero of the linear interpolant between 0.4 and −0.4
}

TEST(ArcStructureDips, AStretchFromTheFirstSampleIsNotADip) {
  const ReorientationProblem p = off_principal_slew();
  const ArcStructure s =
      read_arc_structure(p, direct_with_u2({{0, 0.5}, {1, 0.7}}), kShortestSingularArc, 0.0, 0.0, true);
  ASSERT_TRUE(s.refused.empty()) << s.refused;
  EXPECT_TRUE(events_of_u2(s).empty());
}

/// The switches of u2 in `sw`, ascending.
std::vector<double> switches_of_u2(const SwitchGuess& sw) {
  std::vector<double> out;
  for (std::size_t k = 0; k < sw.times.size(); ++k)
    if (sw.axes[k] == 1) out.push_back(sw.times[k]);
  std::sort(out.begin(), out.end());
  return out;
}

// A dip of one sample to 0.5 ū: the deficit ū − |u| is a triangle of height 0.5 over the 20 ms from the
// sample before to the sample after, 5e-3 N·m·s, which a pulse of −ū (a change of 2ū) makes up in 2.5 ms,
// centred on the sample.
TEST(TorqueDips, ADipGetsAPairOfSwitchesAsWideAsTheImpulseItLacks) {
  const ReorientationProblem p = off_principal_slew();
  const DirectSolution d = direct_with_u2({{100, 0.5}});
  const SwitchGuess sw = read_switch_guess(p, d);
  ASSERT_TRUE(switches_of_u2(sw).empty());
  SwitchGuess paired;
  ASSERT_TRUE(with_switch_pairs_at_dips(p, d, sw, paired));
  const std::vector<double> t = switches_of_u2(paired);
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 1.0 - 1.25e-3, 1e-14);
  EXPECT_NEAR(t[1], 1.0 + 1.25e-3, 1e-14);
  EXPECT_EQ(paired.times.size(), sw.times.size() + 2);
  EXPECT_EQ(paired.initial_sign, sw.initial_sign);
}

// Three samples, 0.6, 0.3 and 0.7 ū: deficit 0.01 × (0.4/2 + (0.4 + 0.7)/2 + (0.7 + 0.3)/2 + 0.3/2) =
// 1.4e-2 N·m·s, a pulse of 7 ms centred on the deficit's mean time (the same trapezoids, written out here).
TEST(TorqueDips, AWiderDipIsCentredOnItsDeficit) {
  const ReorientationProblem p = off_principal_slew();
  const DirectSolution d = direct_with_u2({{100, 0.6}, {101, 0.3}, {102, 0.7}});
  SwitchGuess paired;
  ASSERT_TRUE(with_switch_pairs_at_dips(p, d, read_switch_guess(p, d), paired));
  const std::vector<double> t = switches_of_u2(paired);
  ASSERT_EQ(t.size(), 2u);
  const double f[5] = {0.0, 0.4, 0.7, 0.3, 0.0};  // ū − |u| at 0.99 … 1.03 s
  double deficit = 0.0, moment = 0.0;
  for (int k = 0; k < 4; ++k) {
    const double t0 = 0.99 + 0.01 * k, t1 = t0 + 0.01;
    deficit += 0.005 * (f[k] + f[k + 1]);
    moment += 0.005 * (f[k] * t0 + f[k + 1] * t1);
  }
  EXPECT_NEAR(deficit, 1.4e-2, 1e-15);
  EXPECT_NEAR(t[1] - t[0], deficit / 2.0, 1e-14);
  EXPECT_NEAR(0.5 * (t[0] + t[1]), moment / deficit, 1e-14);
}

TEST(TorqueDips, NoPairWithoutADip) {
  const ReorientationProblem p = off_principal_slew();
  std::map<int, double> through_a_switch{{100, 0.4}, {101, -0.4}};
  for (int k = 102; k < kSamples; ++k)
    through_a_switch[k] = -1.0;
  const DirectSolution d = direct_with_u2(through_a_switch);
  SwitchGuess paired;
  EXPECT_FALSE(with_switch_pairs_at_dips(p, d, read_switch_guess(p, d), paired));
  std::map<int, double> long_stretch;  // 50 ms inside the bound: a singular arc, read as one elsewhere
  for (int k = 100; k <= 105; ++k)
    long_stretch[k] = 0.5;
  const DirectSolution e = direct_with_u2(long_stretch);
  EXPECT_FALSE(with_switch_pairs_at_dips(p, e, read_switch_guess(p, e), paired));
}

// Problem 6 of the benchmark's nonprincipal family, seed 9 (T = 4.938 s): the direct u2 leaves its bound at
// one sample only (0.85 ū2 at t = 2.7655 s, 67 intervals at mesh tolerance 1e-7), inside a bang arc of −ū2,
// and the multipliers estimated from it give σ2 falling to about 1e-6 there. The bang-bang shooting over the
// four switches read stalls (residual 1.1e-4), and so does the shooting over a singular arc of u2 at the dip
// (8.4e-4): the optimum has a pulse of +ū2 about 0.65 ms long, σ2 crossing 0 twice, which the shooting
// reaches from the pair of switches at the dip. Oracles: the verification (H constant, the control minimising
// H with no sample of the wrong sign, the DOP853 replay) and the direct method's final time, to its mesh
// error at tolerance 1e-5.
TEST(TorqueDips, APulseShorterThanTheMeshIsShotFromAPairOfSwitchesAtItsDip) {
  if (::poinsot::test::sanitized()) GTEST_SKIP() << "about 1 s in release (the direct phase)";
  ReorientationProblem p;
  p.inertia_body << 5.319049390950718, 0.7289484105823689, -0.285474510045837,  //
      0.7289484105823689, 6.426800768760901, -0.6807104294428629,               //
      -0.285474510045837, -0.6807104294428629, 9.007949266865905;
  p.torque_max = Vec3(1.34951433546738, 0.7568000684848404, 1.7708760371909111);
  p.attitude_final = Quat(Eigen::AngleAxisd(
      2.0349239567748576, Vec3(-0.8165196306862496, 0.017461322776365525, -0.5770535459650952).normalized()));
  CollocationOptions seed;
  seed.mesh_tolerance = 3e-7;
  const DirectSolution d = solve_direct(p, seed);
  ASSERT_TRUE(d.converged) << d.status;
  const IndirectSolution s = solve_indirect(p, d);
  ASSERT_TRUE(s.converged) << s.status;
  EXPECT_TRUE(s.singular_arcs.empty());
  std::vector<double> u2;
  for (std::size_t k = 0; k < s.switch_times.size(); ++k)
    if (s.switch_axes[k] == 1 && s.switch_times[k] > 2.7 && s.switch_times[k] < 2.8)
      u2.push_back(s.switch_times[k]);
  ASSERT_EQ(u2.size(), 2u);
  EXPECT_LT(u2[1] - u2[0], 2e-3);
  EXPECT_NEAR(0.5 * (u2[0] + u2[1]), 2.7678, 2e-3);
  EXPECT_NEAR(s.final_time / d.final_time, 1.0, 1e-5);
  const VerificationReport v = verify(p, d, s);
  EXPECT_TRUE(v.passed) << (v.failures.empty() ? "" : v.failures.front());
  EXPECT_EQ(v.switching_sign_violations, 0);
}

}  // namespace
}  // namespace poinsot::optimal::detail
