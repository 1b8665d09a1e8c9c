#include "collocation_nlp.hpp"

#include <cmath>
#include <limits>
#include <utility>

namespace poinsot::optimal::detail {

namespace {
constexpr double kInf = 2e19;  // Ipopt's default "infinite" bound (nlp_upper_bound_inf = 1e19)
}  // namespace

CollocationNlp::CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau)
    : problem_(problem), tau_(std::move(tau)) {
  dyn_.J = problem_.inertia_body;
  dyn_.J_inv = problem_.inertia_body.inverse();
  // Left multiplication by a = q_f* = (w, −v): rows 1..3 of [[a0, −avᵀ], [av, a0 I + j(av)]].
  const Quat& qf = problem_.attitude_final;
  const double a0 = qf.w();
  const Vec3 av = -qf.vec();
  final_attitude_rows_.col(0) = av;
  final_attitude_rows_.block<3, 3>(0, 1) = a0 * Mat3::Identity() + hat(av);
}

int CollocationNlp::num_constraints() const {
  const int base = 14 * intervals() + 2 * intervals() + final_rows();
  return problem_.bound == TorqueBound::norm ? base + points() : base;
}

double CollocationNlp::quadrature_weight(int p) const {
  if (p % 2 == 1) return 4.0 / 6.0 * step_fraction((p - 1) / 2);
  const int k = p / 2;
  double w = 0.0;
  if (k > 0) w += step_fraction(k - 1) / 6.0;
  if (k < intervals()) w += step_fraction(k) / 6.0;
  return w;
}

double CollocationNlp::energy_weight() const {
  switch (problem_.objective) {
    case Objective::minimum_energy:
      return 1.0;
    case Objective::minimum_time_regularised:
      return problem_.energy_weight;
    case Objective::minimum_time:
      return 0.0;
  }
  return 0.0;
}

double CollocationNlp::time_weight() const {
  return problem_.free_final_time() ? 1.0 : 0.0;
}

void CollocationNlp::variable_bounds(std::vector<double>& lo, std::vector<double>& up) const {
  lo.assign(num_variables(), -kInf);
  up.assign(num_variables(), kInf);
  const auto& p = problem_;
  for (int pt = 0; pt < points(); ++pt) {
    const int b = kPointVars * pt;
    for (int i = 0; i < 3; ++i) {
      if (p.has_rate_bound()) {
        lo[b + 4 + i] = -p.rate_max;
        up[b + 4 + i] = p.rate_max;
      }
      const double umax = p.bound == TorqueBound::per_axis ? p.torque_max[i] : p.torque_max[0];
      lo[b + 7 + i] = -umax;
      up[b + 7 + i] = umax;
    }
  }
  const int last = kPointVars * (points() - 1);
  for (int i = 0; i < 4; ++i)
    lo[i] = up[i] = p.attitude_initial.coeffs()[(i + 3) % 4];  // (w, x, y, z)
  lo[10] = up[10] = 0.0;  // ν_0: q_0 is fixed and unit, and every later ν is fixed by its point's ‖q‖ = 1
  for (int i = 0; i < 3; ++i) {
    lo[4 + i] = up[4 + i] = p.omega_initial[i];
    lo[last + 4 + i] = up[last + 4 + i] = p.omega_final[i];
  }
  if (p.free_final_time()) {
    lo[time_index()] = 0.5 * minimum_duration_bound(p);
    up[time_index()] = kInf;
  } else {
    lo[time_index()] = up[time_index()] = p.final_time;
  }
}

void CollocationNlp::constraint_bounds(std::vector<double>& lo, std::vector<double>& up) const {
  lo.assign(num_constraints(), 0.0);
  up.assign(num_constraints(), 0.0);
  if (problem_.bound == TorqueBound::norm) {
    const double u2 = problem_.torque_max[0] * problem_.torque_max[0];
    for (int p = 0; p < points(); ++p) {
      lo[torque_norm_rows_begin() + p] = -kInf;
      up[torque_norm_rows_begin() + p] = u2;
    }
  }
}

double CollocationNlp::objective(const double* z) const {
  const double T = z[time_index()];
  double e = 0.0;
  if (energy_weight() != 0.0)
    for (int p = 0; p < points(); ++p)
      e += quadrature_weight(p) * point(z, p).segment<3>(7).squaredNorm();
  return time_weight() * T + energy_weight() * T * e;
}

