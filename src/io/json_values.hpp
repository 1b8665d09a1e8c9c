#pragma once
// The JSON forms of the io layer's values, shared by the serialisers of every room (the robot files' check
// and inertia reports, summary.json of each kind of run, the Λ report, the view page's data): vectors as
// arrays, matrices row by row, a non-finite number as null (JSON has none).
#include <cmath>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "poinsot/core/types.hpp"

namespace poinsot::io::detail {

using json = nlohmann::ordered_json;

inline json vec(const Vec3& v) {
  return json::array({v[0], v[1], v[2]});
}

/// Row by row: m[i][j] = m(i, j).
inline json mat(const Mat3& m) {
  json rows = json::array();
  for (int i = 0; i < 3; ++i)
    rows.push_back(json::array({m(i, 0), m(i, 1), m(i, 2)}));
  return rows;
}

/// A finite number, or null.
inline json num(double x) {
  return std::isfinite(x) ? json(x) : json(nullptr);
}

inline json opt(const std::optional<double>& x) {
  return x ? num(*x) : json(nullptr);
}

/// A string, or null when empty.
inline json text_or_null(const std::string& s) {
  return s.empty() ? json(nullptr) : json(s);
}

}  // namespace poinsot::io::detail
