#pragma once
/// @file path_inequality_nlp.hpp (internal)
/// A collocation NLP (hermite_simpson_nlp.hpp) with path inequalities added: lower ≤ c(w_p) ≤ upper at every
/// collocation point p but the first (whose state is given), for point functions c of the model's point
/// variables. The rows come after the base NLP's; the variables, the bounds on them and the objective are
/// the base's. Used for the bounds on joint rates of the multibody transcriptions (multibody_direct.cpp).
/// Entries of the Hessian may repeat the base's positions: Ipopt sums repeated triplets.
#include <vector>

#include "hermite_simpson_nlp.hpp"

namespace poinsot::optimal::detail {

class PathInequalityNlp final : public SparseNlp {
 public:
  /// `rows` must outlive this object; lower and upper have one entry per row of `rows`.
  PathInequalityNlp(const HermiteSimpsonNlp& base, const PointFunctions& rows, std::vector<double> lower,
                    std::vector<double> upper);

  int num_variables() const override { return base_.num_variables(); }
  int num_constraints() const override;
  void bounds(std::vector<double>& x_lower, std::vector<double>& x_upper, std::vector<double>& g_lower,
              std::vector<double>& g_upper) const override;
  double objective(const double* x) const override { return base_.objective(x); }
  void objective_gradient(const double* x, double* gradient) const override {
    base_.objective_gradient(x, gradient);
  }
  void constraints(const double* x, double* g) const override;
  int jacobian_nonzeros() const override;
  void jacobian_structure(int* rows, int* cols) const override;
  void jacobian_values(const double* x, double* values) const override;
  int hessian_nonzeros() const override;
  void hessian_structure(int* rows, int* cols) const override;
  void hessian_values(const double* x, double sigma, const double* y, double* values) const override;

 private:
  int constrained_points() const { return base_.points() - 1; }  ///< points 1 … 2N
  const double* point(const double* x, int k) const { return x + base_.model().point_size() * (k + 1); }

  const HermiteSimpsonNlp& base_;
  const PointFunctions& rows_;
  std::vector<double> lower_, upper_;
};

}  // namespace poinsot::optimal::detail
