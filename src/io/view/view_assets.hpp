#pragma once
/// @file view_assets.hpp
/// The viewer's page, style and scripts (viewer/) and three.js (Debian's libjs-three), compiled into the
/// library as text by cmake/PoinsotViewer.cmake, so that view.html can be written with no file to find.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace poinsot::io {

/// The text of an embedded file named relative to viewer/ ("page.html", "js/scene.js", ...) or
/// "three.min.js"; nullopt when the build has no such file (three.min.js without libjs-three).
std::optional<std::string> view_asset(std::string_view name);

/// The total size (bytes) of every embedded file.
std::size_t view_assets_size();

}  // namespace poinsot::io
