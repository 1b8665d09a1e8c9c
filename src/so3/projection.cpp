#include "poinsot/so3/projection.hpp"

#include <fmt/format.h>
#include <Eigen/SVD>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::so3 {

double orthogonality_error(const Mat3& R) {
  return orthogonality_defect(R).norm();
}

Mat3 project_to_so3(const Mat3& M, double max_orthogonality_error) {
  require_finite("project_to_so3: matrix", M);
  const double det = M.determinant();
  if (!(det > 0.0)) {
    throw InvalidInput(
        fmt::format("project_to_so3: matrix {} has determinant {:.6g}; expected det > 0 (a "
                    "reflection or a singular matrix is not a perturbed rotation)",
                    format_matrix(M), det));
  }
  const double err = orthogonality_error(M);
  if (!(err <= max_orthogonality_error)) {
    throw InvalidInput(
        fmt::format("project_to_so3: matrix {} is too far from orthogonal (|M^T M - I| = {:.3g}); "
                    "expected at most {:.3g}",
                    format_matrix(M), err, max_orthogonality_error));
  }
  const Eigen::JacobiSVD<Mat3> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Mat3 u = svd.matrixU();
  const Mat3& v = svd.matrixV();
  if ((u * v.transpose()).determinant() < 0.0) u.col(2) = -u.col(2);
  Mat3 q = u * v.transpose();
  // The Jacobi SVD leaves U and V orthogonal to ~10 ulp; one step of Björck's iteration
  // Q ← Q − ½Q(QᵀQ − I), quadratically convergent, brings Q to round-off.
  bjorck_step(q);
  return q;
}

}  // namespace poinsot::so3
