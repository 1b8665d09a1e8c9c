// The Hermite–Simpson transcription of a differential-algebraic problem (hermite_simpson_dae.hpp).
#include "hermite_simpson_dae.hpp"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>

namespace poinsot::optimal::detail {

HermiteSimpsonDae::HermiteSimpsonDae(const CollocationModel& model, int intervals, double final_time,
                                     Eigen::VectorXd y0, Eigen::MatrixXd final_rows,
                                     Eigen::VectorXd final_values, const FreeFinalTime* free_time,
                                     std::vector<double> fractions)
    : model_(model),
      intervals_(fractions.empty() ? intervals : static_cast<int>(fractions.size())),
      equal_(fractions.empty()),
      dtau_(fractions.empty() ? std::vector<double>(static_cast<std::size_t>(intervals), 1.0 / intervals)
                              : std::move(fractions)),
      final_time_(final_time),
      y0_(std::move(y0)),
      final_rows_(std::move(final_rows)),
      final_values_(std::move(final_values)),
      free_(free_time != nullptr),
      free_time_(free_time != nullptr ? *free_time : FreeFinalTime{}) {
  tau_.assign(1, 0.0);
  for (const double d : dtau_)
    tau_.push_back(tau_.back() + d);
  tau_.back() = 1.0;  // the last node at T exactly
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  const auto add_jac = [&](int row, int col) {
    jac_rows_.push_back(row);
    jac_cols_.push_back(col);
  };
  // Jacobian, in the order jacobian_values() writes it.
  const auto& fp = model_.rhs().jacobian_pattern();
  for (int k = 0; k < intervals_; ++k) {
    const int d = 2 * ny * k, m = d + ny;
    const int w0 = nw * 2 * k, wm = w0 + nw, w1 = wm + nw;
    for (int r = 0; r < ny; ++r) {
      add_jac(d + r, w1 + r);
      add_jac(d + r, w0 + r);
      add_jac(m + r, wm + r);
      add_jac(m + r, w0 + r);
      add_jac(m + r, w1 + r);
    }
    for (const int w : {w0, wm, w1})
      for (const auto& [r, v] : fp)
        add_jac(d + r, w + v);
    for (const int w : {w0, w1})
      for (const auto& [r, v] : fp)
        add_jac(m + r, w + v);
  }
  for (int p = 0; p < points(); ++p)
    for (const auto& [r, v] : path_of(p).jacobian_pattern())
      add_jac(path_row(p) + r, nw * p + v);
  const int fr = path_row(points());
  for (int r = 0; r < final_rows_.rows(); ++r)
    for (int v = 0; v < ny; ++v)
      add_jac(fr + r, nw * 2 * intervals_ + v);
  if (free_) {
    for (int k = 0; k < intervals_; ++k)
      for (int r = 0; r < 2 * ny; ++r)
        add_jac(2 * ny * k + r, time_index());
  }

  // Hessian: the union of the points' patterns.
  std::map<IndexPair, int> index;
  const auto entry = [&](int i, int j) {
    const IndexPair key{std::max(i, j), std::min(i, j)};
    const auto [it, added] = index.emplace(key, static_cast<int>(hess_rows_.size()));
    if (added) {
      hess_rows_.push_back(key.first);
      hess_cols_.push_back(key.second);
    }
    return it->second;
  };
  hess_rhs_.resize(static_cast<std::size_t>(points()));
  hess_path_.resize(static_cast<std::size_t>(points()));
  hess_objective_.resize(static_cast<std::size_t>(points()));
  for (int p = 0; p < points(); ++p) {
    const int off = nw * p;
    const auto pu = static_cast<std::size_t>(p);
    for (const auto& [i, j] : model_.rhs().hessian_pattern())
      hess_rhs_[pu].push_back(entry(off + i, off + j));
    for (const auto& [i, j] : path_of(p).hessian_pattern())
      hess_path_[pu].push_back(entry(off + i, off + j));
    for (const int c : model_.control_indices())
      hess_objective_[pu].push_back(entry(off + c, off + c));
  }
  if (free_) {
    hess_time_rhs_.resize(static_cast<std::size_t>(points()));
    hess_time_objective_.resize(static_cast<std::size_t>(points()));
    for (int p = 0; p < points(); ++p) {
      const auto pu = static_cast<std::size_t>(p);
      for (const auto& [r, v] : model_.rhs().jacobian_pattern())
        hess_time_rhs_[pu].push_back(entry(time_index(), nw * p + v));
      for (const int c : model_.control_indices())
        hess_time_objective_[pu].push_back(entry(time_index(), nw * p + c));
    }
  }
}

int HermiteSimpsonDae::path_row(int p) const {
  const int base = 2 * model_.state_size() * intervals_;
  if (p == 0) return base;
  return base + model_.first_path().rows() + (p - 1) * model_.path().rows();
}

int HermiteSimpsonDae::num_constraints() const {
  return path_row(points()) + static_cast<int>(final_rows_.rows());
}

void HermiteSimpsonDae::bounds(std::vector<double>& xl, std::vector<double>& xu, std::vector<double>& gl,
                               std::vector<double>& gu) const {
  const int nw = model_.point_size();
  xl.assign(static_cast<std::size_t>(num_variables()), 0.0);
  xu.assign(static_cast<std::size_t>(num_variables()), 0.0);
  for (int p = 0; p < points(); ++p)
    model_.variable_bounds(p == 0, xl.data() + nw * p, xu.data() + nw * p);
  for (int i = 0; i < model_.state_size(); ++i)
    xl[static_cast<std::size_t>(i)] = xu[static_cast<std::size_t>(i)] = y0_(i);
  if (free_) {
    xl[static_cast<std::size_t>(time_index())] = free_time_.lower;
    xu[static_cast<std::size_t>(time_index())] = free_time_.upper;
  }
  gl.assign(static_cast<std::size_t>(num_constraints()), 0.0);
  gu = gl;
  const int fr = path_row(points());
  for (int r = 0; r < final_rows_.rows(); ++r)
    gl[static_cast<std::size_t>(fr + r)] = gu[static_cast<std::size_t>(fr + r)] = final_values_(r);
}

double HermiteSimpsonDae::unit_weight(int p) const {
  const auto k = static_cast<std::size_t>(p / 2);
  if (p % 2 == 1) return 4.0 * dtau_[k] / 6.0;
  return ((p > 0 ? dtau_[k - 1] : 0.0) + (p < 2 * intervals_ ? dtau_[k] : 0.0)) / 6.0;
}

double HermiteSimpsonDae::objective(const double* x) const {
  // ε T Σ_p ŵ_p |u_p|² (+ T when free): Simpson's rule with the weights T ŵ_p.
  double E = 0.0;
  const int nw = model_.point_size();
  for (int p = 0; p < points(); ++p) {
    double s = 0.0;
    for (const int c : model_.control_indices())
      s += x[nw * p + c] * x[nw * p + c];
    E += unit_weight(p) * s;
  }
  const double T = final_time(x);
  return (free_ ? T : 0.0) + energy_weight() * T * E;
}

void HermiteSimpsonDae::objective_gradient(const double* x, double* g) const {
  std::fill(g, g + num_variables(), 0.0);
  const int nw = model_.point_size();
  const double T = final_time(x), e = energy_weight();
  double E = 0.0;
  for (int p = 0; p < points(); ++p) {
    for (const int c : model_.control_indices()) {
      g[nw * p + c] = 2.0 * e * T * unit_weight(p) * x[nw * p + c];
      E += unit_weight(p) * x[nw * p + c] * x[nw * p + c];
    }
  }
  if (free_) g[time_index()] = 1.0 + e * E;
}

void HermiteSimpsonDae::constraints(const double* x, double* g) const {
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  const double T = final_time(x);
  std::vector<Eigen::VectorXd> f(static_cast<std::size_t>(points()), Eigen::VectorXd(ny));
  for (int p = 0; p < points(); ++p)
    model_.rhs().values(x + nw * p, f[static_cast<std::size_t>(p)].data());
  for (int k = 0; k < intervals_; ++k) {
    const auto y = [&](int p) { return Eigen::Map<const Eigen::VectorXd>(x + nw * p, ny); };
    const auto F = [&](int p) -> const Eigen::VectorXd& { return f[static_cast<std::size_t>(p)]; };
    const int p0 = 2 * k, pm = p0 + 1, p1 = p0 + 2;
    const double h = interval_step(k, T);
    Eigen::Map<Eigen::VectorXd>(g + 2 * ny * k, ny) = y(p1) - y(p0) - h / 6.0 * (F(p0) + 4.0 * F(pm) + F(p1));
    Eigen::Map<Eigen::VectorXd>(g + 2 * ny * k + ny, ny) =
        y(pm) - 0.5 * (y(p0) + y(p1)) - h / 8.0 * (F(p0) - F(p1));
  }
  for (int p = 0; p < points(); ++p)
    path_of(p).values(x + nw * p, g + path_row(p));
  const Eigen::Map<const Eigen::VectorXd> yN(x + nw * 2 * intervals_, ny);
  Eigen::Map<Eigen::VectorXd>(g + path_row(points()), final_rows_.rows()) = final_rows_ * yN;
}

void HermiteSimpsonDae::jacobian_structure(int* rows, int* cols) const {
  std::copy(jac_rows_.begin(), jac_rows_.end(), rows);
  std::copy(jac_cols_.begin(), jac_cols_.end(), cols);
}

void HermiteSimpsonDae::jacobian_values(const double* x, double* values) const {
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  const double T = final_time(x);
  const auto nf = model_.rhs().jacobian_pattern().size();
  std::vector<double> df(nf * static_cast<std::size_t>(points()));
  for (int p = 0; p < points(); ++p)
    model_.rhs().jacobian_values(x + nw * p, df.data() + nf * static_cast<std::size_t>(p));
  double* out = values;
  for (int k = 0; k < intervals_; ++k) {
    for (int r = 0; r < ny; ++r) {
      *out++ = 1.0;
      *out++ = -1.0;
      *out++ = 1.0;
      *out++ = -0.5;
      *out++ = -0.5;
    }
    const int p0 = 2 * k;
    const double h = interval_step(k, T);
    const double dw[3] = {-h / 6.0, -4.0 * h / 6.0, -h / 6.0};
    for (int s = 0; s < 3; ++s) {
      const double* d = df.data() + nf * static_cast<std::size_t>(p0 + s);
      for (std::size_t e = 0; e < nf; ++e)
        *out++ = dw[s] * d[e];
    }
    const double mw[2] = {-h / 8.0, h / 8.0};
    for (int s = 0; s < 2; ++s) {
      const double* d = df.data() + nf * static_cast<std::size_t>(p0 + 2 * s);
      for (std::size_t e = 0; e < nf; ++e)
        *out++ = mw[s] * d[e];
    }
  }
  for (int p = 0; p < points(); ++p) {
    path_of(p).jacobian_values(x + nw * p, out);
    out += path_of(p).jacobian_pattern().size();
  }
  for (int r = 0; r < final_rows_.rows(); ++r)
    for (int v = 0; v < ny; ++v)
      *out++ = final_rows_(r, v);
  if (free_) {
    // ∂D_k/∂T = −(f_k + 4 f_m + f_{k+1})/(6N), ∂M_k/∂T = −(f_k − f_{k+1})/(8N).
    Eigen::VectorXd f0(ny), fm(ny), f1(ny);
    for (int k = 0; k < intervals_; ++k) {
      model_.rhs().values(x + nw * 2 * k, f0.data());
      model_.rhs().values(x + nw * (2 * k + 1), fm.data());
      model_.rhs().values(x + nw * (2 * k + 2), f1.data());
      if (equal_) {
        Eigen::Map<Eigen::VectorXd>(out, ny) = -(f0 + 4.0 * fm + f1) / (6.0 * intervals_);
        Eigen::Map<Eigen::VectorXd>(out + ny, ny) = -(f0 - f1) / (8.0 * intervals_);
      } else {
        const double d = dtau_[static_cast<std::size_t>(k)];
        Eigen::Map<Eigen::VectorXd>(out, ny) = -d / 6.0 * (f0 + 4.0 * fm + f1);
        Eigen::Map<Eigen::VectorXd>(out + ny, ny) = -d / 8.0 * (f0 - f1);
      }
      out += 2 * ny;
    }
  }
}

void HermiteSimpsonDae::hessian_structure(int* rows, int* cols) const {
  std::copy(hess_rows_.begin(), hess_rows_.end(), rows);
  std::copy(hess_cols_.begin(), hess_cols_.end(), cols);
}

void HermiteSimpsonDae::hessian_values(const double* x, double sigma, const double* y, double* values) const {
  std::fill(values, values + hessian_nonzeros(), 0.0);
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  const double T = final_time(x), eps = energy_weight();
  const auto h = [&](int k) { return interval_step(k, T); };
  const auto nf = model_.rhs().jacobian_pattern().size();
  std::vector<double> df(free_ ? nf : 0);
  Eigen::VectorXd weights(ny);
  std::vector<double> local;
  for (int p = 0; p < points(); ++p) {
    const auto pu = static_cast<std::size_t>(p);
    // The weights of f_p in the defects (see the Jacobian): D_k, M_k of the intervals that hold point p.
    weights.setZero();
    const auto D = [&](int k) { return Eigen::Map<const Eigen::VectorXd>(y + 2 * ny * k, ny); };
    const auto M = [&](int k) { return Eigen::Map<const Eigen::VectorXd>(y + 2 * ny * k + ny, ny); };
    if (p % 2 == 1) {
      weights = -4.0 * h(p / 2) / 6.0 * D(p / 2);
    } else {
      const int k = p / 2;
      if (k < intervals_) weights += -h(k) / 6.0 * D(k) - h(k) / 8.0 * M(k);
      if (k > 0) weights += -h(k - 1) / 6.0 * D(k - 1) + h(k - 1) / 8.0 * M(k - 1);
    }
    const auto& rp = hess_rhs_[pu];
    local.resize(rp.size());
    model_.rhs().hessian_values(x + nw * p, weights.data(), local.data());
    for (std::size_t e = 0; e < rp.size(); ++e)
      values[rp[e]] += local[e];
    const auto& pp = hess_path_[pu];
    local.resize(pp.size());
    path_of(p).hessian_values(x + nw * p, y + path_row(p), local.data());
    for (std::size_t e = 0; e < pp.size(); ++e)
      values[pp[e]] += local[e];
    for (const int entry : hess_objective_[pu])
      values[entry] += 2.0 * sigma * eps * T * unit_weight(p);
    if (!free_) continue;
    // The (T, w_p) entries: the f_p terms' weights are linear in T (weights/T), the objective's 2εŵ_p u.
    model_.rhs().jacobian_values(x + nw * p, df.data());
    const auto& fp = model_.rhs().jacobian_pattern();
    for (std::size_t n = 0; n < nf; ++n)
      values[hess_time_rhs_[pu][n]] += weights(fp[n].first) / T * df[n];
    const auto& controls = model_.control_indices();
    for (std::size_t c = 0; c < controls.size(); ++c)
      values[hess_time_objective_[pu][c]] += 2.0 * sigma * eps * unit_weight(p) * x[nw * p + controls[c]];
  }
}

}  // namespace poinsot::optimal::detail
