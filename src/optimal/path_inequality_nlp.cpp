// A collocation NLP with path inequalities added (path_inequality_nlp.hpp).
#include "path_inequality_nlp.hpp"

namespace poinsot::optimal::detail {

PathInequalityNlp::PathInequalityNlp(const HermiteSimpsonNlp& base, const PointFunctions& rows,
                                     std::vector<double> lower, std::vector<double> upper)
    : base_(base), rows_(rows), lower_(std::move(lower)), upper_(std::move(upper)) {}

int PathInequalityNlp::num_constraints() const {
  return base_.num_constraints() + rows_.rows() * constrained_points();
}

void PathInequalityNlp::bounds(std::vector<double>& xl, std::vector<double>& xu, std::vector<double>& gl,
                               std::vector<double>& gu) const {
  base_.bounds(xl, xu, gl, gu);
  for (int k = 0; k < constrained_points(); ++k) {
    gl.insert(gl.end(), lower_.begin(), lower_.end());
    gu.insert(gu.end(), upper_.begin(), upper_.end());
  }
}

void PathInequalityNlp::constraints(const double* x, double* g) const {
  base_.constraints(x, g);
  double* out = g + base_.num_constraints();
  for (int k = 0; k < constrained_points(); ++k, out += rows_.rows())
    rows_.values(point(x, k), out);
}

int PathInequalityNlp::jacobian_nonzeros() const {
  return base_.jacobian_nonzeros() + static_cast<int>(rows_.jacobian_pattern().size()) * constrained_points();
}

void PathInequalityNlp::jacobian_structure(int* rows, int* cols) const {
  base_.jacobian_structure(rows, cols);
  std::size_t e = static_cast<std::size_t>(base_.jacobian_nonzeros());
  const int nw = base_.model().point_size();
  for (int k = 0; k < constrained_points(); ++k) {
    for (const auto& [r, v] : rows_.jacobian_pattern()) {
      rows[e] = base_.num_constraints() + rows_.rows() * k + r;
      cols[e++] = nw * (k + 1) + v;
    }
  }
}

void PathInequalityNlp::jacobian_values(const double* x, double* values) const {
  base_.jacobian_values(x, values);
  double* out = values + base_.jacobian_nonzeros();
  const auto per_point = static_cast<std::ptrdiff_t>(rows_.jacobian_pattern().size());
  for (int k = 0; k < constrained_points(); ++k, out += per_point)
    rows_.jacobian_values(point(x, k), out);
}

int PathInequalityNlp::hessian_nonzeros() const {
  return base_.hessian_nonzeros() + static_cast<int>(rows_.hessian_pattern().size()) * constrained_points();
}

void PathInequalityNlp::hessian_structure(int* rows, int* cols) const {
  base_.hessian_structure(rows, cols);
  std::size_t e = static_cast<std::size_t>(base_.hessian_nonzeros());
  const int nw = base_.model().point_size();
  for (int k = 0; k < constrained_points(); ++k) {
    for (const auto& [i, j] : rows_.hessian_pattern()) {
      rows[e] = nw * (k + 1) + i;
      cols[e++] = nw * (k + 1) + j;
    }
  }
}

void PathInequalityNlp::hessian_values(const double* x, double sigma, const double* y, double* values) const {
  base_.hessian_values(x, sigma, y, values);
  double* out = values + base_.hessian_nonzeros();
  const double* weights = y + base_.num_constraints();
  const auto per_point = static_cast<std::ptrdiff_t>(rows_.hessian_pattern().size());
  for (int k = 0; k < constrained_points(); ++k, out += per_point, weights += rows_.rows())
    rows_.hessian_values(point(x, k), weights, out);
}

}  // namespace poinsot::optimal::detail
