#pragma once
/// @file point_masses.hpp
/// A body made of point masses, for tests whose oracle is a sum over the points: the inertia tensor about the
/// origin, J = Σ mᵢ (|xᵢ|² I − xᵢ xᵢᵀ) (kg·m²), with xᵢ in the body frame (m).

#include <vector>

#include "poinsot/core/types.hpp"

namespace poinsot::test {

/// One point: its mass (kg) and its position in the body frame, about the origin (m).
struct PointMass {
  double m;
  Vec3 x;
};

/// The inertia tensor of the points about the origin, in the body frame (kg·m²).
inline Mat3 inertia_about_origin(const std::vector<PointMass>& points) {
  Mat3 J = Mat3::Zero();
  for (const PointMass& p : points)
    J += p.m * (p.x.squaredNorm() * Mat3::Identity() - p.x * p.x.transpose());
  return J;
}

}  // namespace poinsot::test
