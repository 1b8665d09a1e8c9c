// The mesh of the Hermite–Simpson transcription: point numbering with phases, Simpson's weights (exact for
// cubics), the points' times, and the refinement rule.
#include "../../src/optimal/collocation_mesh.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "poinsot/core/error.hpp"

namespace poinsot::optimal::detail {
namespace {

TEST(CollocationMesh, PhasesDuplicateTheNodeBetweenThem) {
  // Two phases of 2 and 1 intervals: points 0–4 in the first (node, mid, node, mid, node), 5–7 in the second.
  const CollocationMesh m = CollocationMesh::from_nodes({0.0, 0.4, 1.0, 0.0, 1.0}, {2, 1});
  EXPECT_EQ(m.phases(), 2);
  EXPECT_EQ(m.intervals(), 3);
  EXPECT_EQ(m.points(), 8);
  EXPECT_EQ(m.interval_first_point(2), 5);
  EXPECT_EQ(m.phase_last_point(0), 4);
  EXPECT_TRUE(m.first_of_phase(0));
  EXPECT_TRUE(m.first_of_phase(5));
  EXPECT_FALSE(m.first_of_phase(4));
  EXPECT_EQ(m.point_phase(5), 1);
  EXPECT_DOUBLE_EQ(m.step_fraction(1), 0.6);
  // Durations 2 s and 3 s: the first phase ends at 2 s on both copies of the node between the phases.
  const std::vector<double> t = m.point_times({2.0, 3.0});
  const std::vector<double> expected{0.0, 0.4, 0.8, 1.4, 2.0, 2.0, 3.5, 5.0};
  ASSERT_EQ(t.size(), expected.size());
  for (std::size_t p = 0; p < t.size(); ++p)
    EXPECT_NEAR(t[p], expected[p], 1e-15) << p;
}

TEST(CollocationMesh, SimpsonWeightsIntegrateCubicsExactly) {
  // Simpson's rule is exact for polynomials of degree 3 on every interval: ∫₀¹ (1 + 2τ − 3τ² + 4τ³) dτ = 2 on
  // each phase, whatever its unequal mesh (round-off only).
  const CollocationMesh m = CollocationMesh::from_nodes({0.0, 0.1, 0.45, 1.0, 0.0, 0.7, 1.0}, {3, 2});
  for (int a = 0; a < m.phases(); ++a) {
    double integral = 0.0;
    for (int p = m.phase_first_point(a); p <= m.phase_last_point(a); ++p) {
      const double tau = m.point_fraction(p);
      integral += m.quadrature_weight(p) * (1.0 + 2.0 * tau - 3.0 * tau * tau + 4.0 * tau * tau * tau);
    }
    EXPECT_NEAR(integral, 2.0, 1e-14) << a;
  }
}

TEST(CollocationMesh, UniformAndFractionMeshesAgree) {
  // Equal intervals as a uniform mesh (h = Δ/N as written) and as fractions 1/N: the same times to round-off.
  const CollocationMesh u = CollocationMesh::uniform(4);
  const CollocationMesh f = CollocationMesh::from_fractions({0.25, 0.25, 0.25, 0.25});
  EXPECT_TRUE(u.uniform());
  EXPECT_FALSE(f.uniform());
  const std::vector<double> tu = u.point_times({1.5}), tf = f.point_times({1.5});
  for (std::size_t p = 0; p < tu.size(); ++p)
    EXPECT_NEAR(tu[p], tf[p], 1e-15) << p;
  EXPECT_EQ(tu.back(), 1.5);
  for (int k = 0; k < 4; ++k)
    EXPECT_NEAR(u.step(k, 1.5), f.step(k, 1.5), 1e-16);
  EXPECT_THROW(CollocationMesh::uniform(0), InvalidInput);
  EXPECT_THROW(CollocationMesh::from_nodes({0.0, 1.0}, {2}), InvalidInput);
}

TEST(CollocationMesh, RefinementSplitsByTheFourthRootOfTheErrorRatio) {
  // ⌈(ε/tol)^¼⌉ pieces, at least 2 and at most 5; none above the tolerance: kept.
  EXPECT_EQ(refinement_pieces(1e-7, 1e-7), 1);
  EXPECT_EQ(refinement_pieces(0.5e-7, 1e-7), 1);
  EXPECT_EQ(refinement_pieces(1.01e-7, 1e-7), 2);
  EXPECT_EQ(refinement_pieces(15e-7, 1e-7), 2);   // 15^¼ = 1.97
  EXPECT_EQ(refinement_pieces(17e-7, 1e-7), 3);   // 2.03
  EXPECT_EQ(refinement_pieces(200e-7, 1e-7), 4);  // 3.76
  EXPECT_EQ(refinement_pieces(1.0, 1e-7), 5);
}

}  // namespace
}  // namespace poinsot::optimal::detail
