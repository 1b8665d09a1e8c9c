#include "collocation_nlp.hpp"

#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "poinsot/core/error.hpp"

namespace poinsot::optimal::detail {

namespace {
constexpr double kInf = 2e19;  // Ipopt's default "infinite" bound (nlp_upper_bound_inf = 1e19)
}  // namespace

CollocationNlp::CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau)
    : problem_(problem), tau_(std::move(tau)) {
  phases_.intervals = {static_cast<int>(tau_.size()) - 1};
  set_up();
}

CollocationNlp::CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau,
                               CollocationPhases phases)
    : problem_(problem), tau_(std::move(tau)), phases_(std::move(phases)) {
  const std::size_t P = phases_.intervals.size();
  std::size_t nodes = 0;
  for (const int n : phases_.intervals)
    nodes += static_cast<std::size_t>(n) + 1;
  if (P == 0 || nodes != tau_.size() || phases_.torque_lower.size() != P || phases_.torque_upper.size() != P)
    throw InvalidInput("collocation phases: " + std::to_string(P) + " phases with " +
                       std::to_string(tau_.size()) +
                       " mesh values; expected Σ(N_a + 1) values and bounds per phase");
  if (P > 1 && !problem_.free_final_time())
    throw InvalidInput("collocation phases: " + std::to_string(P) +
                       " phases; expected one phase for a fixed final time");
  set_up();
}

void CollocationNlp::set_up() {
  phase_first_interval_ = {0};
  for (const int n : phases_.intervals) {
    if (n < 1)
      throw InvalidInput("collocation phases: a phase with " + std::to_string(n) +
                         " intervals; expected at least 1");
    for (int k = 0; k < n; ++k)
      interval_phase_.push_back(static_cast<int>(phase_first_interval_.size()) - 1);
    phase_first_interval_.push_back(phase_first_interval_.back() + n);
  }
  int row = 0;
  for (int a = 0; a < phases(); ++a)
    for (int p = phase_first_point(a); p <= phase_last_point(a); ++p) {
      point_phase_.push_back(a);
      norm_row_.push_back(p == phase_first_point(a) ? -1 : row++);
    }
  if (problem_.wheels) {
    const ReactionWheels& w = *problem_.wheels;
    const Mat3 Jb = problem_.bus_inertia();
    dyn_ = CollocationDynamics::wheels(Jb, w.axes_body, problem_.wheel_system_momentum());
    const Mat3 A_inv = w.axes_body.inverse();
    momentum_bounded_ = w.has_momentum_bound();
    momentum_rate_rows_ = A_inv * Jb;
    for (int k = 0; k < 3; ++k)
      momentum_forms_[k] = A_inv(k, 0) * dyn_.M[0] + A_inv(k, 1) * dyn_.M[1] + A_inv(k, 2) * dyn_.M[2];
  } else {
    dyn_ = CollocationDynamics::body(problem_.inertia_body);
  }
  // Left multiplication by a = q_f* = (w, −v): rows 1..3 of [[a0, −avᵀ], [av, a0 I + j(av)]].
  const Quat& qf = problem_.attitude_final;
  const double a0 = qf.w();
  const Vec3 av = -qf.vec();
  final_attitude_rows_.col(0) = av;
  final_attitude_rows_.block<3, 3>(0, 1) = a0 * Mat3::Identity() + hat(av);
  for (const PointingConstraint& c : problem_.pointing)
    pointing_forms_.push_back(c.quadratic_form());
}

std::vector<double> CollocationNlp::point_times(const double* z) const {
  std::vector<double> t;
  double start = 0.0;
  for (int a = 0; a < phases(); ++a) {
    const double D = z[duration_index(a)];
    for (int k = phase_first_interval_[a]; k < phase_first_interval_[a + 1]; ++k) {
      const double t0 = tau_[k + a], t1 = tau_[k + a + 1];
      t.push_back(start + t0 * D);
      t.push_back(start + 0.5 * (t0 + t1) * D);
    }
    start += D;
    t.push_back(start);
  }
  return t;
}

double CollocationNlp::final_time(const double* z) const {
  double T = 0.0;
  for (int a = 0; a < phases(); ++a)
    T += z[duration_index(a)];
  return T;
}

int CollocationNlp::num_constraints() const {
  return momentum_rows_begin() + (momentum_bounded_ ? 3 * (points() - phases()) : 0);
}

double CollocationNlp::quadrature_weight(int p) const {
  const int a = point_phase_[p], l = p - phase_first_point(a), k0 = phase_first_interval_[a];
  if (l % 2 == 1) return 4.0 / 6.0 * step_fraction(k0 + (l - 1) / 2);
  const int k = k0 + l / 2;  // the interval whose left node p is (when k < the phase's end)
  double w = 0.0;
  if (k > k0) w += step_fraction(k - 1) / 6.0;
  if (k < phase_first_interval_[a + 1]) w += step_fraction(k) / 6.0;
  return w;
}

