#pragma once
/// @file hermite_simpson_dae.hpp (internal)
/// The Hermite–Simpson transcription (separated form; Betts 2010, §4.6) of a differential-algebraic optimal
/// control problem, for any point model (CollocationModel):
///
///     ẏ = f(w),  c(w) = 0 at every collocation point,  w = (y, z, u),  y(0) = y₀,  A y(T) = b,
///     minimise ∫ Σ_{i ∈ controls} w_i² dt  (Simpson's rule)            at fixed T, or
///     minimise T + ε ∫ Σ_{i ∈ controls} w_i² dt,  T_min ≤ T ≤ T_max     with T free (FreeFinalTime).
///
/// A free final time is the last NLP variable, with time scaled as t = T τ on a fixed mesh in τ ∈ [0, 1]:
/// h = T/N in the defects and the quadrature weights, so D_k, M_k and the objective are linear in T for
/// fixed w, and their derivatives with respect to T (the Jacobian column of T, the Hessian row of T) are
/// the defects' f-terms and the quadrature divided by T.
///
/// Mesh: N intervals of h_k = T Δτ_k (equal, Δτ_k = 1/N, unless fractions Δτ_k > 0 summing to 1 are given).
/// Points p = 0 … 2N: even p = node p/2, odd p = midpoint. Variables: w_p for every point (the point model's
/// layout). Constraints, in this order:
///   D_k = y_{k+1} − y_k − h/6 (f_k + 4 f_m + f_{k+1}),   M_k = y_m − ½(y_k + y_{k+1}) − h/8 (f_k − f_{k+1})
///   (n_y rows each, interleaved per interval); then c at every point (the model's `first_path` at node 0,
///   `path` elsewhere); then A y_{2N} − b. With Ipopt's Lagrangian σJ + yᵀg, the multipliers of D_k estimate
///   −λ(t_k + h/2) (the costate of the minimum principle).
#include <vector>

#include "poinsot/core/types.hpp"
#include "point_functions.hpp"
#include "sparse_nlp.hpp"

namespace poinsot::optimal::detail {

class CollocationModel {
 public:
  virtual ~CollocationModel() = default;
  virtual int state_size() const = 0;  ///< y = w[0 .. state_size)
  virtual int point_size() const = 0;
  virtual const std::vector<int>& control_indices() const = 0;  ///< where the controls sit in w
  virtual const PointFunctions& rhs() const = 0;                ///< f(w), state_size rows
  virtual const PointFunctions& first_path() const = 0;         ///< c(w) at node 0
  virtual const PointFunctions& path() const = 0;               ///< c(w) at every other point
  /// Bounds on w (±inf where none); `first_node` for node 0 (whose y the engine fixes to y₀ anyway).
  virtual void variable_bounds(bool first_node, double* lower, double* upper) const = 0;
};

/// A free final time: T ∈ [lower, upper] (s, 0 < lower ≤ upper), the objective T + energy_weight ∫ Σ u² dt.
struct FreeFinalTime {
  double lower = 0.0;
  double upper = 0.0;
  double energy_weight = 0.0;  ///< ε ≥ 0 (s per N²·m²·s): a regularisation of the bang-bang optimum
};

class HermiteSimpsonDae final : public SparseNlp {
 public:
  /// `final_time` is T when `free_time` is null, else the initial guess of T (not used by the NLP).
  /// `fractions`: the intervals' Δτ_k (their number replaces `intervals`; positive, summing to 1, not checked
  /// here), or empty for `intervals` equal ones.
  HermiteSimpsonDae(const CollocationModel& model, int intervals, double final_time, Eigen::VectorXd y0,
                    Eigen::MatrixXd final_rows, Eigen::VectorXd final_values,
                    const FreeFinalTime* free_time = nullptr, std::vector<double> fractions = {});

  int intervals() const { return intervals_; }
  int points() const { return 2 * intervals_ + 1; }
  const CollocationModel& model() const { return model_; }
  bool free_time() const { return free_; }
  int time_index() const { return model_.point_size() * points(); }  ///< T's variable when free
  /// T (s) at the variables x: x[time_index()] when free, else the fixed final time.
  double final_time(const double* x) const { return free_ ? x[time_index()] : final_time_; }
  /// Time of point p (s) for the final time T.
  double point_time(int p, double T) const {
    if (equal_) return 0.5 * T / intervals_ * p;
    const auto k = static_cast<std::size_t>(p / 2);
    return T * (p % 2 == 0 ? tau_[k] : tau_[k] + 0.5 * dtau_[k]);
  }
  int path_row(int p) const;  ///< first row of point p's path constraints

  int num_variables() const override { return time_index() + (free_ ? 1 : 0); }
  int num_constraints() const override;
  void bounds(std::vector<double>& x_lower, std::vector<double>& x_upper, std::vector<double>& g_lower,
              std::vector<double>& g_upper) const override;
  double objective(const double* x) const override;
  void objective_gradient(const double* x, double* gradient) const override;
  void constraints(const double* x, double* g) const override;
  int jacobian_nonzeros() const override { return static_cast<int>(jac_rows_.size()); }
  void jacobian_structure(int* rows, int* cols) const override;
  void jacobian_values(const double* x, double* values) const override;
  int hessian_nonzeros() const override { return static_cast<int>(hess_rows_.size()); }
  void hessian_structure(int* rows, int* cols) const override;
  void hessian_values(const double* x, double sigma, const double* y, double* values) const override;

 private:
  /// Simpson weight of point p divided by T (dimensionless: the weight is T times it).
  double unit_weight(int p) const;
  /// h_k (s) of interval k for the final time T.
  double interval_step(int k, double T) const {
    return equal_ ? T / intervals_ : T * dtau_[static_cast<std::size_t>(k)];
  }
  double energy_weight() const { return free_ ? free_time_.energy_weight : 1.0; }
  const PointFunctions& path_of(int p) const { return p == 0 ? model_.first_path() : model_.path(); }

  const CollocationModel& model_;
  int intervals_;
  bool equal_;                // equal intervals: h = T/N exactly as written (no round-off of T·(1/N))
  std::vector<double> dtau_;  // Δτ_k per interval
  std::vector<double> tau_;   // τ of every node (N + 1)
  double final_time_;
  Eigen::VectorXd y0_;
  Eigen::MatrixXd final_rows_;
  Eigen::VectorXd final_values_;
  bool free_ = false;
  FreeFinalTime free_time_;
  std::vector<int> jac_rows_, jac_cols_;
  std::vector<int> hess_rows_, hess_cols_;
  std::vector<std::vector<int>> hess_rhs_, hess_path_;  // per point: local pattern entry → global entry
  std::vector<std::vector<int>> hess_objective_;        // per point: control k → global entry
  // Free final time, per point: the (T, w) entries of the f-terms (per rhs Jacobian entry) and of the
  // objective (per control).
  std::vector<std::vector<int>> hess_time_rhs_, hess_time_objective_;
};

}  // namespace poinsot::optimal::detail
