// The dips that read_arc_structure takes for singular arcs (src/optimal/arc_structure.*), on direct solutions
// made by hand: 201 samples over T = 2 s (every 10 ms), u1 = +ū1 and u3 = −ū3 throughout, u2 as given near
// t = 1 s and +ū2 elsewhere, ū = 1 N·m, an inertia off its principal frame (so that no arc is refused as of
// order two). A stretch inside the bound shorter than kShortestSingularArc of T (40 ms here) is a singular
// arc only with `dips`, and only where u2 keeps its sign from the sample before it to the sample after it;
// the collocation's passage through a switch changes sign and stays a switch. Oracles: the sample times.
#include "../../src/optimal/arc_structure.hpp"

#include <gtest/gtest.h>

#include <map>
#include <vector>

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

}  // namespace
}  // namespace poinsot::optimal::detail
