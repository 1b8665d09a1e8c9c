#include "poinsot/core/linear_solvers.hpp"

#include <utility>

#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>
#include <Eigen/SparseLU>

namespace poinsot {

Eigen::MatrixXd solve_col_piv_qr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
  return A.colPivHouseholderQr().solve(B);
}

Eigen::VectorXd solve_col_piv_qr(const Eigen::MatrixXd& A, const Eigen::VectorXd& b) {
  return A.colPivHouseholderQr().solve(b);
}

struct DenseLu::Impl {
  Eigen::PartialPivLU<Eigen::MatrixXd> lu;
};

DenseLu::DenseLu(const Eigen::MatrixXd& A)
    : impl_(std::make_unique<Impl>(Impl{Eigen::PartialPivLU<Eigen::MatrixXd>(A)})) {}
DenseLu::~DenseLu() = default;
DenseLu::DenseLu(DenseLu&&) noexcept = default;
DenseLu& DenseLu::operator=(DenseLu&&) noexcept = default;

Eigen::VectorXd DenseLu::solve(const Eigen::VectorXd& b) const {
  return impl_->lu.solve(b);
}

struct SparseLu::Impl {
  Eigen::SparseLU<Eigen::SparseMatrix<double>, Eigen::COLAMDOrdering<int>> lu;
};

SparseLu::SparseLu() : impl_(std::make_unique<Impl>()) {}
SparseLu::~SparseLu() = default;
SparseLu::SparseLu(SparseLu&&) noexcept = default;
SparseLu& SparseLu::operator=(SparseLu&&) noexcept = default;

void SparseLu::analyse_pattern(const Eigen::SparseMatrix<double>& A) {
  impl_->lu.analyzePattern(A);
}

bool SparseLu::factorise(const Eigen::SparseMatrix<double>& A) {
  impl_->lu.factorize(A);
  return impl_->lu.info() == Eigen::Success;
}

bool SparseLu::compute(const Eigen::SparseMatrix<double>& A) {
  impl_->lu.compute(A);
  return impl_->lu.info() == Eigen::Success;
}

Eigen::VectorXd SparseLu::solve(const Eigen::VectorXd& b) const {
  return impl_->lu.solve(b);
}

struct ThinSvd::Impl {
  // `mutable`: the threshold is a parameter of each solve, not a state of the decomposition.
  mutable Eigen::BDCSVD<Eigen::MatrixXd> svd;
};

ThinSvd::ThinSvd(const Eigen::MatrixXd& A)
    : impl_(std::make_unique<Impl>(
          Impl{Eigen::BDCSVD<Eigen::MatrixXd>(A, Eigen::ComputeThinU | Eigen::ComputeThinV)})) {}
ThinSvd::~ThinSvd() = default;
ThinSvd::ThinSvd(ThinSvd&&) noexcept = default;
ThinSvd& ThinSvd::operator=(ThinSvd&&) noexcept = default;

Eigen::VectorXd ThinSvd::solve(const Eigen::VectorXd& b, double relative_threshold) const {
  impl_->svd.setThreshold(relative_threshold);
  return impl_->svd.solve(b);
}

RightSingularVectors right_singular_vectors(const Eigen::MatrixXd& A) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(A, Eigen::ComputeFullV);
  return {svd.singularValues(), svd.matrixV()};
}

}  // namespace poinsot
