#pragma once
/// @file mesh.hpp
/// Exact mass properties of a closed triangle mesh (a polyhedron of uniform density) and of a thin surface.
///
/// Solid (divergence theorem, Mirtich 1996, "Fast and accurate computation of polyhedral mass properties";
/// Eberly, "Polyhedral mass properties (revisited)", 2002; Tonon 2004, J. Math. Stat. 1(1), eq. for the
/// canonical tetrahedron). Each triangle (a, b, c), oriented counter-clockwise seen from outside, forms with
/// a reference point p the tetrahedron (p, a, b, c) of signed volume v = (a−p)·((b−p)×(c−p))/6. With x
/// relative to p and vertices x1, x2, x3 (the fourth is 0), exactly:
///   ∫ dV = v,   ∫ x dV = v (x1 + x2 + x3)/4,   ∫ x⊗x dV = v/20 (Σ xi⊗xi + s⊗s),  s = x1 + x2 + x3.
/// Summing over the triangles of a closed, consistently oriented surface gives the integrals over the
/// enclosed volume (the signed contributions of the parts outside cancel). The reference point is the centre
/// of the bounding box, so that the sums do not cancel catastrophically for a mesh far from the origin. Then
/// m = ρ V, c = p + ∫x/V, K_c = ρ ∫x⊗x − m (c−p)⊗(c−p), J_c = tr(K_c) I − K_c (docs/conventions.md).
///
/// Shell (a thin surface of areal density σ, as MuJoCo's shellinertia): per triangle of area A,
///   ∫ dA = A,  ∫ x dA = A s/3,  ∫ x⊗x dA = A/12 (Σ xi⊗xi + s⊗s).
/// The surface need not be closed or oriented.
///
/// Diagnostics (by name, with counts): `open edges` (used by one triangle: not watertight), `inconsistent
/// winding` (an edge used twice in the same direction, or unequal numbers of uses in its two directions),
/// `non-manifold edges` (more than two triangles, but balanced), `degenerate triangles` (two equal vertex
/// indices, or an area below 1e-14 of the squared bounding-box diagonal), `shells` (connected components),
/// `inward orientation` (negative total signed volume).
/// Open or inconsistent meshes are an error for the solid method; an inward mesh is an error unless flipping
/// is asked for.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/inertia/mass_properties.hpp"

namespace poinsot::inertia {

/// An indexed triangle mesh. Vertices in m, in the mesh's own frame.
struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<std::int32_t, 3>> triangles;  ///< counter-clockwise seen from outside
};

/// Topology and orientation of a mesh.
struct MeshDiagnostics {
  std::size_t triangles = 0;
  std::size_t vertices = 0;
  std::size_t open_edges = 0;
  std::size_t inconsistent_edges = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t degenerate_triangles = 0;
  std::size_t shells = 0;
  double signed_volume = 0.0;  ///< m³, positive for an outward-oriented closed mesh
  double area = 0.0;           ///< m²
  bool watertight() const { return open_edges == 0; }
  bool consistent() const { return inconsistent_edges == 0; }
  bool inward() const { return signed_volume < 0.0; }
  /// One line per finding, e.g. "open edges: 3 (not watertight)", "shells: 2"; empty for a clean mesh.
  std::vector<std::string> messages() const;
};

/// Examines `mesh`. Throws InvalidInput for an empty mesh, an index out of range, or non-finite vertices.
MeshDiagnostics diagnose(const TriangleMesh& mesh);

/// Integrals over the enclosed volume (unit density) about the reference point `origin`: volume (m³), first
/// moment ∫x dV (m⁴) and second moment ∫x⊗x dV (m⁵), x relative to `origin`. No checks (the benchmarked
/// kernel).
struct VolumeIntegrals {
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  Mat3 second = Mat3::Zero();
};
VolumeIntegrals volume_integrals(const TriangleMesh& mesh, const Vec3& origin);

/// The centre of the bounding box (m), the reference point used by the mass-property functions.
Vec3 bounding_box_center(const TriangleMesh& mesh);

/// Options of mesh_mass_properties.
struct MeshOptions {
  bool flip_inward = false;  ///< flip an inward-oriented mesh instead of rejecting it
};

/// Mass properties of the solid enclosed by `mesh` with uniform `density` (kg/m³), in the mesh frame. Throws
/// InvalidInput for a non-positive density, an open or inconsistent mesh (the message gives the counts), an
/// inward mesh unless options.flip_inward, or a mesh enclosing no volume. `diagnostics`, when given, receives
/// the examination (also when it throws).
MassProperties mesh_mass_properties(const TriangleMesh& mesh, double density, const MeshOptions& options = {},
                                    MeshDiagnostics* diagnostics = nullptr);
/// The same with a total mass (kg) instead of a density.
MassProperties mesh_mass_properties_with_mass(const TriangleMesh& mesh, double mass,
                                              const MeshOptions& options = {},
                                              MeshDiagnostics* diagnostics = nullptr);
/// Mass properties of the surface itself with areal density `areal_density` (kg/m²); for a thickness t of a
/// material of density ρ pass ρ t. The mesh may be open. Throws InvalidInput for a non-positive density or a
/// mesh of zero area.
MassProperties mesh_shell_mass_properties(const TriangleMesh& mesh, double areal_density,
                                          MeshDiagnostics* diagnostics = nullptr);
/// The shell with a total mass (kg).
MassProperties mesh_shell_mass_properties_with_mass(const TriangleMesh& mesh, double mass,
                                                    MeshDiagnostics* diagnostics = nullptr);

/// Reverses the orientation of every triangle.
void flip_orientation(TriangleMesh& mesh);

}  // namespace poinsot::inertia
