// The amendment of a singular arc whose torque leaves its bound (with_bounded_singular_torque,
// src/optimal/arc_structure.*), on a structure and an extremal's samples made by hand: one singular arc of
// u1 from t = 1 s to t = 3 s, u1 = +ū1 before and after it, ū = 1 N·m, samples every 0.1 s (two at each
// event, one per side). Oracles: where the torque crosses its bound (exact for a torque linear between
// samples), and the events the minimum principle asks for there (a bang arc of the torque's sign in its
// place).
#include "../../src/optimal/arc_structure.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <vector>

namespace poinsot::optimal::detail {
namespace {

using Kind = ArcEvent::Kind;
using Arc = ArcEvent::Arc;

/// The singular arc of u1 over [1, 3] s, entered and left with u1 = +ū1.
ArcStructure one_singular_arc() {
  ArcStructure s;
  ArcEvent entry, exit;
  entry.kind = Kind::entry;
  exit.kind = Kind::exit;
  entry.arc = exit.arc = Arc::singular;
  entry.side = exit.side = 0.0;
  entry.time = 1.0;
  exit.time = 3.0;
  exit.sign_after = 1.0;
  entry.pair = 1;
  exit.pair = 0;
  s.events = {entry, exit};
  return s;
}

/// An extremal's samples from 0 to 4 s every 0.1 s: u1 = +1 off the arc, `singular(t)` on it (both sides
/// sampled at the entry and the exit); u2 = u3 = 0.
IndirectSolution samples(const std::function<double(double)>& singular) {
  IndirectSolution shot;
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.1 * k;
    const bool on_arc = t > 1.0 - 1e-12 && t < 3.0 + 1e-12;
    if (k == 10 || k == 30) {  // the bang arc's side of the event first at the entry, last at the exit
      shot.time.push_back(t);
      shot.torque_body.emplace_back(k == 10 ? 1.0 : singular(t), 0.0, 0.0);
      shot.time.push_back(t);
      shot.torque_body.emplace_back(k == 10 ? singular(t) : 1.0, 0.0, 0.0);
      continue;
    }
    shot.time.push_back(t);
    shot.torque_body.emplace_back(on_arc ? singular(t) : 1.0, 0.0, 0.0);
  }
  return shot;
}

ReorientationProblem unit_bounds() {
  ReorientationProblem p;
  p.torque_max = Vec3::Ones();
  return p;
}

/// An expected event: its kind and time (s).
struct Event {
  Kind kind;
  double time;
};

/// `s` has the events `expected` (in that order, all of axis 1), each entry paired with an exit and back.
void expect_events(const ArcStructure& s, const std::vector<Event>& expected) {
  ASSERT_EQ(s.events.size(), expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    EXPECT_EQ(s.events[k].kind, expected[k].kind) << "event " << k;
    EXPECT_NEAR(s.events[k].time, expected[k].time, 1e-12) << "event " << k;
    EXPECT_EQ(s.events[k].axis, 0);
  }
  // every entry is paired with an exit, and back; a switch has no pair
  for (std::size_t k = 0; k < s.events.size(); ++k) {
    const int pair = s.events[k].pair;
    if (s.events[k].kind == Kind::sign_change) {
      EXPECT_EQ(pair, -1) << "event " << k;
      continue;
    }
    ASSERT_GE(pair, 0) << "event " << k;
    EXPECT_EQ(s.events[static_cast<std::size_t>(pair)].pair, static_cast<int>(k));
    EXPECT_NE(s.events[static_cast<std::size_t>(pair)].kind, s.events[k].kind);
  }
}

// Entered from +ū1 with ũ1 = −1.5 ū1, back inside from t = 1.25 s: a switch to −ū1 at the old entry, and the
// entry where |ũ1| = ū1.
TEST(BoundedSingularTorque, OutsideAtTheEntryOfTheOtherSignIsASwitchThenTheEntry) {
  const ArcStructure s = one_singular_arc();
  const IndirectSolution shot = samples([](double t) { return t < 1.5 ? -1.5 + 2.0 * (t - 1.0) : -0.5; });
  ArcStructure amended;
  ASSERT_TRUE(with_bounded_singular_torque(unit_bounds(), s, {1.0, 3.0}, shot, amended));
  expect_events(amended, {{Kind::sign_change, 1.0}, {Kind::entry, 1.25}, {Kind::exit, 3.0}});
}

// Outside with the sign of the bang arc before: that arc lasts until the torque is back inside.
TEST(BoundedSingularTorque, OutsideAtTheEntryOfTheSameSignMovesTheEntry) {
  const IndirectSolution shot = samples([](double t) { return t < 1.5 ? 1.5 - 2.0 * (t - 1.0) : 0.5; });
  ArcStructure amended;
  ASSERT_TRUE(with_bounded_singular_torque(unit_bounds(), one_singular_arc(), {1.0, 3.0}, shot, amended));
  expect_events(amended, {{Kind::entry, 1.25}, {Kind::exit, 3.0}});
}

// Outside of the other sign than the one after the exit: the exit moves to where it leaves the bound, with
// the torque's sign after it, and a switch at the old exit returns to +ū1.
TEST(BoundedSingularTorque, OutsideAtTheExitIsTheExitThenASwitch) {
  const IndirectSolution shot = samples([](double t) { return t > 2.5 ? -0.5 - 2.0 * (t - 2.5) : -0.5; });
  ArcStructure amended;
  ASSERT_TRUE(with_bounded_singular_torque(unit_bounds(), one_singular_arc(), {1.0, 3.0}, shot, amended));
  expect_events(amended, {{Kind::entry, 1.0}, {Kind::exit, 2.75}, {Kind::sign_change, 3.0}});
  EXPECT_EQ(amended.events[1].sign_after, -1.0);
}

// Outside inside the arc: an exit where it leaves the bound, a bang arc of its sign, a new entry where it is
// back; the original entry pairs with the new exit, the new entry with the original exit.
TEST(BoundedSingularTorque, OutsideInsideTheArcIsAnExitAndAReEntry) {
  const IndirectSolution shot = samples([](double t) { return 1.0 + 0.5 - 2.0 * std::abs(t - 2.0); });
  // |ũ1| = 1 where 2|t − 2| = 0.5: t = 1.75 and 2.25 s; ũ1 = 1.5 − 2|t − 2| is below the bound at 1 s and 3 s
  ArcStructure amended;
  ASSERT_TRUE(with_bounded_singular_torque(unit_bounds(), one_singular_arc(), {1.0, 3.0}, shot, amended));
  expect_events(amended, {{Kind::entry, 1.0}, {Kind::exit, 1.75}, {Kind::entry, 2.25}, {Kind::exit, 3.0}});
  EXPECT_EQ(amended.events[1].sign_after, 1.0);
  EXPECT_EQ(amended.events[0].pair, 1);
  EXPECT_EQ(amended.events[2].pair, 3);
}

// Nothing to amend within the bound (to the excess tolerance), and nothing that can be amended when the
// torque is outside over the whole arc.
TEST(BoundedSingularTorque, WithinTheBoundOrOutsideThroughoutIsLeftAsItIs) {
  ArcStructure amended;
  const IndirectSolution inside = samples([](double) { return 1.0 + 0.5 * kSingularTorqueExcess; });
  EXPECT_FALSE(with_bounded_singular_torque(unit_bounds(), one_singular_arc(), {1.0, 3.0}, inside, amended));
  const IndirectSolution outside = samples([](double) { return -2.0; });
  EXPECT_FALSE(with_bounded_singular_torque(unit_bounds(), one_singular_arc(), {1.0, 3.0}, outside, amended));
  EXPECT_TRUE(amended.events.empty());
}

}  // namespace
}  // namespace poinsot::optimal::detail