Vec7 CollocationNlp::defect_weight(int p, const double* y) const {
  const int a = point_phase_[p], l = p - phase_first_point(a), k0 = phase_first_interval_[a];
  if (l % 2 == 1) {
    const int k = k0 + (l - 1) / 2;
    return -4.0 / 6.0 * step_fraction(k) * Eigen::Map<const Vec7>(y + 14 * k);
  }
  const int k = k0 + l / 2;
  Vec7 c = Vec7::Zero();
  if (k > k0) {
    const double h = step_fraction(k - 1);
    c += -h / 6.0 * Eigen::Map<const Vec7>(y + 14 * (k - 1)) +
         h / 8.0 * Eigen::Map<const Vec7>(y + 14 * (k - 1) + 7);
  }
  if (k < phase_first_interval_[a + 1]) {
    const double h = step_fraction(k);
    c += -h / 6.0 * Eigen::Map<const Vec7>(y + 14 * k) - h / 8.0 * Eigen::Map<const Vec7>(y + 14 * k + 7);
  }
  return c;
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
    const int a = point_phase_[pt];
    for (int i = 0; i < 3; ++i) {
      if (p.has_rate_bound()) {
        lo[b + 4 + i] = -p.rate_max;
        up[b + 4 + i] = p.rate_max;
      }
      const double umax = p.bound == TorqueBound::per_axis ? p.torque_max[i] : p.torque_max[0];
      lo[b + 7 + i] = phases_.torque_lower.empty() ? -umax : phases_.torque_lower[a][i];
      up[b + 7 + i] = phases_.torque_upper.empty() ? umax : phases_.torque_upper[a][i];
    }
    if (pt == phase_first_point(a)) lo[b + 10] = up[b + 10] = 0.0;  // ν at a phase's first point (see above)
  }
  const int last = kPointVars * (points() - 1);
  for (int i = 0; i < 4; ++i)
    lo[i] = up[i] = p.attitude_initial.coeffs()[(i + 3) % 4];  // (w, x, y, z)
  lo[10] = up[10] = 0.0;  // ν_0: q_0 is fixed and unit, and every later ν is fixed by its point's ‖q‖ = 1
  for (int i = 0; i < 3; ++i) {
    lo[4 + i] = up[4 + i] = p.omega_initial[i];
    lo[last + 4 + i] = up[last + 4 + i] = p.omega_final[i];
  }
  if (phases() > 1) {
    for (int a = 0; a < phases(); ++a) {
      lo[duration_index(a)] = 0.0;
      up[duration_index(a)] = kInf;
    }
  } else if (p.free_final_time()) {
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
  for (int p = 0; p < points(); ++p)
    for (int c = 0; c < pointing_count() && norm_row_[p] >= 0; ++c) {
      const PointingConstraint& pc = problem_.pointing[c];
      const bool out = pc.kind == PointingKind::keep_out;
      lo[pointing_row(p, c)] = out ? -kInf : std::cos(pc.half_angle);
      up[pointing_row(p, c)] = out ? std::cos(pc.half_angle) : kInf;
    }
  for (int p = 0; p < points(); ++p)
    for (int k = 0; k < 3 && momentum_row(p, k) >= 0; ++k) {
      const double hmax = problem_.wheels->momentum_max[k];
      lo[momentum_row(p, k)] = std::isfinite(hmax) ? -hmax : -kInf;
      up[momentum_row(p, k)] = std::isfinite(hmax) ? hmax : kInf;
    }
}

double CollocationNlp::objective(const double* z) const {
  double e = 0.0;
  if (energy_weight() != 0.0)
    for (int p = 0; p < points(); ++p)
      e +=
          z[duration_index(point_phase_[p])] * quadrature_weight(p) * point(z, p).segment<3>(7).squaredNorm();
  return time_weight() * final_time(z) + energy_weight() * e;
}

void CollocationNlp::objective_gradient(const double* z, double* grad) const {
  std::fill(grad, grad + num_variables(), 0.0);
  const double a = energy_weight();
  for (int ph = 0; ph < phases(); ++ph)
    grad[duration_index(ph)] = time_weight();
  if (a != 0.0)
    for (int p = 0; p < points(); ++p) {
      const Vec3 u = point(z, p).segment<3>(7);
      const double w = quadrature_weight(p), D = z[duration_index(point_phase_[p])];
      grad[duration_index(point_phase_[p])] += a * w * u.squaredNorm();
      for (int i = 0; i < 3; ++i)
        grad[kPointVars * p + 7 + i] = 2.0 * a * w * D * u[i];
    }
}