void CollocationNlp::objective_gradient(const double* z, double* grad) const {
  std::fill(grad, grad + num_variables(), 0.0);
  const double T = z[time_index()];
  const double a = energy_weight();
  double e = 0.0;
  if (a != 0.0)
    for (int p = 0; p < points(); ++p) {
      const Vec3 u = point(z, p).segment<3>(7);
      const double w = quadrature_weight(p);
      e += w * u.squaredNorm();
      for (int i = 0; i < 3; ++i)
        grad[kPointVars * p + 7 + i] = 2.0 * a * w * T * u[i];
    }
  grad[time_index()] = time_weight() + a * e;
}

void CollocationNlp::constraints(const double* z, double* g) const {
  const double T = z[time_index()];
  for (int k = 0; k < intervals(); ++k) {
    const Vec11 z0 = point(z, 2 * k), z1 = point(z, 2 * k + 1), z2 = point(z, 2 * k + 2);
    const Vec7 f0 = dyn_.rhs(z0), f1 = dyn_.rhs(z1), f2 = dyn_.rhs(z2);
    const double h = step_fraction(k) * T;
    Eigen::Map<Vec7>(g + 14 * k) = z2.head<7>() - z0.head<7>() - h / 6.0 * (f0 + 4.0 * f1 + f2);
    Eigen::Map<Vec7>(g + 14 * k + 7) =
        z1.head<7>() - 0.5 * (z0.head<7>() + z2.head<7>()) - h / 8.0 * (f0 - f2);
  }
  for (int p = 1; p < points(); ++p)
    g[norm_rows_begin() + p - 1] = point(z, p).head<4>().squaredNorm() - 1.0;
  if (final_rows() == 3)
    Eigen::Map<Vec3>(g + final_rows_begin()) = final_attitude_rows_ * point(z, points() - 1).head<4>();
  if (problem_.bound == TorqueBound::norm)
    for (int p = 0; p < points(); ++p)
      g[torque_norm_rows_begin() + p] = point(z, p).segment<3>(7).squaredNorm();
}

int CollocationNlp::jacobian_nonzeros() const {
  const int per_interval = 14 * (3 * kPointVars + 1);
  const int torque = problem_.bound == TorqueBound::norm ? 3 * points() : 0;
  return intervals() * per_interval + 4 * (points() - 1) + 4 * final_rows() + torque;
}

void CollocationNlp::jacobian_structure(int* rows, int* cols) const {
  int n = 0;
  for (int k = 0; k < intervals(); ++k)
    for (int r = 0; r < 14; ++r) {
      for (int j = 0; j < 3; ++j)
        for (int c = 0; c < kPointVars; ++c) {
          rows[n] = 14 * k + r;
          cols[n++] = kPointVars * (2 * k + j) + c;
        }
      rows[n] = 14 * k + r;
      cols[n++] = time_index();
    }
  for (int p = 1; p < points(); ++p)
    for (int c = 0; c < 4; ++c) {
      rows[n] = norm_rows_begin() + p - 1;
      cols[n++] = kPointVars * p + c;
    }
  for (int r = 0; r < final_rows(); ++r)
    for (int c = 0; c < 4; ++c) {
      rows[n] = final_rows_begin() + r;
      cols[n++] = kPointVars * (points() - 1) + c;
    }
  if (problem_.bound == TorqueBound::norm)
    for (int p = 0; p < points(); ++p)
      for (int c = 0; c < 3; ++c) {
        rows[n] = torque_norm_rows_begin() + p;
        cols[n++] = kPointVars * p + 7 + c;
      }
}

