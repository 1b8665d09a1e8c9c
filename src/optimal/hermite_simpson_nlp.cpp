// The Hermite–Simpson transcription (hermite_simpson_nlp.hpp).
#include "hermite_simpson_nlp.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "poinsot/core/error.hpp"

namespace poinsot::optimal::detail {

void CollocationModel::path_bounds(bool first_of_phase, double* lower, double* upper) const {
  const int rows = first_of_phase ? first_path().rows() : path().rows();
  std::fill(lower, lower + rows, 0.0);
  std::fill(upper, upper + rows, 0.0);
}

HermiteSimpsonNlp::HermiteSimpsonNlp(const CollocationModel& model, CollocationMesh mesh, Eigen::VectorXd y0,
                                     Eigen::MatrixXd final_rows, Eigen::VectorXd final_values,
                                     CollocationTime time, CollocationObjective objective)
    : model_(model),
      mesh_(std::move(mesh)),
      y0_(std::move(y0)),
      final_rows_(std::move(final_rows)),
      final_values_(std::move(final_values)),
      time_(std::move(time)),
      objective_(objective) {
  const auto P = static_cast<std::size_t>(mesh_.phases());
  if (time_.free() ? time_.lower.size() != P || time_.upper.size() != P : P != 1)
    throw InvalidInput("collocation phases: " + std::to_string(P) + " phases with " +
                       std::to_string(time_.lower.size()) +
                       " duration bounds; expected one bound per phase with a free final time, and one phase "
                       "with a fixed final time");
  if (y0_.size() != model_.state_size() || final_rows_.cols() != model_.state_size() ||
      final_rows_.rows() != final_values_.size())
    throw InvalidInput("collocation: boundary conditions of sizes " + std::to_string(y0_.size()) + ", " +
                       std::to_string(final_rows_.rows()) + "×" + std::to_string(final_rows_.cols()) +
                       " and " + std::to_string(final_values_.size()) + "; expected the state size " +
                       std::to_string(model_.state_size()));
  build_jacobian_structure();
  build_hessian_structure();
}

void HermiteSimpsonNlp::build_jacobian_structure() {
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  const auto add = [&](int row, int col) {
    jac_rows_.push_back(row);
    jac_cols_.push_back(col);
  };
  // In the order jacobian_values() writes the entries.
  const auto& fp = model_.rhs().jacobian_pattern();
  for (int k = 0; k < intervals(); ++k) {
    const int d = defect_row(k), m = d + ny;
    const int w0 = nw * mesh_.interval_first_point(k), wm = w0 + nw, w1 = wm + nw;
    for (int r = 0; r < ny; ++r) {
      add(d + r, w1 + r);
      add(d + r, w0 + r);
      add(m + r, wm + r);
      add(m + r, w0 + r);
      add(m + r, w1 + r);
    }
    for (const int w : {w0, wm, w1})
      for (const auto& [r, v] : fp)
        add(d + r, w + v);
    for (const int w : {w0, w1})
      for (const auto& [r, v] : fp)
        add(m + r, w + v);
  }
  for (int p = 0; p < points(); ++p)
    for (const auto& [r, v] : path_of(p).jacobian_pattern())
      add(path_row(p) + r, nw * p + v);
  for (int a = 0; a + 1 < mesh_.phases(); ++a)
    for (int r = 0; r < ny; ++r) {
      add(link_row(a) + r, nw * mesh_.phase_last_point(a) + r);
      add(link_row(a) + r, nw * mesh_.phase_first_point(a + 1) + r);
    }
  for (int r = 0; r < final_rows_.rows(); ++r)
    for (int v = 0; v < ny; ++v)
      add(final_row() + r, nw * (points() - 1) + v);
  if (free_time())
    for (int k = 0; k < intervals(); ++k)
      for (int r = 0; r < 2 * ny; ++r)
        add(defect_row(k) + r, duration_index(mesh_.interval_phase(k)));
}

void HermiteSimpsonNlp::build_hessian_structure() {
  // The union of the points' patterns.
  const int nw = model_.point_size();
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
  const auto n = static_cast<std::size_t>(points());
  hess_rhs_.resize(n);
  hess_path_.resize(n);
  hess_objective_.resize(n);
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
  if (!free_time()) return;
  hess_time_rhs_.resize(n);
  hess_time_objective_.resize(n);
  for (int p = 0; p < points(); ++p) {
    const auto pu = static_cast<std::size_t>(p);
    const int D = duration_index(mesh_.point_phase(p));
    for (const auto& [r, v] : model_.rhs().jacobian_pattern())
      hess_time_rhs_[pu].push_back(entry(D, nw * p + v));
    for (const int c : model_.control_indices())
      hess_time_objective_[pu].push_back(entry(D, nw * p + c));
  }
}

int HermiteSimpsonNlp::path_row(int p) const {
  const int base = 2 * model_.state_size() * intervals();
  // Every point before p: the first of each phase started so far has first_path rows, the others path rows.
  const int firsts =
      p == points() ? mesh_.phases() : mesh_.point_phase(p) + (mesh_.first_of_phase(p) ? 0 : 1);
  return base + firsts * model_.first_path().rows() + (p - firsts) * model_.path().rows();
}

int HermiteSimpsonNlp::num_constraints() const {
  return final_row() + static_cast<int>(final_rows_.rows());
}

double HermiteSimpsonNlp::final_time(const double* x) const {
  if (!free_time()) return time_.fixed;
  double T = 0.0;
  for (int a = 0; a < mesh_.phases(); ++a)
    T += x[duration_index(a)];
  return T;
}

std::vector<double> HermiteSimpsonNlp::point_times(const double* x) const {
  std::vector<double> durations;
  for (int a = 0; a < mesh_.phases(); ++a)
    durations.push_back(duration(x, a));
  return mesh_.point_times(durations);
}

Eigen::VectorXd HermiteSimpsonNlp::costate(const std::vector<double>& y, int k) const {
  return -Eigen::Map<const Eigen::VectorXd>(y.data() + defect_row(k), model_.state_size());
}

void HermiteSimpsonNlp::bounds(std::vector<double>& xl, std::vector<double>& xu, std::vector<double>& gl,
                               std::vector<double>& gu) const {
  const int nw = model_.point_size();
  xl.assign(static_cast<std::size_t>(num_variables()), 0.0);
  xu.assign(static_cast<std::size_t>(num_variables()), 0.0);
  for (int p = 0; p < points(); ++p) {
    const PointRole role{mesh_.point_phase(p), p == 0, mesh_.first_of_phase(p), p + 1 == points()};
    model_.variable_bounds(role, xl.data() + nw * p, xu.data() + nw * p);
  }
  for (int i = 0; i < model_.state_size(); ++i)
    xl[static_cast<std::size_t>(i)] = xu[static_cast<std::size_t>(i)] = y0_(i);
  if (free_time())
    for (int a = 0; a < mesh_.phases(); ++a) {
      xl[static_cast<std::size_t>(duration_index(a))] = time_.lower[static_cast<std::size_t>(a)];
      xu[static_cast<std::size_t>(duration_index(a))] = time_.upper[static_cast<std::size_t>(a)];
    }
  gl.assign(static_cast<std::size_t>(num_constraints()), 0.0);
  gu = gl;
  for (int p = 0; p < points(); ++p) {
    const auto r = static_cast<std::size_t>(path_row(p));
    model_.path_bounds(mesh_.first_of_phase(p), gl.data() + r, gu.data() + r);
  }
  for (int r = 0; r < final_rows_.rows(); ++r)
    gl[static_cast<std::size_t>(final_row() + r)] = gu[static_cast<std::size_t>(final_row() + r)] =
        final_values_(r);
}

double HermiteSimpsonNlp::objective(const double* x) const {
  // β Σ Δ_a + α Σ_p Δ_{a(p)} w_p |u_p|²: Simpson's rule for ∫ Σ u² dt.
  const int nw = model_.point_size();
  double E = 0.0;
  if (objective_.energy_weight != 0.0)
    for (int p = 0; p < points(); ++p) {
      double s = 0.0;
      for (const int c : model_.control_indices())
        s += x[nw * p + c] * x[nw * p + c];
      E += duration(x, mesh_.point_phase(p)) * mesh_.quadrature_weight(p) * s;
    }
  return objective_.time_weight * (free_time() ? final_time(x) : 0.0) + objective_.energy_weight * E;
}

void HermiteSimpsonNlp::objective_gradient(const double* x, double* g) const {
  std::fill(g, g + num_variables(), 0.0);
  const int nw = model_.point_size();
  const double alpha = objective_.energy_weight;
  if (free_time())
    for (int a = 0; a < mesh_.phases(); ++a)
      g[duration_index(a)] = objective_.time_weight;
  if (alpha == 0.0) return;
  for (int p = 0; p < points(); ++p) {
    const int a = mesh_.point_phase(p);
    const double w = mesh_.quadrature_weight(p), D = duration(x, a);
    double s = 0.0;
    for (const int c : model_.control_indices()) {
      g[nw * p + c] = 2.0 * alpha * w * D * x[nw * p + c];
      s += x[nw * p + c] * x[nw * p + c];
    }
    if (free_time()) g[duration_index(a)] += alpha * w * s;
  }
}

void HermiteSimpsonNlp::constraints(const double* x, double* g) const {
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  Eigen::MatrixXd f(ny, points());
  for (int p = 0; p < points(); ++p)
    model_.rhs().values(x + nw * p, f.col(p).data());
  const auto y = [&](int p) { return Eigen::Map<const Eigen::VectorXd>(x + nw * p, ny); };
  for (int k = 0; k < intervals(); ++k) {
    const int p0 = mesh_.interval_first_point(k), pm = p0 + 1, p1 = p0 + 2;
    const double h = interval_step(x, k);
    Eigen::Map<Eigen::VectorXd>(g + defect_row(k), ny) =
        y(p1) - y(p0) - h / 6.0 * (f.col(p0) + 4.0 * f.col(pm) + f.col(p1));
    Eigen::Map<Eigen::VectorXd>(g + defect_row(k) + ny, ny) =
        y(pm) - 0.5 * (y(p0) + y(p1)) - h / 8.0 * (f.col(p0) - f.col(p1));
  }
  for (int p = 0; p < points(); ++p)
    path_of(p).values(x + nw * p, g + path_row(p));
  for (int a = 0; a + 1 < mesh_.phases(); ++a)
    Eigen::Map<Eigen::VectorXd>(g + link_row(a), ny) =
        y(mesh_.phase_last_point(a)) - y(mesh_.phase_first_point(a + 1));
  Eigen::Map<Eigen::VectorXd>(g + final_row(), final_rows_.rows()) = final_rows_ * y(points() - 1);
}

void HermiteSimpsonNlp::jacobian_structure(int* rows, int* cols) const {
  std::copy(jac_rows_.begin(), jac_rows_.end(), rows);
  std::copy(jac_cols_.begin(), jac_cols_.end(), cols);
}

void HermiteSimpsonNlp::jacobian_values(const double* x, double* values) const {
  const int ny = model_.state_size();
  const int nw = model_.point_size();
  const auto nf = model_.rhs().jacobian_pattern().size();
  std::vector<double> df(nf * static_cast<std::size_t>(points()));
  for (int p = 0; p < points(); ++p)
    model_.rhs().jacobian_values(x + nw * p, df.data() + nf * static_cast<std::size_t>(p));
  double* out = values;
  for (int k = 0; k < intervals(); ++k) {
    for (int r = 0; r < ny; ++r) {
      *out++ = 1.0;
      *out++ = -1.0;
      *out++ = 1.0;
      *out++ = -0.5;
      *out++ = -0.5;
    }
    const int p0 = mesh_.interval_first_point(k);
    const double h = interval_step(x, k);
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
  for (int a = 0; a + 1 < mesh_.phases(); ++a)
    for (int r = 0; r < ny; ++r) {
      *out++ = 1.0;
      *out++ = -1.0;
    }
  for (int r = 0; r < final_rows_.rows(); ++r)
    for (int v = 0; v < ny; ++v)
      *out++ = final_rows_(r, v);
  if (!free_time()) return;
  // ∂D_k/∂Δ = −∂h_k/∂Δ (f_k + 4 f_m + f_{k+1})/6, ∂M_k/∂Δ = −∂h_k/∂Δ (f_k − f_{k+1})/8.
  Eigen::VectorXd f0(ny), fm(ny), f1(ny);
  for (int k = 0; k < intervals(); ++k) {
    const int p0 = mesh_.interval_first_point(k);
    model_.rhs().values(x + nw * p0, f0.data());
    model_.rhs().values(x + nw * (p0 + 1), fm.data());
    model_.rhs().values(x + nw * (p0 + 2), f1.data());
    if (mesh_.uniform()) {
      Eigen::Map<Eigen::VectorXd>(out, ny) = -(f0 + 4.0 * fm + f1) / (6.0 * intervals());
      Eigen::Map<Eigen::VectorXd>(out + ny, ny) = -(f0 - f1) / (8.0 * intervals());
    } else {
      const double d = mesh_.step_fraction(k);
      Eigen::Map<Eigen::VectorXd>(out, ny) = -d / 6.0 * (f0 + 4.0 * fm + f1);
      Eigen::Map<Eigen::VectorXd>(out + ny, ny) = -d / 8.0 * (f0 - f1);
    }
    out += 2 * ny;
  }
}

Eigen::VectorXd HermiteSimpsonNlp::defect_weight(int p, const double* y) const {
  const int ny = model_.state_size();
  const int a = mesh_.point_phase(p), l = p - mesh_.phase_first_point(a), k0 = mesh_.phase_first_interval(a);
  const auto D = [&](int k) { return Eigen::Map<const Eigen::VectorXd>(y + defect_row(k), ny); };
  const auto M = [&](int k) { return Eigen::Map<const Eigen::VectorXd>(y + defect_row(k) + ny, ny); };
  if (l % 2 == 1) {
    const int k = k0 + l / 2;
    return -4.0 / 6.0 * mesh_.step_fraction(k) * D(k);
  }
  const int k = k0 + l / 2;
  Eigen::VectorXd c = Eigen::VectorXd::Zero(ny);
  if (k > k0) c += -mesh_.step_fraction(k - 1) / 6.0 * D(k - 1) + mesh_.step_fraction(k - 1) / 8.0 * M(k - 1);
  if (k < mesh_.phase_first_interval(a + 1))
    c += -mesh_.step_fraction(k) / 6.0 * D(k) - mesh_.step_fraction(k) / 8.0 * M(k);
  return c;
}

void HermiteSimpsonNlp::hessian_structure(int* rows, int* cols) const {
  std::copy(hess_rows_.begin(), hess_rows_.end(), rows);
  std::copy(hess_cols_.begin(), hess_cols_.end(), cols);
}

void HermiteSimpsonNlp::hessian_values(const double* x, double sigma, const double* y, double* values) const {
  std::fill(values, values + hessian_nonzeros(), 0.0);
  const int nw = model_.point_size();
  const double alpha = objective_.energy_weight;
  const auto& fp = model_.rhs().jacobian_pattern();
  const auto& controls = model_.control_indices();
  std::vector<double> df(free_time() ? fp.size() : 0);
  std::vector<double> local;
  for (int p = 0; p < points(); ++p) {
    const auto pu = static_cast<std::size_t>(p);
    const int a = mesh_.point_phase(p);
    const double D = duration(x, a), w = mesh_.quadrature_weight(p);
    // yᵀg holds Δ (c_unit · f_p): the f_p terms of the defects of the intervals that hold point p.
    const Eigen::VectorXd c_unit = defect_weight(p, y);
    const Eigen::VectorXd weights = D * c_unit;
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
      values[entry] += 2.0 * sigma * alpha * D * w;
    if (!free_time()) continue;
    // The (Δ, w_p) entries: c_unitᵀ ∂f_p/∂w_p, and the objective's 2 α w_p u_p.
    model_.rhs().jacobian_values(x + nw * p, df.data());
    for (std::size_t n = 0; n < fp.size(); ++n)
      values[hess_time_rhs_[pu][n]] += c_unit(fp[n].first) * df[n];
    for (std::size_t c = 0; c < controls.size(); ++c)
      values[hess_time_objective_[pu][c]] += 2.0 * sigma * alpha * w * x[nw * p + controls[c]];
  }
}

}  // namespace poinsot::optimal::detail
