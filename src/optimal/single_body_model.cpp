// One rigid body as a point model of the Hermite–Simpson transcription (single_body_model.hpp).
#include "single_body_model.hpp"

#include <cmath>
#include <utility>

namespace poinsot::optimal::detail {

namespace {

/// f(w) of collocation_dynamics.hpp as point functions, its Hessian ∇²(cᵀf) exact
/// (CollocationDynamics::weighted_hessian). Both patterns are dense (7 × 11 and the lower triangle of 11 ×
/// 11) although some entries are always zero: with the exact sparse blocks MUMPS orders the KKT matrix of the
/// single body worse, and Betts' direct solve took 20 to 50 % longer (bench_optimal, measured alternately).
class RigidBodyRhs final : public PointFunctions {
 public:
  explicit RigidBodyRhs(const CollocationDynamics& dyn) : dyn_(dyn) {
    for (int r = 0; r < 7; ++r)
      for (int c = 0; c < 11; ++c)
        jac_.emplace_back(r, c);
    for (int i = 0; i < 11; ++i)
      for (int j = 0; j <= i; ++j)
        hess_.emplace_back(i, j);
  }

  int rows() const override { return 7; }
  void values(const double* w, double* out) const override {
    Eigen::Map<Vec7> f(out);
    f = dyn_.rhs(Eigen::Map<const Vec11>(w));
  }
  const std::vector<IndexPair>& jacobian_pattern() const override { return jac_; }
  void jacobian_values(const double* w, double* values) const override {
    const Mat7x11 a = dyn_.jacobian(Eigen::Map<const Vec11>(w));
    for (const auto& [r, c] : jac_)
      *values++ = a(r, c);
  }
  const std::vector<IndexPair>& hessian_pattern() const override { return hess_; }
  void hessian_values(const double* w, const double* weights, double* values) const override {
    const Mat11 h = dyn_.weighted_hessian(Eigen::Map<const Vec7>(weights), Eigen::Map<const Vec11>(w));
    for (const auto& [i, j] : hess_)
      *values++ = h(i, j);
  }

 private:
  const CollocationDynamics& dyn_;
  std::vector<IndexPair> jac_, hess_;
};

/// Adds the row Σ_ij F_ij q_i q_j (F symmetric, q = w[0..4)) to `rows` and returns it.
int add_quaternion_form(QuadraticFunctions& rows, const Eigen::Matrix4d& F) {
  const int r = rows.add_row();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j <= i; ++j)
      if (F(i, j) != 0.0) rows.add_bilinear(r, i, j, i == j ? F(i, i) : 2.0 * F(i, j));
  return r;
}

}  // namespace

SingleBodyModel::SingleBodyModel(const ReorientationProblem& problem, CollocationPhases phases)
    : problem_(problem), phases_(std::move(phases)) {
  if (problem_.wheels) {
    dyn_ = CollocationDynamics::wheels(problem_.bus_inertia(), problem_.wheels->axes_body,
                                       problem_.wheel_system_momentum());
    momentum_bounded_ = problem_.wheels->has_momentum_bound();
  } else {
    dyn_ = CollocationDynamics::body(problem_.inertia_body);
  }
  rhs_ = std::make_unique<RigidBodyRhs>(dyn_);
  build_paths();
}

