#pragma once
/// @file errata_cases.hpp
/// The worked axisymmetric cases of docs/conventions.md, shared by the analysis tests (SI units, R(0) = I,
/// the symmetry axis along body z): case b, prolate (A = 2, C = 1 kg·m²), and case c, oblate (A = 1, C = 1.8
/// kg·m²), each with its initial body angular velocity in rad/s.

#include "poinsot/analysis/axisymmetric.hpp"
#include "poinsot/core/types.hpp"

namespace poinsot::analysis::errata {

inline const AxisymmetricInertia kCaseB{2.0, 1.0, Vec3::UnitZ()};  ///< prolate
inline const Vec3 kOmegaB(0.3, -0.4, 1.2);
inline const AxisymmetricInertia kCaseC{1.0, 1.8, Vec3::UnitZ()};  ///< oblate
inline const Vec3 kOmegaC(1.0, 0.5, -2.0);

}  // namespace poinsot::analysis::errata
