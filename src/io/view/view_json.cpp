// The pieces of view.html's data shared by its kinds of runs (see view_json.hpp).
#include "view_json.hpp"

#include <cstdint>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/io/view/view_page.hpp"

namespace poinsot::io::detail {

/// The equivalent box and ellipsoid, and the scenario's own surface (about the centre of mass, body axes)
/// when there is one: `surface` {vertices (x, y, z …), triangles (i, j, k …)} or null, and
/// `surface_triangles` (its count, also when it is over kViewSurfaceTrianglesMax and left out).
ViewJson shapes_json(const Mat3& inertia_com, double mass, const inertia::TriangleMesh* surface) {
  const EquivalentShapes s = equivalent_shapes(inertia_com, mass);
  ViewJson j = {{"box_half_extents", vec(s.box_half_extents)},
                {"ellipsoid_semi_axes", vec(s.ellipsoid_semi_axes)},
                {"axes", mat(s.axes)},
                {"surface", nullptr},
                {"surface_triangles", surface ? static_cast<long long>(surface->triangles.size()) : 0}};
  if (surface && static_cast<long long>(surface->triangles.size()) <= kViewSurfaceTrianglesMax) {
    std::vector<double> v;
    v.reserve(3 * surface->vertices.size());
    for (const Vec3& p : surface->vertices)
      for (int k = 0; k < 3; ++k)
        v.push_back(rounded_for_drawing(p[k]));
    std::vector<std::int32_t> t;
    t.reserve(3 * surface->triangles.size());
    for (const auto& tri : surface->triangles)
      t.insert(t.end(), tri.begin(), tri.end());
    j["surface"] = {{"vertices", v}, {"triangles", t}};
  }
  return j;
}

/// The numbers a page's frames may hold: InvalidInput beyond kViewValuesMax, naming the frames that fit.
void check_page_budget(const std::string& dir, long long frames, long long values_per_frame, int requested) {
  if (frames * values_per_frame <= kViewValuesMax) return;
  throw InvalidInput(fmt::format(
      "view: --frames {} gives {} frames × {} numbers = {} numbers for \"{}\", more than a page holds ({}); "
      "expected --frames ≤ {}",
      requested, frames, values_per_frame, frames * values_per_frame, dir, kViewValuesMax,
      kViewValuesMax / values_per_frame));
}

/// The columns `names` of every frame, frame after frame.
std::vector<double> gather(const CsvFrames& f, const std::vector<std::string>& names,
                           const std::string& path) {
  std::vector<std::size_t> idx;
  for (const auto& n : names)
    idx.push_back(csv_column(f, n, path));
  std::vector<double> out;
  out.reserve(f.values.size() * idx.size());
  for (const auto& row : f.values)
    for (std::size_t i : idx)
      out.push_back(row[i]);
  return out;
}

ViewJson frames_header(const CsvFrames& f, const std::string& path) {
  return {{"samples", f.rows},
          {"frames", static_cast<long long>(f.values.size())},
          {"stride", f.stride},
          {"t", gather(f, {"t"}, path)}};
}

}  // namespace poinsot::io::detail
