#pragma once
/// @file view_json.hpp
/// The pieces of view.html's data (view_page.hpp, docs/viewer.md) shared by its kinds of runs (a body, a
/// multibody file, an optimal manoeuvre): a body's drawn shapes, the frames'
/// columns and the page's budget of numbers. Internal to the io layer.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/json_values.hpp"  // vec, mat: the io layer's JSON forms of vectors and matrices
#include "poinsot/core/types.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "view_data.hpp"

namespace poinsot::io::detail {

using ViewJson = nlohmann::ordered_json;

/// The equivalent box and ellipsoid of `inertia_com` (J about the centre of mass, body frame) and `mass`, and
/// the scenario's own surface (about the centre of mass, body axes) when there is one: `surface` {vertices
/// (x, y, z …), triangles (i, j, k …)} or null, and `surface_triangles` (its count, also when it is over
/// kViewSurfaceTrianglesMax and left out).
ViewJson shapes_json(const Mat3& inertia_com, double mass, const inertia::TriangleMesh* surface);

/// The numbers a page's frames may hold: InvalidInput beyond kViewValuesMax, naming the frames that fit.
void check_page_budget(const std::string& dir, long long frames, long long values_per_frame, int requested);

/// The columns `names` of every frame, frame after frame. Throws InvalidInput naming a missing column.
std::vector<double> gather(const CsvFrames& f, const std::vector<std::string>& names,
                           const std::string& path);

/// samples, frames, stride and the frames' times t.
ViewJson frames_header(const CsvFrames& f, const std::string& path);

}  // namespace poinsot::io::detail
