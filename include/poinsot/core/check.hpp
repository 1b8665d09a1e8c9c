#pragma once
/// @file check.hpp
/// Validation of input values. Each function throws poinsot::InvalidInput with a one-line message naming
/// the field, the value received and what was expected; `what` is the field's name as the user knows it,
/// e.g. "so3::exp: rotation vector" or "box: size".

#include <string_view>

#include "poinsot/core/types.hpp"

namespace poinsot {

/// Throws unless `value` is finite.
void require_finite(std::string_view what, double value);
/// Throws unless every entry of `v` is finite.
void require_finite(std::string_view what, const Vec3& v);
/// Throws unless every entry of `m` is finite.
void require_finite(std::string_view what, const Mat3& m);
/// Throws unless every coefficient of `q` is finite.
void require_finite(std::string_view what, const Quat& q);
/// Throws unless `value` is finite and strictly positive; `unit` is printed after the value (e.g. "kg").
void require_positive(std::string_view what, double value, std::string_view unit = "");
/// Throws unless `value` is finite and >= 0.
void require_non_negative(std::string_view what, double value, std::string_view unit = "");

}  // namespace poinsot
