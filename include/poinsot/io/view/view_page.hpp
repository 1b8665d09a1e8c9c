#pragma once
/// @file view_page.hpp
/// view.html: one self-contained web page that shows a finished run in 3-D (docs/viewer.md). The page holds
/// the run's data (JSON) and its scripts (viewer/ and three.js from Debian's libjs-three) inline: it opens
/// from disk in any browser with no server and no network.
///
/// Data: the frames of trajectory.csv (every row, or every k-th row and the last when there are more rows
/// than `frames`; the page interpolates between frames, the orientation by slerp), summary.json's body and
/// invariants, and the model from the scenario file when it can still be read (mass, pivot, gravity; for
/// multibody files every body's inertia and the joints). Numbers are written as the shortest text that reads
/// back to the same double, so the page's frames equal trajectory.csv's rows exactly.
///
/// Size: at most view_page_size_bound(frames, values_per_frame, bodies) bytes: the scripts, plus 25 bytes for
/// every number of every frame (the longest shortest-round-trip double has 24 characters, plus a comma).

#include <cstddef>
#include <string>

namespace poinsot::io {

inline constexpr int kViewFramesDefault = 2000;       ///< default most frames in a page
inline constexpr int kViewFramesMin = 2;              ///< fewest frames a page may ask for
inline constexpr int kViewFramesMax = 100000;         ///< most frames a page may ask for
inline constexpr long long kViewValuesMax = 2000000;  ///< most numbers in a page's frames (≤ 50 MB of text)
/// Most triangles of a body's surface (shape or mesh from the scenario) drawn in a page; a larger mesh is
/// drawn as the equivalent box (the page says so).
inline constexpr long long kViewSurfaceTrianglesMax = 10000;

struct ViewOptions {
  /// Most frames in the page, in [kViewFramesMin, kViewFramesMax]; longer runs are decimated.
  int frames = kViewFramesDefault;
  /// The scenario file that made the run (for the model); empty: the path recorded in summary.json, used
  /// only if it still reads and matches the run.
  std::string scenario_path;
};

/// Throws InvalidInput unless `options.frames` is in [kViewFramesMin, kViewFramesMax] (for a front end that
/// checks its options before a run).
void check_view_options(const ViewOptions& options);

/// The page's data as JSON (the keys are listed in docs/viewer.md) from the folder of a finished run
/// (summary.json and trajectory.csv of `poinsot run`; diagnostics.csv of a multibody run when present).
/// Throws InvalidInput (one line) when the folder holds no finished run, when `frames` is out of range, or
/// when frames × numbers per frame exceeds kViewValuesMax (the message says which `frames` would fit).
std::string view_data_json(const std::string& run_dir, const ViewOptions& options = {});

/// The whole page: the template viewer/page.html with the style, three.js, the viewer's scripts and the data
/// inlined. Throws as view_data_json, and InvalidInput when the build has no three.js (libjs-three).
std::string view_page_html(const std::string& run_dir, const ViewOptions& options = {});

/// Writes `run_dir`/view.html atomically (temporary file, then rename) and returns its path. Nothing is
/// written when it throws (as view_page_html).
std::string write_view_page(const std::string& run_dir, const ViewOptions& options = {});

/// An upper bound of the size (bytes) of a page of `frames` frames with `values_per_frame` numbers each
/// (12 for a single body: t, q, ω, energy, L; for a multibody file 1 + 10 per body, + 1 with
/// diagnostics.csv; with the model 6 per joint and per body more) and `bodies` bodies whose drawn surfaces
/// have `surface_triangles` triangles in all: the embedded scripts, 8 KiB + 2 KiB per body of other data,
/// 25 bytes per number and kSurfaceBytesPerTriangle per surface triangle.
std::size_t view_page_size_bound(long long frames, long long values_per_frame, long long bodies = 1,
                                 long long surface_triangles = 0);

/// Bytes of page per triangle of a drawn surface: its 3 indices (at most 11 characters each) and at most 3
/// vertices of 3 numbers of 9 digits (at most 16 characters each), with commas: 36 + 144.
inline constexpr std::size_t kSurfaceBytesPerTriangle = 180;

}  // namespace poinsot::io
