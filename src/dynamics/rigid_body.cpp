#include "poinsot/dynamics/rigid_body.hpp"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::dynamics {
namespace {

/// Symmetric, PSD and triangle inequality, with a tolerance scaled by the trace.
void require_physical_inertia(const Mat3& J, const char* what) {
  require_finite(what, J);
  const double scale = std::max(J.trace(), 0.0);
  const double tol = 1e-12 * std::max(scale, 1e-300);
  if ((J - J.transpose()).cwiseAbs().maxCoeff() > tol) {
    throw InvalidInput(
        fmt::format("{}: tensor {} kg·m² is not symmetric; expected J = Jᵀ", what, format_matrix(J)));
  }
  const Vec3 m = Eigen::SelfAdjointEigenSolver<Mat3>(J, Eigen::EigenvaluesOnly).eigenvalues();
  if (!(scale > 0.0)) {
    throw InvalidInput(fmt::format("{}: tensor {} kg·m² has trace {}; expected a positive trace", what,
                                   format_matrix(J), scale));
  }
  if (m[0] < -tol) {
    throw InvalidInput(fmt::format("{}: principal moments {} kg·m² include a negative one; expected all >= 0",
                                   what, format_vector(m)));
  }
  if (m[0] + m[1] < m[2] - tol) {
    throw InvalidInput(
        fmt::format("{}: principal moments {} kg·m² violate the triangle inequality I1 + I2 >= I3 "
                    "(short by {})",
                    what, format_vector(m), format_number(m[2] - m[0] - m[1], 6)));
  }
}

}  // namespace

RigidBody RigidBody::from_principal_moments(const Vec3& moments) {
  require_finite("body: principal_moments", moments);
  for (int i = 0; i < 3; ++i) {
    if (!(moments[i] > 0.0)) {
      throw InvalidInput(
          fmt::format("body: principal_moments {} kg·m²: moment {} is {}; expected every moment > 0",
                      format_vector(moments), i + 1, moments[i]));
    }
  }
  RigidBody b;
  b.inertia_com_ = moments.asDiagonal();
  require_physical_inertia(b.inertia_com_, "body: principal_moments");
  b.derive();
  return b;
}

RigidBody RigidBody::from_inertia(const Mat3& inertia_com_body) {
  require_physical_inertia(inertia_com_body, "body: inertia");
  RigidBody b;
  b.inertia_com_ = 0.5 * (inertia_com_body + inertia_com_body.transpose());
  b.derive();
  if (!(b.principal_moments_[0] > 0.0)) {
    throw InvalidInput(
        fmt::format("body: inertia has principal moments {} kg·m²; expected all > 0 (a body with a "
                    "zero moment is a point mass or a thin rod, whose rotation about its axis is "
                    "undefined)",
                    format_vector(b.principal_moments_)));
  }
  return b;
}

RigidBody RigidBody::with_pivot(double mass, const Vec3& pivot_to_com_body) const {
  require_positive("body: mass", mass, "kg");
  require_finite("body: pivot_to_com (m)", pivot_to_com_body);
  RigidBody b = *this;
  b.mass_ = mass;
  b.pivot_to_com_ = pivot_to_com_body;
  b.has_pivot_ = true;
  b.derive();
  return b;
}

void RigidBody::derive() {
  const Vec3& d = pivot_to_com_;
  inertia_ = inertia_com_;
  if (has_pivot_) inertia_ += mass_ * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
  inertia_inverse_ = inertia_.inverse();
  poinsot_ = 0.5 * inertia_.trace() * Mat3::Identity() - inertia_;
  diagonal_ = inertia_(0, 1) == 0.0 && inertia_(0, 2) == 0.0 && inertia_(1, 2) == 0.0;
  if (diagonal_) {
    // Sort the diagonal ascending; the axes are a signed permutation with det = +1.
    Eigen::Vector3i idx(0, 1, 2);
    std::sort(idx.data(), idx.data() + 3, [&](int a, int c) { return inertia_(a, a) < inertia_(c, c); });
    principal_axes_.setZero();
    for (int k = 0; k < 3; ++k) {
      principal_moments_[k] = inertia_(idx[k], idx[k]);
      principal_axes_(idx[k], k) = 1.0;
    }
    if (principal_axes_.determinant() < 0.0) principal_axes_.col(2) *= -1.0;
  } else {
    const Eigen::SelfAdjointEigenSolver<Mat3> es(inertia_);
    principal_moments_ = es.eigenvalues();
    principal_axes_ = es.eigenvectors();
    if (principal_axes_.determinant() < 0.0) principal_axes_.col(2) *= -1.0;
  }
}

}  // namespace poinsot::dynamics
