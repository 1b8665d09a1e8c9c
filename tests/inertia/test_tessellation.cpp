// Tests of tessellation.hpp: every tessellation is closed, consistently and outward oriented, in one piece
// (two for a thick spherical shell), and its vertices lie on the shape's surface.
#include "poinsot/inertia/tessellation.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::inertia {
namespace {

ShapeSpec tessellated_spec(const char* kind) {
  ShapeSpec s;
  s.kind = kind;
  s.size = Vec3(0.5, 0.3, 0.2);
  s.radius = 0.3;
  s.length = 0.8;
  s.height = 0.6;
  s.major_radius = 0.5;
  s.minor_radius = 0.1;
  return s;
}

TEST(Tessellation, ClosedOutwardAndConnected) {
  for (const char* kind : {"box", "sphere", "cylinder", "cone", "ellipsoid", "capsule", "torus"}) {
    for (int n : {3, 8, 33}) {
      const MeshDiagnostics d = diagnose(tessellate(tessellated_spec(kind), n));
      EXPECT_TRUE(d.messages().empty()) << kind << " " << n << ": " << d.messages().front();
      EXPECT_GT(d.signed_volume, 0.0) << kind;
    }
  }
  ShapeSpec thick = tessellated_spec("sphere");
  thick.inner_radius = 0.1;
  const MeshDiagnostics d = diagnose(tessellate(thick, 16));
  EXPECT_EQ(d.shells, 2u);
  EXPECT_EQ(d.open_edges + d.inconsistent_edges, 0u);
  ShapeSpec tube = tessellated_spec("cylinder");
  tube.inner_radius = 0.2;
  EXPECT_TRUE(diagnose(tessellate(tube, 16)).messages().empty());
}

TEST(Tessellation, VerticesLieOnTheSurface) {
  for (const auto& v : tessellate(tessellated_spec("sphere"), 20).vertices)
    EXPECT_NEAR(v.norm(), 0.3, 1e-15);
  for (const auto& v : tessellate(tessellated_spec("torus"), 20).vertices) {
    const double rho = std::hypot(v.x(), v.y()) - 0.5;
    EXPECT_NEAR(std::hypot(rho, v.z()), 0.1, 1e-15);
  }
  for (const auto& v : tessellate(tessellated_spec("ellipsoid"), 20).vertices) {
    EXPECT_NEAR(v.cwiseQuotient(Vec3(0.5, 0.3, 0.2)).norm(), 1.0, 4e-16);
  }
}

TEST(Tessellation, RejectsWhatIsNotASolid) {
  EXPECT_THROW(tessellate(tessellated_spec("rod"), 8), InvalidInput);
  EXPECT_THROW(tessellate(tessellated_spec("sphere"), 2), InvalidInput);
  ShapeSpec s = tessellated_spec("sphere");
  s.hollow = true;
  EXPECT_THROW(tessellate(s, 8), InvalidInput);
  EXPECT_THROW(revolve({{0.0, 0.0}}, 8), InvalidInput);
}

}  // namespace
}  // namespace poinsot::inertia
