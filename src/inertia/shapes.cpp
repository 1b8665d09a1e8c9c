#include "poinsot/inertia/shapes.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::inertia {
namespace {

MassProperties diagonal(double mass, double jxx, double jyy, double jzz) {
  MassProperties out;
  out.mass = mass;
  out.inertia_com = Vec3(jxx, jyy, jzz).asDiagonal();
  return out;
}

void require_inner(const char* shape, double radius, double inner_radius) {
  require_non_negative(fmt::format("{}: inner radius", shape), inner_radius, "m");
  if (!(inner_radius < radius)) {
    throw InvalidInput(fmt::format("{}: inner radius {} m; expected less than the outer radius {} m", shape,
                                   format_number(inner_radius), format_number(radius)));
  }
}

}  // namespace

MassProperties point_mass(double mass) {
  require_positive("point: mass", mass, "kg");
  return diagonal(mass, 0.0, 0.0, 0.0);
}

MassProperties rod(double mass, double length) {
  require_positive("rod: mass", mass, "kg");
  require_positive("rod: length", length, "m");
  const double j = mass * length * length / 12.0;
  return diagonal(mass, j, j, 0.0);
}

MassProperties plate(double mass, double a, double b) {
  require_positive("plate: mass", mass, "kg");
  require_positive("plate: size x", a, "m");
  require_positive("plate: size y", b, "m");
  return diagonal(mass, mass * b * b / 12.0, mass * a * a / 12.0, mass * (a * a + b * b) / 12.0);
}

MassProperties box(double mass, const Vec3& s) {
  require_positive("box: mass", mass, "kg");
  for (int k = 0; k < 3; ++k)
    require_positive(fmt::format("box: size {}", "xyz"[k]), s[k], "m");
  const Vec3 q = s.cwiseAbs2();
  return diagonal(mass, mass * (q.y() + q.z()) / 12.0, mass * (q.x() + q.z()) / 12.0,
                  mass * (q.x() + q.y()) / 12.0);
}

MassProperties solid_sphere(double mass, double r) {
  require_positive("sphere: mass", mass, "kg");
  require_positive("sphere: radius", r, "m");
  const double j = 0.4 * mass * r * r;
  return diagonal(mass, j, j, j);
}

MassProperties hollow_sphere(double mass, double R, double r) {
  require_positive("sphere: mass", mass, "kg");
  require_positive("sphere: radius", R, "m");
  require_inner("sphere", R, r);
  // (R⁵ − r⁵)/(R³ − r³) written with x = r/R as R²(1 + x + x² + x³ + x⁴)/(1 + x + x²): no cancellation.
  const double x = r / R;
  const double ratio = (1.0 + x + x * x + x * x * x + x * x * x * x) / (1.0 + x + x * x);
  const double j = 0.4 * mass * R * R * ratio;
  return diagonal(mass, j, j, j);
}

MassProperties spherical_shell(double mass, double r) {
  require_positive("sphere: mass", mass, "kg");
  require_positive("sphere: radius", r, "m");
  const double j = 2.0 / 3.0 * mass * r * r;
  return diagonal(mass, j, j, j);
}

MassProperties cylinder(double mass, double R, double L, double r) {
  require_positive("cylinder: mass", mass, "kg");
  require_positive("cylinder: radius", R, "m");
  require_positive("cylinder: length", L, "m");
  require_inner("cylinder", R, r);
  const double q = R * R + r * r;
  const double jxx = mass * (3.0 * q + L * L) / 12.0;
  return diagonal(mass, jxx, jxx, 0.5 * mass * q);
}

MassProperties cylindrical_shell(double mass, double R, double L) {
  require_positive("cylinder: mass", mass, "kg");
  require_positive("cylinder: radius", R, "m");
  require_positive("cylinder: length", L, "m");
  const double jxx = mass * (6.0 * R * R + L * L) / 12.0;
  return diagonal(mass, jxx, jxx, mass * R * R);
}

MassProperties cone(double mass, double R, double h) {
  require_positive("cone: mass", mass, "kg");
  require_positive("cone: radius", R, "m");
  require_positive("cone: height", h, "m");
  const double jxx = mass * (3.0 / 20.0 * R * R + 3.0 / 80.0 * h * h);
  return diagonal(mass, jxx, jxx, 0.3 * mass * R * R);
}

MassProperties ellipsoid(double mass, const Vec3& s) {
  require_positive("ellipsoid: mass", mass, "kg");
  for (int k = 0; k < 3; ++k)
    require_positive(fmt::format("ellipsoid: semi-axis {}", "abc"[k]), s[k], "m");
  const Vec3 q = s.cwiseAbs2();
  return diagonal(mass, mass * (q.y() + q.z()) / 5.0, mass * (q.x() + q.z()) / 5.0,
                  mass * (q.x() + q.y()) / 5.0);
}

MassProperties capsule(double mass, double r, double L) {
  require_positive("capsule: mass", mass, "kg");
  require_positive("capsule: radius", r, "m");
  require_positive("capsule: length", L, "m");
  const double vc = std::numbers::pi * r * r * L;
  const double vs = 4.0 / 3.0 * std::numbers::pi * r * r * r;
  const double mc = mass * vc / (vc + vs);
  const double ms = mass * vs / (vc + vs);
  const double jzz = 0.5 * mc * r * r + 0.4 * ms * r * r;
  const double jxx = mc * (3.0 * r * r + L * L) / 12.0 + ms * (0.4 * r * r + 0.25 * L * L + 0.375 * L * r);
  return diagonal(mass, jxx, jxx, jzz);
}

