// Singular arcs of order two are refused by the shooting with their reason (src/optimal/arc_structure.cpp).
// About a principal axis e_i, J⁻¹e_i ∥ e_i and ∂σ̈_i/∂u_i = C_ii = 2σ·(J⁻¹e_i × e_i) = 0 for every σ: u_i does
// not enter σ̈_i, and an arc with σ_i ≡ 0 is of order two at least, whose junctions with bang arcs chatter.
// The direct solution here is made by hand, with the feature the structure reader looks at (a torque inside
// its bound over a stretch); the oracle is that algebra: the same torques with an inertia off its principal
// frame in the singular axis' row are not refused as order two.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "poinsot/optimal/indirect_shooting.hpp"

namespace poinsot::optimal {
namespace {

constexpr double kFinalTime = 2.0;
constexpr int kSamples = 201;

/// A direct solution of kSamples samples over [0, kFinalTime] with the body torque given as a function of t,
/// the body at rest, and two costate estimates (the shooting's seed needs them; their values do not matter to
/// the structure).
DirectSolution hand_made_direct(const std::function<Vec3(double)>& torque) {
  DirectSolution d;
  d.nlp_solved = true;
  d.final_time = kFinalTime;
  for (int k = 0; k < kSamples; ++k) {
    const double t = kFinalTime * k / (kSamples - 1);
    d.time.push_back(t);
    d.attitude.push_back(Quat::Identity());
    d.omega_body.push_back(Vec3::Zero());
    d.torque_body.push_back(torque(t));
  }
  for (const double t : {0.25 * kFinalTime, 0.75 * kFinalTime}) {
    d.costate_time.push_back(t);
    d.costate_attitude_body.push_back(Vec3(1.0, 0.5, -0.5));
    d.costate_omega.push_back(Vec3(-0.1, 0.2, 0.3));
  }
  return d;
}

ReorientationProblem slew(const Mat3& inertia) {
  ReorientationProblem p;
  p.inertia_body = inertia;
  p.attitude_final = Quat(Eigen::AngleAxisd(1.0, Vec3(1.0, 2.0, 2.0).normalized()));
  return p;
}

/// u1 inside its bound from 0.6 s to 1.2 s (a singular arc's signature), bang-bang otherwise.
Vec3 torque_with_u1_inside(double t) {
  const double u1 = t < 0.6 ? 1.0 : t <= 1.2 ? 0.2 : -1.0;
  return Vec3(u1, t < 1.0 ? 1.0 : -1.0, t < 1.0 ? -1.0 : 1.0);
}

TEST(OrderTwoSingularArcs, AnArcAboutAPrincipalAxisIsRefusedWithItsReason) {
  const ReorientationProblem p = slew(Vec3(2.0, 2.5, 3.0).asDiagonal().toDenseMatrix());
  const DirectSolution d = hand_made_direct(torque_with_u1_inside);
  const IndirectSolution s = solve_indirect(p, d);
  EXPECT_FALSE(s.converged);
  EXPECT_EQ(s.status.rfind("not applied: u1 is inside its bound from t = 0.6 s to 1.2 s", 0), 0u) << s.status;
  EXPECT_NE(s.status.find("about a principal axis: a singular arc of order two"), std::string::npos)
      << s.status;
}

TEST(OrderTwoSingularArcs, AnArcOffAPrincipalAxisIsNotRefusedAsOrderTwo) {
  Mat3 J;
  J << 2.0, 0.2, 0.05,  //
      0.2, 2.5, 0.0,    //
      0.05, 0.0, 3.0;
  const DirectSolution d = hand_made_direct(torque_with_u1_inside);
  const IndirectSolution s = solve_indirect(slew(J), d);
  // C_11 ≠ 0: the arc is shot, not refused (the hand-made costates lead nowhere, which is not what is checked
  // here).
  EXPECT_EQ(s.status.rfind("not applied", 0), std::string::npos) << s.status;
  EXPECT_EQ(s.status.find("order two"), std::string::npos) << s.status;
}

}  // namespace
}  // namespace poinsot::optimal
