#pragma once
/// @file tessellation.hpp
/// Closed, outward-oriented triangle meshes of the elementary shapes of shapes.hpp, in the same frames
/// (origin at the centre of mass, axis along z). Used to check the closed forms against the mesh method, for
/// benchmarks and for drawing. Curved surfaces are inscribed polyhedra: `segments` around the axis and
/// `rings` along the profile, so the volume and the moments converge as O(1/segments²).

#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/shapes.hpp"

namespace poinsot::inertia {

/// A closed surface of revolution about z: the profile is a polyline of (r, z) points (m), either from the
/// axis to the axis (first and last r = 0, traversed so that the outside is on the right, i.e. upward along
/// an outer wall) or, with `closed_loop`, a loop with every r > 0 traversed counter-clockwise in the (r, z)
/// plane. Points with r = 0 become single pole vertices. Throws InvalidInput for fewer than 3 segments or a
/// profile of fewer than 2 points.
TriangleMesh revolve(const std::vector<Eigen::Vector2d>& profile, int segments, bool closed_loop = false);

/// Tessellation of `spec` (every kind but point, rod and plate; a hollow sphere or cylinder gives a closed
/// solid of the given inner radius; hollow = true is not a solid and is rejected). Throws InvalidInput for
/// those and for bad sizes.
TriangleMesh tessellate(const ShapeSpec& spec, int segments);

/// Segments around the axis of a curved shape's drawn surface (a scenario's body, a robot file's link): the
/// inertia comes from the closed forms, the tessellation is only drawn.
inline constexpr int kDrawnSurfaceSegments = 48;

/// A box of the given size (m) centred at the origin: 12 triangles.
TriangleMesh box_mesh(const Vec3& size);

}  // namespace poinsot::inertia