void CollocationNlp::constraints(const double* z, double* g) const {
  for (int k = 0; k < intervals(); ++k) {
    const int b = interval_first_point(k);
    const Vec11 z0 = point(z, b), z1 = point(z, b + 1), z2 = point(z, b + 2);
    const Vec7 f0 = dyn_.rhs(z0), f1 = dyn_.rhs(z1), f2 = dyn_.rhs(z2);
    const double h = interval_step(z, k);
    Eigen::Map<Vec7>(g + 14 * k) = z2.head<7>() - z0.head<7>() - h / 6.0 * (f0 + 4.0 * f1 + f2);
    Eigen::Map<Vec7>(g + 14 * k + 7) =
        z1.head<7>() - 0.5 * (z0.head<7>() + z2.head<7>()) - h / 8.0 * (f0 - f2);
  }
  for (int p = 0; p < points(); ++p)
    if (norm_row_[p] >= 0) g[norm_rows_begin() + norm_row_[p]] = point(z, p).head<4>().squaredNorm() - 1.0;
  for (int a = 0; a + 1 < phases(); ++a)
    Eigen::Map<Vec7>(g + link_rows_begin() + 7 * a) =
        point(z, phase_last_point(a)).head<7>() - point(z, phase_first_point(a + 1)).head<7>();
  if (final_rows() == 3)
    Eigen::Map<Vec3>(g + final_rows_begin()) = final_attitude_rows_ * point(z, points() - 1).head<4>();
  if (problem_.bound == TorqueBound::norm)
    for (int p = 0; p < points(); ++p)
      g[torque_norm_rows_begin() + p] = point(z, p).segment<3>(7).squaredNorm();
  for (int p = 0; p < points(); ++p)
    for (int c = 0; c < pointing_count() && norm_row_[p] >= 0; ++c) {
      const Vec4 q = point(z, p).head<4>();
      g[pointing_row(p, c)] = q.dot(pointing_forms_[c] * q);
    }
  for (int p = 0; p < points(); ++p)
    for (int k = 0; k < 3 && momentum_row(p, k) >= 0; ++k)
      g[momentum_row(p, k)] = wheel_momentum(point(z, p), k);
}

int CollocationNlp::jacobian_nonzeros() const {
  const int per_interval = 14 * (3 * kPointVars + 1);
  const int torque = problem_.bound == TorqueBound::norm ? 3 * points() : 0;
  return intervals() * per_interval + 4 * (points() - phases()) + 14 * (phases() - 1) + 4 * final_rows() +
         torque + 4 * pointing_count() * (points() - phases()) +
         (momentum_bounded_ ? 3 * 7 * (points() - phases()) : 0);
}

