#include "poinsot/optimal/reaction_wheels.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <string>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::optimal {

Mat3 bus_inertia(const Mat3& inertia_locked, const ReactionWheels& w) {
  return inertia_locked - w.axes_body * w.spin_inertia.asDiagonal() * w.axes_body.transpose();
}

Vec3 total_momentum_space(const Mat3& inertia_locked, const ReactionWheels& w, const Quat& q,
                          const Vec3& omega, const Vec3& h) {
  return q.toRotationMatrix() * (bus_inertia(inertia_locked, w) * omega + w.axes_body * h);
}

Vec3 wheel_momentum(const Mat3& inertia_locked, const ReactionWheels& w, const Vec3& L, const Quat& q,
                    const Vec3& omega) {
  return w.axes_body.partialPivLu().solve(q.toRotationMatrix().transpose() * L -
                                          bus_inertia(inertia_locked, w) * omega);
}

Vec3 wheel_speed(const ReactionWheels& w, const Vec3& h, const Vec3& omega) {
  return h.cwiseQuotient(w.spin_inertia) - w.axes_body.transpose() * omega;
}

void validate(const ReactionWheels& w, const Mat3& inertia_locked) {
  for (int k = 0; k < 3; ++k) {
    const Vec3 a = w.axes_body.col(k);
    if (!a.allFinite() || a.norm() == 0.0)
      throw InvalidInput(fmt::format("optimal_control.reaction_wheels.axes[{}]: {}; expected a nonzero axis",
                                     k + 1, format_vector(a)));
    if (std::abs(a.norm() - 1.0) > 1e-9)
      throw InvalidInput(
          fmt::format("optimal_control.reaction_wheels.axes[{}]: {} has norm {}; expected a "
                      "unit vector",
                      k + 1, format_vector(a), format_number(a.norm())));
  }
  if (!(std::abs(w.axes_body.determinant()) >= 1e-6))
    throw InvalidInput(
        fmt::format("optimal_control.reaction_wheels.axes: det A = {}; expected three "
                    "independent spin axes (|det A| ≥ 1e-6)",
                    format_number(w.axes_body.determinant())));
  if (!w.spin_inertia.allFinite() || !(w.spin_inertia.minCoeff() > 0.0))
    throw InvalidInput(
        fmt::format("optimal_control.reaction_wheels.spin_inertia: {} kg·m²; expected finite "
                    "positive axial inertias",
                    format_vector(w.spin_inertia)));
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(bus_inertia(inertia_locked, w));
  if (!(eig.eigenvalues()[0] > 1e-12 * eig.eigenvalues()[2]))
    throw InvalidInput(fmt::format(
        "optimal_control.reaction_wheels.spin_inertia: {} kg·m² leaves the bus the principal moments {} "
        "kg·m²; expected the wheels' axial inertia to be part of the spacecraft's inertia (J − A diag(I) Aᵀ "
        "positive definite)",
        format_vector(w.spin_inertia), format_vector(eig.eigenvalues())));
  if (std::isnan(w.momentum_max.sum()) || !(w.momentum_max.minCoeff() > 0.0))
    throw InvalidInput(
        fmt::format("optimal_control.reaction_wheels.momentum_max: {} N·m·s; expected "
                    "positive bounds (or none)",
                    format_vector(w.momentum_max)));
  if (!w.momentum_initial.allFinite())
    throw InvalidInput(
        fmt::format("optimal_control.reaction_wheels.momentum_initial: {} N·m·s; expected "
                    "finite values",
                    format_vector(w.momentum_initial)));
  for (int k = 0; k < 3; ++k)
    if (std::abs(w.momentum_initial[k]) > w.momentum_max[k])
      throw InvalidInput(
          fmt::format("optimal_control.reaction_wheels.momentum_max: {} N·m·s is below the "
                      "initial |h_{}| = {} N·m·s; expected bounds the start meets",
                      format_vector(w.momentum_max), k + 1, format_number(std::abs(w.momentum_initial[k]))));
}

}  // namespace poinsot::optimal
