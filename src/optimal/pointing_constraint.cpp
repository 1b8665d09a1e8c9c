// Attitude path constraints (pointing_constraint.hpp).
#include "poinsot/optimal/pointing_constraint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::optimal {

std::string_view pointing_kind_name(PointingKind kind) {
  return kind == PointingKind::keep_out ? "keep_out" : "keep_in";
}

double PointingConstraint::cosine(const Quat& attitude) const {
  return direction_space.dot(attitude * boresight_body);
}

double PointingConstraint::angle(const Quat& attitude) const {
  return angle(Mat3(attitude.toRotationMatrix()));
}

double PointingConstraint::angle(const Mat3& R_space_body) const {
  // atan2 of ‖s × Rb‖ and s·Rb: accurate near 0 and π, where arccos loses half the digits.
  const Vec3 d = R_space_body * boresight_body;
  return std::atan2(direction_space.cross(d).norm(), direction_space.dot(d));
}

double PointingConstraint::margin(const Quat& attitude) const {
  return margin(Mat3(attitude.toRotationMatrix()));
}

double PointingConstraint::margin(const Mat3& R_space_body) const {
  const double phi = angle(R_space_body);
  return kind == PointingKind::keep_out ? phi - half_angle : half_angle - phi;
}

Eigen::Matrix4d rotation_bilinear_form(const Vec3& b, const Vec3& s) {
  const double sb = s.dot(b);
  const Vec3 bxs = b.cross(s);
  Eigen::Matrix4d A;
  A(0, 0) = sb;
  A.block<3, 1>(1, 0) = bxs;
  A.block<1, 3>(0, 1) = bxs.transpose();
  A.block<3, 3>(1, 1) = b * s.transpose() + s * b.transpose() - sb * Mat3::Identity();
  return A;
}

Eigen::Matrix4d PointingConstraint::quadratic_form() const {
  return rotation_bilinear_form(boresight_body, direction_space);
}

PointingConstraint PointingConstraint::widened(double delta) const {
  PointingConstraint c = *this;
  c.half_angle += kind == PointingKind::keep_out ? delta : -delta;
  return c;
}

std::string PointingConstraint::label() const {
  return name.empty() ? std::string(pointing_kind_name(kind))
                      : fmt::format("{} \"{}\"", pointing_kind_name(kind), name);
}

void validate(const PointingConstraint& c, std::string_view field) {
  for (const auto& [key, v] : {std::pair<const char*, const Vec3&>{"boresight_body", c.boresight_body},
                               std::pair<const char*, const Vec3&>{"direction_space", c.direction_space}})
    if (!v.allFinite() || std::abs(v.norm() - 1.0) > 1e-9)
      throw InvalidInput(fmt::format("{}.{}: got {} (norm {}), expected a unit vector", field, key,
                                     format_vector(v), format_number(v.norm())));
  if (!(c.half_angle > 0.0 && c.half_angle < std::numbers::pi))
    throw InvalidInput(fmt::format("{}.half_angle: got {} rad, expected 0 < half_angle < π", field,
                                   format_number(c.half_angle)));
}

double PointingMargins::worst() const {
  double w = std::numeric_limits<double>::infinity();
  for (const double m : margin)
    w = std::min(w, m);
  return w;
}

void PointingMargins::reset(const std::vector<PointingConstraint>& constraints) {
  if (margin.size() == constraints.size()) return;
  margin.assign(constraints.size(), std::numeric_limits<double>::infinity());
  time.assign(constraints.size(), 0.0);
}

void PointingMargins::lower(const std::vector<PointingConstraint>& constraints, double t, const Quat& q) {
  reset(constraints);
  for (std::size_t c = 0; c < constraints.size(); ++c)
    if (const double m = constraints[c].margin(q); !(m >= margin[c])) {
      margin[c] = m;
      time[c] = t;
    }
}

void PointingMargins::lower_along(const std::vector<PointingConstraint>& constraints, double t0,
                                  const Quat& q0, const Vec3& omega0, double t1, const Quat& q1_in,
                                  const Vec3& omega1, int samples) {
  if (constraints.empty()) return;
  const double h = t1 - t0;
  // q1 on q0's side (q and −q are one attitude); q̇ = ½ q ⊗ (0, ω).
  const Quat q1 = q0.coeffs().dot(q1_in.coeffs()) < 0.0 ? Quat(-q1_in.coeffs()) : q1_in;
  const Eigen::Vector4d a = q0.coeffs(), b = q1.coeffs();
  const Eigen::Vector4d da = (q0 * Quat(0.0, omega0.x(), omega0.y(), omega0.z())).coeffs() * (0.5 * h);
  const Eigen::Vector4d db = (q1 * Quat(0.0, omega1.x(), omega1.y(), omega1.z())).coeffs() * (0.5 * h);
  for (int i = 1; i <= samples; ++i) {
    const double s = static_cast<double>(i) / samples, s2 = s * s, s3 = s2 * s;
    const Eigen::Vector4d v =
        (2 * s3 - 3 * s2 + 1) * a + (s3 - 2 * s2 + s) * da + (-2 * s3 + 3 * s2) * b + (s3 - s2) * db;
    Quat q;
    q.coeffs() = v.normalized();
    lower(constraints, i == samples ? t1 : t0 + s * h, q);
  }
}

}  // namespace poinsot::optimal
