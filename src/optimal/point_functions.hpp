#pragma once
/// @file point_functions.hpp (internal)
/// A vector of scalar functions c(w) of the variables w of one collocation point, with a fixed sparsity
/// pattern for the Jacobian ∂c/∂w and for the lower triangle of the Hessian of a weighted sum Σ_r y_r ∇²c_r.
/// The collocation engine (hermite_simpson_nlp.hpp) assembles the NLP from these; the rotation-matrix model
/// implements them as polynomials of degree 2 (QuadraticFunctions below), the minimal-coordinate model by
/// forward automatic differentiation.
#include <utility>
#include <vector>

namespace poinsot::optimal::detail {

using IndexPair = std::pair<int, int>;

class PointFunctions {
 public:
  virtual ~PointFunctions() = default;
  virtual int rows() const = 0;
  virtual void values(const double* w, double* out) const = 0;
  /// (row, variable) pairs of the structural non-zeros of ∂c/∂w.
  virtual const std::vector<IndexPair>& jacobian_pattern() const = 0;
  virtual void jacobian_values(const double* w, double* values) const = 0;
  /// (i, j) pairs, i ≥ j, of the structural non-zeros of ∇²c_r for any r.
  virtual const std::vector<IndexPair>& hessian_pattern() const = 0;
  /// Σ_r weights_r ∇²c_r(w) on hessian_pattern().
  virtual void hessian_values(const double* w, const double* weights, double* values) const = 0;
};

/// Scalar functions each a polynomial of degree ≤ 2 in w: c_r(w) = k_r + Σ a w_i + Σ b w_i w_j. Their
/// Jacobian is affine in w and their Hessians are constant, so both are exact by construction. Build with the
/// add_ functions, then call finish() once before evaluating.
class QuadraticFunctions final : public PointFunctions {
 public:
  int add_row();
  void add_constant(int row, double k);
  void add_linear(int row, int var, double a);
  void add_bilinear(int row, int i, int j, double b);  ///< b w_i w_j (i = j allowed)
  void finish();

  int rows() const override { return static_cast<int>(constant_.size()); }
  void values(const double* w, double* out) const override;
  const std::vector<IndexPair>& jacobian_pattern() const override { return jac_pattern_; }
  void jacobian_values(const double* w, double* values) const override;
  const std::vector<IndexPair>& hessian_pattern() const override { return hess_pattern_; }
  void hessian_values(const double* w, const double* weights, double* values) const override;

 private:
  struct Linear {
    int row, var;
    double a;
  };
  struct Bilinear {
    int row, i, j;
    double b;
  };
  struct JacobianTerm {  // values[entry] += coefficient · w[var]
    int entry, var;
    double coefficient;
  };
  struct HessianTerm {  // values[entry] += coefficient · weights[row]
    int entry, row;
    double coefficient;
  };
  std::vector<double> constant_;
  std::vector<Linear> linear_;
  std::vector<Bilinear> bilinear_;
  std::vector<IndexPair> jac_pattern_, hess_pattern_;
  std::vector<double> jac_constant_;
  std::vector<JacobianTerm> jac_terms_;
  std::vector<HessianTerm> hess_terms_;
};

}  // namespace poinsot::optimal::detail
