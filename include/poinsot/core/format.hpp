#pragma once
/// @file format.hpp
/// Text forms of numbers, vectors and matrices for error messages and reports: shortest round-trip
/// representation of each double ("0.1", "1e-08"), vectors as "(x, y, z)", matrices row by row.

#include <string>

#include "poinsot/core/types.hpp"

namespace poinsot {

/// Shortest text that reads back to the same double ("1", "0.25", "1e-08", "nan", "inf").
std::string format_number(double value);
/// A number printed with `digits` significant digits ("%.{digits}g").
std::string format_number(double value, int digits);
/// "(x, y, z)" with each entry as format_number.
std::string format_vector(const Vec3& v);
/// "[[a, b, c], [d, e, f], [g, h, i]]", row by row.
std::string format_matrix(const Mat3& m);
/// "(w, x, y, z)".
std::string format_quaternion(const Quat& q);

}  // namespace poinsot