void SingleBodyModel::build_paths() {
  const auto add_torque_norm = [&](QuadraticFunctions& rows) {
    const int r = rows.add_row();
    for (int i = 7; i < 10; ++i)
      rows.add_bilinear(r, i, i, 1.0);
  };
  if (norm_rows() == 1) add_torque_norm(first_path_);
  const int norm = add_quaternion_form(path_, Eigen::Matrix4d::Identity());
  path_.add_constant(norm, -1.0);
  if (norm_rows() == 1) add_torque_norm(path_);
  for (const PointingConstraint& c : problem_.pointing)
    add_quaternion_form(path_, c.quadratic_form());
  if (momentum_bounded_) {
    const Mat3 A_inv = problem_.wheels->axes_body.inverse();
    const Mat3 g = A_inv * problem_.bus_inertia();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Matrix4d N = A_inv(k, 0) * dyn_.M[0] + A_inv(k, 1) * dyn_.M[1] + A_inv(k, 2) * dyn_.M[2];
      const int r = add_quaternion_form(path_, N);
      for (int i = 0; i < 3; ++i)
        if (g(k, i) != 0.0) path_.add_linear(r, 4 + i, -g(k, i));
    }
  }
  first_path_.finish();
  path_.finish();
}

void SingleBodyModel::path_bounds(bool first_of_phase, double* lower, double* upper) const {
  int r = 0;
  const auto set = [&](double lo, double up) {
    lower[r] = lo;
    upper[r++] = up;
  };
  const double u_max = problem_.torque_max[0];
  if (first_of_phase) {
    if (norm_rows() == 1) set(-kNoBound, u_max * u_max);
    return;
  }
  set(0.0, 0.0);
  if (norm_rows() == 1) set(-kNoBound, u_max * u_max);
  for (const PointingConstraint& c : problem_.pointing) {
    const bool out = c.kind == PointingKind::keep_out;
    set(out ? -kNoBound : std::cos(c.half_angle), out ? std::cos(c.half_angle) : kNoBound);
  }
  if (momentum_bounded_)
    for (int k = 0; k < 3; ++k) {
      const double h = problem_.wheels->momentum_max[k];
      set(std::isfinite(h) ? -h : -kNoBound, std::isfinite(h) ? h : kNoBound);
    }
}

void SingleBodyModel::variable_bounds(const PointRole& role, double* lo, double* up) const {
  const ReorientationProblem& p = problem_;
  for (int i = 0; i < kPointVars; ++i) {
    lo[i] = -kNoBound;
    up[i] = kNoBound;
  }
  const auto a = static_cast<std::size_t>(role.phase);
  for (int i = 0; i < 3; ++i) {
    if (p.has_rate_bound()) {
      lo[4 + i] = -p.rate_max;
      up[4 + i] = p.rate_max;
    }
    const double u_max = p.bound == TorqueBound::per_axis ? p.torque_max[i] : p.torque_max[0];
    lo[7 + i] = phases_.torque_lower.empty() ? -u_max : phases_.torque_lower[a][i];
    up[7 + i] = phases_.torque_upper.empty() ? u_max : phases_.torque_upper[a][i];
  }
  // ν at a phase's first point: its q is unit (given, or the previous phase's last q, whose ν the path row
  // ‖q‖ = 1 fixes), so ν = 0 there.
  if (role.first_of_phase) lo[10] = up[10] = 0.0;
  if (role.last)
    for (int i = 0; i < 3; ++i)
      lo[4 + i] = up[4 + i] = p.omega_final[i];
}

Eigen::VectorXd SingleBodyModel::initial_state() const {
  Eigen::VectorXd y(kStateVars);
  const Quat& q = problem_.attitude_initial;
  y << q.w(), q.x(), q.y(), q.z(), problem_.omega_initial;
  return y;
}

Eigen::MatrixXd SingleBodyModel::final_rows() const {
  if (final_row_count() == 0) return Eigen::MatrixXd::Zero(0, kStateVars);
  // Left multiplication by a = q_f* = (w, −v): rows 1..3 of [[a0, −avᵀ], [av, a0 I + j(av)]].
  const Quat& qf = problem_.attitude_final;
  const Vec3 av = -qf.vec();
  Eigen::MatrixXd rows = Eigen::MatrixXd::Zero(final_row_count(), kStateVars);
  rows.col(0) = av;
  rows.block<3, 3>(0, 1) = qf.w() * Mat3::Identity() + hat(av);
  return rows;
}

}  // namespace poinsot::optimal::detail