void CollocationNlp::jacobian_structure(int* rows, int* cols) const {
  int n = 0;
  for (int k = 0; k < intervals(); ++k)
    for (int r = 0; r < 14; ++r) {
      for (int j = 0; j < 3; ++j)
        for (int c = 0; c < kPointVars; ++c) {
          rows[n] = 14 * k + r;
          cols[n++] = kPointVars * (interval_first_point(k) + j) + c;
        }
      rows[n] = 14 * k + r;
      cols[n++] = duration_index(interval_phase_[k]);
    }
  for (int p = 0; p < points(); ++p)
    for (int c = 0; c < 4 && norm_row_[p] >= 0; ++c) {
      rows[n] = norm_rows_begin() + norm_row_[p];
      cols[n++] = kPointVars * p + c;
    }
  for (int a = 0; a + 1 < phases(); ++a)
    for (int r = 0; r < 7; ++r) {
      rows[n] = rows[n + 1] = link_rows_begin() + 7 * a + r;
      cols[n++] = kPointVars * phase_last_point(a) + r;
      cols[n++] = kPointVars * phase_first_point(a + 1) + r;
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
  for (int p = 0; p < points(); ++p)
    for (int c = 0; c < pointing_count() && norm_row_[p] >= 0; ++c)
      for (int i = 0; i < 4; ++i) {
        rows[n] = pointing_row(p, c);
        cols[n++] = kPointVars * p + i;
      }
  for (int p = 0; p < points(); ++p)
    for (int k = 0; k < 3 && momentum_row(p, k) >= 0; ++k)
      for (int i = 0; i < 7; ++i) {
        rows[n] = momentum_row(p, k);
        cols[n++] = kPointVars * p + i;
      }
}

void CollocationNlp::jacobian_values(const double* z, double* v) const {
  Mat7x11 I7 = Mat7x11::Zero();
  I7.leftCols<7>().setIdentity();
  int n = 0;
  for (int k = 0; k < intervals(); ++k) {
    const int b = interval_first_point(k);
    const Vec11 z0 = point(z, b), z1 = point(z, b + 1), z2 = point(z, b + 2);
    const Vec7 f0 = dyn_.rhs(z0), f1 = dyn_.rhs(z1), f2 = dyn_.rhs(z2);
    const Mat7x11 A0 = dyn_.jacobian(z0), A1 = dyn_.jacobian(z1), A2 = dyn_.jacobian(z2);
    const double dt = step_fraction(k), h = interval_step(z, k);
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
  for (int p = 0; p < points(); ++p)
    for (int c = 0; c < 4 && norm_row_[p] >= 0; ++c)
      v[n++] = 2.0 * z[kPointVars * p + c];
  for (int a = 0; a + 1 < phases(); ++a)
    for (int r = 0; r < 7; ++r) {
      v[n++] = 1.0;
      v[n++] = -1.0;
    }
  for (int r = 0; r < final_rows(); ++r)
    for (int c = 0; c < 4; ++c)
      v[n++] = final_attitude_rows_(r, c);
  if (problem_.bound == TorqueBound::norm)
    for (int p = 0; p < points(); ++p)
      for (int c = 0; c < 3; ++c)
        v[n++] = 2.0 * z[kPointVars * p + 7 + c];
  for (int p = 0; p < points(); ++p)
    for (int c = 0; c < pointing_count() && norm_row_[p] >= 0; ++c) {
      const Vec4 grad = 2.0 * pointing_forms_[c] * point(z, p).head<4>();
      for (int i = 0; i < 4; ++i)
        v[n++] = grad[i];
    }
  for (int p = 0; p < points(); ++p)
    for (int k = 0; k < 3 && momentum_row(p, k) >= 0; ++k) {
      const Vec4 grad = 2.0 * momentum_forms_[k] * point(z, p).head<4>();
      for (int i = 0; i < 4; ++i)
        v[n++] = grad[i];
      for (int i = 0; i < 3; ++i)
        v[n++] = -momentum_rate_rows_(k, i);
    }
}

int CollocationNlp::hessian_nonzeros() const {
  return points() * (kPointVars * (kPointVars + 1) / 2 + kPointVars) + phases();
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
      rows[n] = duration_index(point_phase_[p]);
      cols[n++] = b + c;
    }
  }
  for (int a = 0; a < phases(); ++a) {
    rows[n] = duration_index(a);
    cols[n++] = duration_index(a);
  }
}

void CollocationNlp::hessian_values(const double* z, double sigma, const double* y, double* v) const {
  const double a = energy_weight();
  int n = 0;
  for (int p = 0; p < points(); ++p) {
    const double D = z[duration_index(point_phase_[p])];
    const Vec7 c_unit = defect_weight(p, y);  // yᵀg contains D (c_unit · f_p)
    const Vec11 zp = point(z, p);
    Mat11 H = dyn_.weighted_hessian(D * c_unit, zp);
    if (norm_row_[p] >= 0)
      H.block<4, 4>(0, 0).diagonal().array() += 2.0 * y[norm_rows_begin() + norm_row_[p]];
    if (problem_.bound == TorqueBound::norm)
      H.block<3, 3>(7, 7).diagonal().array() += 2.0 * y[torque_norm_rows_begin() + p];
    for (int c = 0; c < pointing_count() && norm_row_[p] >= 0; ++c)
      H.block<4, 4>(0, 0) += 2.0 * y[pointing_row(p, c)] * pointing_forms_[c];
    for (int k = 0; k < 3 && momentum_row(p, k) >= 0; ++k)
      H.block<4, 4>(0, 0) += 2.0 * y[momentum_row(p, k)] * momentum_forms_[k];
    const double w = quadrature_weight(p);
    H.block<3, 3>(7, 7).diagonal().array() += sigma * 2.0 * a * w * D;
    for (int r = 0; r < kPointVars; ++r)
      for (int col = 0; col <= r; ++col)
        v[n++] = H(r, col);
    // ∂²/∂Δ∂z_p: c_unitᵀ ∂f_p/∂z_p, plus the objective's 2 α w_p u_p.
    Vec11 cross = dyn_.jacobian(zp).transpose() * c_unit;
    cross.segment<3>(7) += sigma * 2.0 * a * w * zp.segment<3>(7);
    for (int col = 0; col < kPointVars; ++col)
      v[n++] = cross[col];
  }
  for (int ph = 0; ph < phases(); ++ph)
    v[n++] = 0.0;
}

}  // namespace poinsot::optimal::detail
