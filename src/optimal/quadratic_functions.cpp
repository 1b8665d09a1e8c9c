// Polynomials of degree ≤ 2 with their exact derivatives (point_functions.hpp).
#include <algorithm>
#include <map>

#include "point_functions.hpp"

namespace poinsot::optimal::detail {

int QuadraticFunctions::add_row() {
  constant_.push_back(0.0);
  return rows() - 1;
}
void QuadraticFunctions::add_constant(int row, double k) {
  constant_[static_cast<std::size_t>(row)] += k;
}
void QuadraticFunctions::add_linear(int row, int var, double a) {
  if (a != 0.0) linear_.push_back({row, var, a});
}
void QuadraticFunctions::add_bilinear(int row, int i, int j, double b) {
  if (b != 0.0) bilinear_.push_back({row, std::max(i, j), std::min(i, j), b});
}

void QuadraticFunctions::finish() {
  std::map<IndexPair, int> jac, hess;
  const auto entry = [](std::map<IndexPair, int>& m, IndexPair key) {
    return m.emplace(key, static_cast<int>(m.size())).first->second;
  };
  // Entries are numbered in order of appearance; the pattern lists them in that order.
  std::vector<IndexPair> jac_order, hess_order;
  const auto jac_entry = [&](int row, int var) {
    const auto before = jac.size();
    const int e = entry(jac, {row, var});
    if (jac.size() != before) jac_order.push_back({row, var});
    return e;
  };
  const auto hess_entry = [&](int i, int j) {
    const auto before = hess.size();
    const int e = entry(hess, {i, j});
    if (hess.size() != before) hess_order.push_back({i, j});
    return e;
  };
  std::vector<std::pair<int, double>> constants;
  for (const Linear& l : linear_)
    constants.push_back({jac_entry(l.row, l.var), l.a});
  for (const Bilinear& q : bilinear_) {
    if (q.i == q.j) {
      jac_terms_.push_back({jac_entry(q.row, q.i), q.i, 2.0 * q.b});
      hess_terms_.push_back({hess_entry(q.i, q.i), q.row, 2.0 * q.b});
    } else {
      jac_terms_.push_back({jac_entry(q.row, q.i), q.j, q.b});
      jac_terms_.push_back({jac_entry(q.row, q.j), q.i, q.b});
      hess_terms_.push_back({hess_entry(q.i, q.j), q.row, q.b});
    }
  }
  jac_pattern_ = jac_order;
  hess_pattern_ = hess_order;
  jac_constant_.assign(jac_pattern_.size(), 0.0);
  for (const auto& [e, a] : constants)
    jac_constant_[static_cast<std::size_t>(e)] += a;
}

void QuadraticFunctions::values(const double* w, double* out) const {
  std::copy(constant_.begin(), constant_.end(), out);
  for (const Linear& l : linear_)
    out[l.row] += l.a * w[l.var];
  for (const Bilinear& q : bilinear_)
    out[q.row] += q.b * w[q.i] * w[q.j];
}

void QuadraticFunctions::jacobian_values(const double* w, double* values) const {
  std::copy(jac_constant_.begin(), jac_constant_.end(), values);
  for (const JacobianTerm& t : jac_terms_)
    values[t.entry] += t.coefficient * w[t.var];
}

void QuadraticFunctions::hessian_values(const double*, const double* weights, double* values) const {
  std::fill(values, values + hess_pattern_.size(), 0.0);
  for (const HessianTerm& t : hess_terms_)
    values[t.entry] += t.coefficient * weights[t.row];
}

}  // namespace poinsot::optimal::detail