MassProperties torus(double mass, double R, double r) {
  require_positive("torus: mass", mass, "kg");
  require_positive("torus: major radius", R, "m");
  require_positive("torus: minor radius", r, "m");
  if (!(r <= R)) {
    throw InvalidInput(
        fmt::format("torus: minor radius {} m; expected at most the major radius {} m (a "
                    "self-intersecting torus is not a solid of revolution of this formula)",
                    format_number(r), format_number(R)));
  }
  const double jxx = mass * (0.5 * R * R + 0.625 * r * r);
  return diagonal(mass, jxx, jxx, mass * (R * R + 0.75 * r * r));
}

namespace {

/// Validates the sizes of `spec` by building it with unit mass; returns the measure.
double measure_of(const ShapeSpec& s) {
  const std::string& k = s.kind;
  if (k == "point") return 0.0;
  if (k == "rod") {
    (void)rod(1.0, s.length);
    return s.length;
  }
  if (k == "plate") {
    (void)plate(1.0, s.size.x(), s.size.y());
    return s.size.x() * s.size.y();
  }
  if (k == "box") {
    (void)box(1.0, s.size);
    return s.size.prod();
  }
  if (k == "sphere") {
    if (s.hollow) {
      (void)spherical_shell(1.0, s.radius);
      return 4.0 * std::numbers::pi * s.radius * s.radius;
    }
    (void)hollow_sphere(1.0, s.radius, s.inner_radius);
    return 4.0 / 3.0 * std::numbers::pi * (std::pow(s.radius, 3) - std::pow(s.inner_radius, 3));
  }
  if (k == "cylinder") {
    if (s.hollow) {
      (void)cylindrical_shell(1.0, s.radius, s.length);
      return 2.0 * std::numbers::pi * s.radius * s.length;
    }
    (void)cylinder(1.0, s.radius, s.length, s.inner_radius);
    return std::numbers::pi * (s.radius * s.radius - s.inner_radius * s.inner_radius) * s.length;
  }
  if (k == "cone") {
    (void)cone(1.0, s.radius, s.height);
    return std::numbers::pi * s.radius * s.radius * s.height / 3.0;
  }
  if (k == "ellipsoid") {
    (void)ellipsoid(1.0, s.size);
    return 4.0 / 3.0 * std::numbers::pi * s.size.prod();
  }
  if (k == "capsule") {
    (void)capsule(1.0, s.radius, s.length);
    return std::numbers::pi * s.radius * s.radius * (s.length + 4.0 / 3.0 * s.radius);
  }
  if (k == "torus") {
    (void)torus(1.0, s.major_radius, s.minor_radius);
    return 2.0 * std::numbers::pi * std::numbers::pi * s.major_radius * s.minor_radius * s.minor_radius;
  }
  throw InvalidInput(
      fmt::format("shape: got \"{}\", expected one of point, rod, plate, box, sphere, cylinder, "
                  "cone, ellipsoid, capsule, torus",
                  k));
}

}  // namespace

double shape_measure(const ShapeSpec& spec) {
  return measure_of(spec);
}

std::string density_unit(const ShapeSpec& s) {
  if (s.kind == "point") return "";
  if (s.kind == "rod") return "kg/m";
  if (s.kind == "plate" || (s.hollow && (s.kind == "sphere" || s.kind == "cylinder"))) return "kg/m²";
  return "kg/m³";
}

MassProperties shape_with_mass(const ShapeSpec& s, double mass) {
  (void)measure_of(
      s);  // validates the kind and the sizes first, so that their message comes before the mass's
  const std::string& k = s.kind;
  if (k == "point") return point_mass(mass);
  if (k == "rod") return rod(mass, s.length);
  if (k == "plate") return plate(mass, s.size.x(), s.size.y());
  if (k == "box") return box(mass, s.size);
  if (k == "sphere") {
    if (s.hollow) return spherical_shell(mass, s.radius);
    return s.inner_radius > 0.0 ? hollow_sphere(mass, s.radius, s.inner_radius)
                                : solid_sphere(mass, s.radius);
  }
  if (k == "cylinder") {
    return s.hollow ? cylindrical_shell(mass, s.radius, s.length)
                    : cylinder(mass, s.radius, s.length, s.inner_radius);
  }
  if (k == "cone") return cone(mass, s.radius, s.height);
  if (k == "ellipsoid") return ellipsoid(mass, s.size);
  if (k == "capsule") return capsule(mass, s.radius, s.length);
  return torus(mass, s.major_radius, s.minor_radius);
}

MassProperties shape_with_density(const ShapeSpec& s, double density) {
  const double measure = measure_of(s);
  if (s.kind == "point") {
    throw InvalidInput("point: a point mass has no density; expected a mass (kg)");
  }
  require_positive(fmt::format("{}: density", s.kind), density, density_unit(s));
  return shape_with_mass(s, density * measure);
}

}  // namespace poinsot::inertia
