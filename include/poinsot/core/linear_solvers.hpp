#pragma once
/// @file linear_solvers.hpp
/// Linear solves of dynamic size, each compiled once (src/core/linear_solvers.cpp). Eigen's decompositions of
/// dynamic size cost several seconds of compile time in every file that names one, and more under the
/// sanitizers (docs/measurements/ci_time.md), so the library and its tests call them through these. Each does
/// exactly what the Eigen call it names does, so results are the same to the bit.

#include <memory>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace poinsot {

/// The least-squares solution X of A X = B by Householder QR with column pivoting (Eigen's
/// `A.colPivHouseholderQr().solve(B)`): the solution for a square invertible A; for a rank-deficient or
/// rectangular A, a basic least-squares solution (rank decided at Eigen's default threshold).
Eigen::MatrixXd solve_col_piv_qr(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B);
/// As above, for one right-hand side (Eigen's matrix-vector path).
Eigen::VectorXd solve_col_piv_qr(const Eigen::MatrixXd& A, const Eigen::VectorXd& b);

/// A = P⁻¹ L U, the LU factorisation with partial (row) pivoting of a square invertible A (Eigen's
/// PartialPivLU), kept for several right-hand sides. A singular A gives infinite or NaN solutions: the
/// caller checks them.
class DenseLu {
 public:
  explicit DenseLu(const Eigen::MatrixXd& A);
  ~DenseLu();
  DenseLu(DenseLu&&) noexcept;
  DenseLu& operator=(DenseLu&&) noexcept;
  DenseLu(const DenseLu&) = delete;
  DenseLu& operator=(const DenseLu&) = delete;

  /// x = A⁻¹ b.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The LU factorisation of a square sparse matrix with COLAMD column ordering (Eigen's SparseLU). The
/// pattern's analysis is kept: `factorise` of a matrix with the pattern of the last `analyse_pattern` reuses
/// it.
class SparseLu {
 public:
  SparseLu();
  ~SparseLu();
  SparseLu(SparseLu&&) noexcept;
  SparseLu& operator=(SparseLu&&) noexcept;
  SparseLu(const SparseLu&) = delete;
  SparseLu& operator=(const SparseLu&) = delete;

  /// The ordering and elimination tree of A's pattern.
  void analyse_pattern(const Eigen::SparseMatrix<double>& A);
  /// The numerical factorisation of A (the pattern analysed last); false when it fails (a structurally or
  /// numerically singular A: SparseLU does not pivot for rank).
  bool factorise(const Eigen::SparseMatrix<double>& A);
  /// analyse_pattern and factorise.
  bool compute(const Eigen::SparseMatrix<double>& A);
  /// x = A⁻¹ b with the last successful factorisation.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// A = U Σ Vᵀ, the thin singular value decomposition of a dense A by Eigen's divide-and-conquer SVD
/// (`BDCSVD<MatrixXd>(A, ComputeThinU | ComputeThinV)`), kept for least-squares solves that leave out the
/// small singular values.
class ThinSvd {
 public:
  explicit ThinSvd(const Eigen::MatrixXd& A);
  ~ThinSvd();
  ThinSvd(ThinSvd&&) noexcept;
  ThinSvd& operator=(ThinSvd&&) noexcept;
  ThinSvd(const ThinSvd&) = delete;
  ThinSvd& operator=(const ThinSvd&) = delete;

  /// The minimum-norm least-squares solution x = V Σ⁺ Uᵀ b, where Σ⁺ inverts only the singular values above
  /// `relative_threshold` × the largest and sets the others to zero (Eigen's `setThreshold` then `solve`).
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b, double relative_threshold) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// The singular values of A, non-increasing, and the full n×n matrix V of its right singular vectors
/// (A = U Σ Vᵀ), by Eigen's two-sided Jacobi SVD (`JacobiSVD<MatrixXd>(A, ComputeFullV)`; QR-preconditioned,
/// accurate to round-off relative to the largest singular value).
struct RightSingularVectors {
  Eigen::VectorXd singular_values;
  Eigen::MatrixXd V;
};
RightSingularVectors right_singular_vectors(const Eigen::MatrixXd& A);

}  // namespace poinsot
