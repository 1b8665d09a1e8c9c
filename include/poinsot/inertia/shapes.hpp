#pragma once
/// @file shapes.hpp
/// Mass properties of homogeneous elementary shapes, about their centre of mass in the shape's own frame
/// (origin at the centre of mass; axis of symmetry along z). Mass in kg, lengths in m, J in kg·m².
///
/// Formulas (J = diag(Jxx, Jyy, Jzz), m the mass). Sources: [MK] Meriam & Kraige, Engineering Mechanics:
/// Dynamics, 7th ed., Appendix D, Table D/4; [G] Goldstein, Poole & Safko, Classical Mechanics, 3rd ed.,
/// §5.3; [W] E. W. Weisstein, MathWorld, "Moment of Inertia" and "Torus"; derivations marked (derived) use
/// only the parallel-axis theorem on the listed results.
///  * point mass: J = 0.
///  * thin rod, length L along z [MK]: Jxx = Jyy = m L²/12, Jzz = 0.
///  * rectangular plate a × b in the xy-plane (a along x) [MK]: Jxx = m b²/12, Jyy = m a²/12,
///    Jzz = m (a² + b²)/12 (perpendicular-axis theorem). About a corner, as in the lecture [LEC]: shift with
///    MassProperties::inertia_about((−a/2, −b/2, 0)).
///  * box a × b × c [MK]: Jxx = m (b² + c²)/12 and cyclic.
///  * solid sphere, radius R [MK]: 2/5 m R². Thick spherical shell R > r (derived: difference of two solid
///    spheres of equal density): 2/5 m (R⁵ − r⁵)/(R³ − r³). Thin shell [MK]: 2/3 m R².
///  * solid cylinder, radius R, length L [MK]: Jzz = m R²/2, Jxx = Jyy = m (3R² + L²)/12. Thick-walled tube,
///    inner radius r [MK]: Jzz = m (R² + r²)/2, Jxx = m (3(R² + r²) + L²)/12. Thin-walled tube (no end caps,
///    r → R): Jzz = m R², Jxx = m (6R² + L²)/12.
///  * solid cone, base radius R, height h, base at z = −h/4 and apex at z = +3h/4 [MK]: Jzz = 3/10 m R²,
///    Jxx = Jyy = m (3/20 R² + 3/80 h²).
///  * solid ellipsoid, semi-axes a, b, c along x, y, z [W]: Jxx = m (b² + c²)/5 and cyclic.
///  * capsule: cylinder of radius r and length L (between the centres of its end caps) with two hemispherical
///    caps (derived): masses split by volume, m_c = m·πr²L/V, m_s = m·(4/3)πr³/V; Jzz = m_c r²/2 + 2/5 m_s
///    r², Jxx = m_c (3r² + L²)/12 + m_s (2/5 r² + L²/4 + 3/8 L r) (hemisphere centroid at 3r/8 from its
///    face).
///  * solid torus, tube radius r, distance R >= r from the axis z to the tube's centre [W]:
///    Jzz = m (R² + 3/4 r²), Jxx = Jyy = m (R²/2 + 5/8 r²).
/// Every function throws InvalidInput for a mass <= 0, a size <= 0 or non-finite input (message names the
/// field and the value), and for inconsistent sizes (inner radius >= outer, torus R < r).

#include <string>

#include "poinsot/core/types.hpp"
#include "poinsot/inertia/mass_properties.hpp"

namespace poinsot::inertia {

MassProperties point_mass(double mass);
MassProperties rod(double mass, double length);
MassProperties plate(double mass, double size_x, double size_y);
MassProperties box(double mass, const Vec3& size);
MassProperties solid_sphere(double mass, double radius);
/// Thick spherical shell of outer radius `radius` and inner radius 0 <= `inner_radius` < `radius`.
MassProperties hollow_sphere(double mass, double radius, double inner_radius);
/// Thin spherical shell (a surface) of radius `radius`.
MassProperties spherical_shell(double mass, double radius);
/// Solid (inner_radius = 0) or thick-walled (0 < inner_radius < radius) cylinder along z.
MassProperties cylinder(double mass, double radius, double length, double inner_radius = 0.0);
/// Thin-walled tube (a surface without end caps) of radius `radius` and length `length` along z.
MassProperties cylindrical_shell(double mass, double radius, double length);
MassProperties cone(double mass, double radius, double height);
MassProperties ellipsoid(double mass, const Vec3& semi_axes);
MassProperties capsule(double mass, double radius, double length);
MassProperties torus(double mass, double major_radius, double minor_radius);

/// A shape by name and sizes, for command lines and body files. Which fields each kind uses:
/// point: none; rod: length; plate: size (x, y); box: size (x, y, z); sphere: radius (+ inner_radius or
/// hollow); cylinder: radius, length (+ inner_radius or hollow); cone: radius, height; ellipsoid: size (the
/// semi-axes a, b, c); capsule: radius, length; torus: major_radius, minor_radius.
struct ShapeSpec {
  std::string kind;           ///< point, rod, plate, box, sphere, cylinder, cone, ellipsoid, capsule, torus
  Vec3 size = Vec3::Zero();   ///< m
  double radius = 0.0;        ///< m
  double length = 0.0;        ///< m
  double height = 0.0;        ///< m
  double inner_radius = 0.0;  ///< m; 0 for a solid
  double major_radius = 0.0;  ///< m
  double minor_radius = 0.0;  ///< m
  bool hollow = false;        ///< thin shell (sphere) or thin-walled tube (cylinder)
};

/// The measure that a density multiplies: volume (m³) for solids, area (m²) for plates and thin shells,
/// length (m) for rods; 0 for a point. Throws InvalidInput as the shape functions do.
double shape_measure(const ShapeSpec& spec);
/// "kg/m³", "kg/m²" or "kg/m": the unit of the density of `spec` (empty for a point).
std::string density_unit(const ShapeSpec& spec);
/// Mass properties of `spec` with the given mass (kg).
MassProperties shape_with_mass(const ShapeSpec& spec, double mass);
/// Mass properties of `spec` with the given density (unit from density_unit); a point has no density.
MassProperties shape_with_density(const ShapeSpec& spec, double density);

}  // namespace poinsot::inertia
