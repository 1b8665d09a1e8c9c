#include "poinsot/inertia/tessellation.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::inertia {
namespace {

/// Arc of a circle of centre (rc, zc) and radius a from angle t0 to t1 in `n` pieces, appended to `p`
/// without its first point (which the previous piece already placed) unless `first`.
void arc(std::vector<Eigen::Vector2d>& p, double rc, double zc, double a, double t0, double t1, int n,
         bool first) {
  for (int i = first ? 0 : 1; i <= n; ++i) {
    const double t = t0 + (t1 - t0) * i / n;
    double r = rc + a * std::cos(t);
    if (std::abs(r) < 1e-15 * a) r = 0.0;  // the poles lie exactly on the axis
    p.emplace_back(r, zc + a * std::sin(t));
  }
}

void line(std::vector<Eigen::Vector2d>& p, const Eigen::Vector2d& to, int n) {
  const Eigen::Vector2d from = p.back();
  for (int i = 1; i <= n; ++i)
    p.push_back(from + (to - from) * (static_cast<double>(i) / n));
}

void append(TriangleMesh& into, const TriangleMesh& part, bool reversed) {
  const auto offset = static_cast<std::int32_t>(into.vertices.size());
  into.vertices.insert(into.vertices.end(), part.vertices.begin(), part.vertices.end());
  for (auto t : part.triangles) {
    for (auto& i : t)
      i += offset;
    if (reversed) std::swap(t[1], t[2]);
    into.triangles.push_back(t);
  }
}

std::vector<Eigen::Vector2d> sphere_profile(double radius, int rings) {
  std::vector<Eigen::Vector2d> p;
  arc(p, 0.0, 0.0, radius, -std::numbers::pi / 2, std::numbers::pi / 2, rings, true);
  return p;
}

}  // namespace

TriangleMesh revolve(const std::vector<Eigen::Vector2d>& profile, int segments, bool closed_loop) {
  if (segments < 3) throw InvalidInput(fmt::format("tessellation: segments {}; expected >= 3", segments));
  if (profile.size() < 2) throw InvalidInput("tessellation: profile has fewer than 2 points; expected >= 2");
  TriangleMesh m;
  const auto n = static_cast<std::size_t>(segments);
  std::vector<std::vector<std::int32_t>> rings;
  for (const auto& q : profile) {
    std::vector<std::int32_t> ring(n);
    if (q.x() == 0.0) {
      const auto idx = static_cast<std::int32_t>(m.vertices.size());
      m.vertices.emplace_back(0.0, 0.0, q.y());
      std::fill(ring.begin(), ring.end(), idx);
    } else {
      for (std::size_t j = 0; j < n; ++j) {
        const double phi = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(n);
        ring[j] = static_cast<std::int32_t>(m.vertices.size());
        m.vertices.emplace_back(q.x() * std::cos(phi), q.x() * std::sin(phi), q.y());
      }
    }
    rings.push_back(std::move(ring));
  }
  const std::size_t pieces = closed_loop ? profile.size() : profile.size() - 1;
  for (std::size_t i = 0; i < pieces; ++i) {
    const auto& lo = rings[i];
    const auto& hi = rings[(i + 1) % rings.size()];
    for (std::size_t j = 0; j < n; ++j) {
      const std::size_t k = (j + 1) % n;
      const std::array<std::int32_t, 3> t1{lo[j], lo[k], hi[k]};
      const std::array<std::int32_t, 3> t2{lo[j], hi[k], hi[j]};
      for (const auto& t : {t1, t2}) {
        if (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]) m.triangles.push_back(t);
      }
    }
  }
  return m;
}

TriangleMesh box_mesh(const Vec3& size) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i) {
    m.vertices.emplace_back((i & 1 ? 0.5 : -0.5) * size.x(), (i & 2 ? 0.5 : -0.5) * size.y(),
                            (i & 4 ? 0.5 : -0.5) * size.z());
  }
  // Outward, counter-clockwise seen from outside.
  m.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                 {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return m;
}

TriangleMesh tessellate(const ShapeSpec& s, int segments) {
  (void)shape_measure(s);  // validates the sizes
  const int rings = std::max(2, segments / 2);
  const std::string& k = s.kind;
  if (s.hollow) {
    throw InvalidInput(
        fmt::format("tessellation: a thin {} shell is a surface; give inner_radius for a solid", k));
  }
  if (k == "box") return box_mesh(s.size);
  if (k == "sphere" || k == "ellipsoid") {
    const double r = k == "sphere" ? s.radius : 1.0;
    TriangleMesh m = revolve(sphere_profile(r, rings), segments);
    if (k == "ellipsoid") {
      for (auto& v : m.vertices)
        v = v.cwiseProduct(s.size);
    } else if (s.inner_radius > 0.0) {
      append(m, revolve(sphere_profile(s.inner_radius, rings), segments), true);
    }
    return m;
  }
  if (k == "cylinder") {
    const double h = 0.5 * s.length;
    std::vector<Eigen::Vector2d> p;
    if (s.inner_radius > 0.0) {
      p = {{s.inner_radius, -h}, {s.radius, -h}, {s.radius, h}, {s.inner_radius, h}};
      return revolve(p, segments, true);
    }
    p = {{0.0, -h}, {s.radius, -h}, {s.radius, h}, {0.0, h}};
    return revolve(p, segments);
  }
  if (k == "cone") {
    std::vector<Eigen::Vector2d> p{{0.0, -0.25 * s.height}, {s.radius, -0.25 * s.height}};
    line(p, Eigen::Vector2d(0.0, 0.75 * s.height), rings);  // a straight generator needs no refinement,
    return revolve(p, segments);                            // but more rings keep the triangles well shaped
  }
  if (k == "capsule") {
    const double h = 0.5 * s.length;
    std::vector<Eigen::Vector2d> p;
    arc(p, 0.0, -h, s.radius, -std::numbers::pi / 2, 0.0, std::max(1, rings / 2), true);
    line(p, Eigen::Vector2d(s.radius, h), 1);
    arc(p, 0.0, h, s.radius, 0.0, std::numbers::pi / 2, std::max(1, rings / 2), false);
    return revolve(p, segments);
  }
  if (k == "torus") {
    std::vector<Eigen::Vector2d> p;
    arc(p, s.major_radius, 0.0, s.minor_radius, 0.0, 2.0 * std::numbers::pi, segments, true);
    p.pop_back();  // the loop closes on its first point
    return revolve(p, segments, true);
  }
  throw InvalidInput(
      fmt::format("tessellation: a {} has no volume to tessellate; expected box, sphere, "
                  "cylinder, cone, ellipsoid, capsule or torus",
                  k));
}

}  // namespace poinsot::inertia