void CollocationNlp::jacobian_values(const double* z, double* v) const {
  const double T = z[time_index()];
  Mat7x11 I7 = Mat7x11::Zero();
  I7.leftCols<7>().setIdentity();
  int n = 0;
  for (int k = 0; k < intervals(); ++k) {
    const Vec11 z0 = point(z, 2 * k), z1 = point(z, 2 * k + 1), z2 = point(z, 2 * k + 2);
    const Vec7 f0 = dyn_.rhs(z0), f1 = dyn_.rhs(z1), f2 = dyn_.rhs(z2);
    const Mat7x11 A0 = dyn_.jacobian(z0), A1 = dyn_.jacobian(z1), A2 = dyn_.jacobian(z2);
    const double dt = step_fraction(k), h = dt * T;
    const Mat7x11 d[3] = {-I7 - h / 6.0 * A0, -4.0 * h / 6.0 * A1, I7 - h / 6.0 * A2};
    const Mat7x11 m[3] = {-0.5 * I7 - h / 8.0 * A0, I7, -0.5 * I7 + h / 8.0 * A2};
    const Vec7 dT = -dt / 6.0 * (f0 + 4.0 * f1 + f2), mT = -dt / 8.0 * (f0 - f2);
    for (int r = 0; r < 7; ++r) {
      for (int j = 0; j < 3; ++j)
        for (int c = 0; c < kPointVars; ++c)
          v[n++] = d[j](r, c);
      v[n++] = dT[r];
    }
    for (int r = 0; r < 7; ++r) {
      for (int j = 0; j < 3; ++j)
        for (int c = 0; c < kPointVars; ++c)
          v[n++] = m[j](r, c);
      v[n++] = mT[r];
    }
  }
  for (int p = 1; p < points(); ++p)
    for (int c = 0; c < 4; ++c)
      v[n++] = 2.0 * z[kPointVars * p + c];
  for (int r = 0; r < final_rows(); ++r)
    for (int c = 0; c < 4; ++c)
      v[n++] = final_attitude_rows_(r, c);
  if (problem_.bound == TorqueBound::norm)
    for (int p = 0; p < points(); ++p)
      for (int c = 0; c < 3; ++c)
        v[n++] = 2.0 * z[kPointVars * p + 7 + c];
}

int CollocationNlp::hessian_nonzeros() const {
  return points() * (kPointVars * (kPointVars + 1) / 2 + kPointVars) + 1;
}

void CollocationNlp::hessian_structure(int* rows, int* cols) const {
  int n = 0;
  for (int p = 0; p < points(); ++p) {
    const int b = kPointVars * p;
    for (int r = 0; r < kPointVars; ++r)
      for (int c = 0; c <= r; ++c) {
        rows[n] = b + r;
        cols[n++] = b + c;
      }
    for (int c = 0; c < kPointVars; ++c) {
      rows[n] = time_index();
      cols[n++] = b + c;
    }
  }
  rows[n] = time_index();
  cols[n] = time_index();
}

void CollocationNlp::hessian_values(const double* z, double sigma, const double* y, double* v) const {
  const double T = z[time_index()];
  const double a = energy_weight();
  int n = 0;
  for (int p = 0; p < points(); ++p) {
    // c_p: the weight of f_p in yᵀg (every defect term is linear in f_p with a coefficient ∝ T).
    Vec7 c = Vec7::Zero();
    if (p % 2 == 1) {
      const int k = (p - 1) / 2;
      c = -4.0 / 6.0 * step_fraction(k) * T * Eigen::Map<const Vec7>(y + 14 * k);
    } else {
      const int k = p / 2;
      if (k > 0) {
        const double h = step_fraction(k - 1) * T;
        c += -h / 6.0 * Eigen::Map<const Vec7>(y + 14 * (k - 1)) +
             h / 8.0 * Eigen::Map<const Vec7>(y + 14 * (k - 1) + 7);
      }
      if (k < intervals()) {
        const double h = step_fraction(k) * T;
        c += -h / 6.0 * Eigen::Map<const Vec7>(y + 14 * k) - h / 8.0 * Eigen::Map<const Vec7>(y + 14 * k + 7);
      }
    }
    const Vec11 zp = point(z, p);
    Mat11 H = dyn_.weighted_hessian(c);
    if (p >= 1) H.block<4, 4>(0, 0).diagonal().array() += 2.0 * y[norm_rows_begin() + p - 1];
    if (problem_.bound == TorqueBound::norm)
      H.block<3, 3>(7, 7).diagonal().array() += 2.0 * y[torque_norm_rows_begin() + p];
    const double w = quadrature_weight(p);
    H.block<3, 3>(7, 7).diagonal().array() += sigma * 2.0 * a * w * T;
    for (int r = 0; r < kPointVars; ++r)
      for (int col = 0; col <= r; ++col)
        v[n++] = H(r, col);
    // ∂²/∂T∂z_p: (c_p / T)ᵀ ∂f_p/∂z_p, plus the objective's 2 α w_p u_p.
    Vec11 cross = dyn_.jacobian(zp).transpose() * (c / T);
    cross.segment<3>(7) += sigma * 2.0 * a * w * zp.segment<3>(7);
    for (int col = 0; col < kPointVars; ++col)
      v[n++] = cross[col];
  }
  v[n] = 0.0;
}

}  // namespace poinsot::optimal::detail
