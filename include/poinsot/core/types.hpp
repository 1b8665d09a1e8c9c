#pragma once
/// @file types.hpp
/// The fixed-size linear-algebra types poinsot uses throughout (Eigen, double precision).

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace poinsot {

using Vec3 = Eigen::Vector3d;  ///< A 3-vector; its frame is named by the variable (omega_body, L_space, ...).
using Mat3 = Eigen::Matrix3d;  ///< A 3×3 matrix (rotation, inertia tensor, multiplier matrix Λ, ...).
using Quat = Eigen::Quaterniond;  ///< A unit quaternion (Hamilton convention, w + x i + y j + z k).

}  // namespace poinsot
