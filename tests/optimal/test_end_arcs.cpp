// The switching structures shot again without a first or last bang arc (without_vanishing_end_arcs,
// without_short_end_arcs, src/optimal/switching_structure.*), on structures made by hand with T = 10 s.
// Oracle: the switches that remain, axis by axis, and the initial sign of an axis that lost its first switch
// (the arc before it is gone, so the control starts with the sign that followed it).
#include "../../src/optimal/switching_structure.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "poinsot/optimal/indirect_shooting.hpp"

namespace poinsot::optimal::detail {
namespace {

/// u1 switches at 0.2, 4 and 9.9 s; u2 at 5 s; u3 at 0.3 s and 9.6 s; u1 and u3 start positive, u2 negative.
SwitchGuess three_axes() {
  SwitchGuess sw;
  sw.initial_sign = Vec3(1.0, -1.0, 1.0);
  sw.times = {4.0, 0.2, 9.9, 5.0, 9.6, 0.3};
  sw.axes = {0, 0, 0, 1, 2, 2};
  return sw;
}

/// The switches of axis i, in the order of `sw`.
std::vector<double> switches_of(const SwitchGuess& sw, int i) {
  std::vector<double> t;
  for (std::size_t k = 0; k < sw.times.size(); ++k)
    if (sw.axes[k] == i) t.push_back(sw.times[k]);
  return t;
}

TEST(EndArcs, ShortEndArcsOfTheDirectStructureAreDroppedAxisByAxis) {
  // Within kShortEndArc T of either end lie u1's switches at 0.2 and 9.9 s and u3's at 0.3 s and 9.6 s; the
  // others (4 and 5 s) do not.
  const double edge = kShortEndArc * 10.0;
  ASSERT_TRUE(edge > 0.3 && edge > 10.0 - 9.6 && edge < 4.0)
      << "the structure assumes kShortEndArc T = " << edge;
  SwitchGuess out;
  ASSERT_TRUE(without_short_end_arcs(three_axes(), 10.0, out));
  EXPECT_EQ(switches_of(out, 0), std::vector<double>{4.0});
  EXPECT_EQ(switches_of(out, 1), std::vector<double>{5.0});
  EXPECT_TRUE(switches_of(out, 2).empty());
  EXPECT_EQ(out.initial_sign, Vec3(-1.0, -1.0, -1.0));
}

TEST(EndArcs, AStructureWithoutShortEndArcsIsLeftAlone) {
  SwitchGuess sw;
  sw.times = {1.0, 8.0, 5.0};
  sw.axes = {0, 0, 1};
  SwitchGuess out;
  out.times = {42.0};
  EXPECT_FALSE(without_short_end_arcs(sw, 10.0, out));
  EXPECT_EQ(out.times, std::vector<double>{42.0});
  EXPECT_FALSE(without_short_end_arcs(sw, 0.0, out)) << "no final time";
}

TEST(EndArcs, SwitchesTheShotLeftAtAnEdgeAreDroppedFromTheStructure) {
  // The shot's switches in the structure's order; u1's first went to 1e-9 s, u3's last to T − 1e-9 s.
  IndirectSolution shot;
  shot.final_time = 10.0;
  shot.switch_times = {4.1, 1e-9, 8.0, 5.0, 10.0 - 1e-9, 0.4};
  shot.switch_axes = {0, 0, 0, 1, 2, 2};
  SwitchGuess out;
  ASSERT_TRUE(without_vanishing_end_arcs(three_axes(), shot, out));
  EXPECT_EQ(switches_of(out, 0), (std::vector<double>{4.0, 9.9}));
  EXPECT_EQ(switches_of(out, 1), std::vector<double>{5.0});
  EXPECT_EQ(switches_of(out, 2), std::vector<double>{0.3});
  EXPECT_EQ(out.initial_sign, Vec3(-1.0, -1.0, 1.0));
  // Nothing at an edge: false.
  shot.switch_times = {4.1, 0.1, 8.0, 5.0, 9.0, 0.4};
  EXPECT_FALSE(without_vanishing_end_arcs(three_axes(), shot, out));
}

}  // namespace
}  // namespace poinsot::optimal::detail
