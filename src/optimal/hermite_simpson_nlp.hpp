#pragma once
/// @file hermite_simpson_nlp.hpp (internal)
/// The Hermite–Simpson transcription (separated form; Betts 2010, §4.6) of an optimal control problem of a
/// differential-algebraic system, for any point model (CollocationModel): one rigid body
/// (single_body_model.hpp) or coupled bodies (multibody_rotation_model.hpp, multibody_minimal_model.hpp).
///
///     ẏ = f(w),  lower ≤ c(w) ≤ upper at every collocation point,  w = (y, z, u),  y(0) = y₀,  A y(T) = b,
///     minimise β T + α ∫ Σ_{i ∈ controls} w_i² dt  (Simpson's rule).
///
/// Mesh (collocation_mesh.hpp): phases of durations Δ_a, T = Σ Δ_a, h_k = Δτ_k Δ_a. The durations are
/// variables (after the points' variables, one per phase) when the final time is free, each within its
/// bounds; at a fixed final time there is one phase and no duration variable. The defects, the constraints'
/// f-terms and the objective are linear in each Δ_a for fixed w, so their derivatives with respect to Δ_a are
/// the f-terms and the quadrature divided by Δ_a.
///
/// Variables: w_p for every point p (the model's layout, point_size() each), then the durations. Constraints,
/// in this order:
///   D_k = y_{k+1} − y_k − h_k/6 (f_k + 4 f_m + f_{k+1})           (Simpson defect, n_y rows)
///   M_k = y_m − ½(y_k + y_{k+1}) − h_k/8 (f_k − f_{k+1})         (Hermite midpoint, n_y rows)
///   interleaved per interval (defect_row(k)); then c at every point (the model's `first_path` at the first
///   point of each phase, whose state is given or linked, `path` elsewhere; path_row(p)); then
///   y_{last of phase a} − y_{first of phase a+1} = 0 (n_y rows per phase boundary); then A y_last − b.
///
/// The costate sign convention lives here (costate): with Ipopt's Lagrangian σJ + yᵀg, the multipliers of
/// D_k estimate −λ(t_k + h_k/2), λ the costate of the minimum principle (H = L + λᵀf).
#include <vector>

#include "collocation_mesh.hpp"
#include "poinsot/core/types.hpp"
#include "point_functions.hpp"
#include "sparse_nlp.hpp"

namespace poinsot::optimal::detail {

/// The bound that stands for "none" (above Ipopt's default nlp_upper_bound_inf = 1e19, so Ipopt drops it).
inline constexpr double kNoBound = 2e19;

/// Where a point sits in the mesh, for the bounds on its variables.
struct PointRole {
  int phase = 0;
  bool first = false;           ///< the first point of all: the state y₀
  bool first_of_phase = false;  ///< the first point of a phase: its state is y₀ or the previous phase's last
  bool last = false;            ///< the last point of all
};

class CollocationModel {
 public:
  virtual ~CollocationModel() = default;
  virtual int state_size() const = 0;  ///< y = w[0 .. state_size)
  virtual int point_size() const = 0;
  virtual const std::vector<int>& control_indices() const = 0;  ///< where the controls sit in w
  virtual const PointFunctions& rhs() const = 0;                ///< f(w), state_size rows
  virtual const PointFunctions& first_path() const = 0;         ///< c(w) at the first point of each phase
  virtual const PointFunctions& path() const = 0;               ///< c(w) at every other point
  /// Bounds on the rows of first_path (`first_of_phase`) or path: equalities c = 0 unless overridden.
  virtual void path_bounds(bool first_of_phase, double* lower, double* upper) const;
  /// Bounds on w (±inf where none); the engine fixes the first point's y to y₀ after these.
  virtual void variable_bounds(const PointRole& role, double* lower, double* upper) const = 0;
};

/// The final time: fixed (one phase, no duration variable) or free, with bounds on every phase's duration.
struct CollocationTime {
  double fixed = 0.0;                ///< T (s) when `lower` is empty
  std::vector<double> lower, upper;  ///< per phase (s, 0 ≤ lower ≤ upper) when free
  bool free() const { return !lower.empty(); }
  static CollocationTime at(double T) { return {T, {}, {}}; }
};

/// The objective β T + α ∫ Σ u² dt (β ≥ 0 1/s-free, α ≥ 0).
struct CollocationObjective {
  double time_weight = 0.0;    ///< β
  double energy_weight = 1.0;  ///< α
};

class HermiteSimpsonNlp final : public SparseNlp {
 public:
  /// `model` must outlive this object. `time` has one duration bound per phase of `mesh` when free; a fixed
  /// time needs one phase. `final_rows` (A, n_f × n_y) and `final_values` (b) constrain the last point's
  /// state. Throws InvalidInput when the sizes disagree.
  HermiteSimpsonNlp(const CollocationModel& model, CollocationMesh mesh, Eigen::VectorXd y0,
                    Eigen::MatrixXd final_rows, Eigen::VectorXd final_values, CollocationTime time,
                    CollocationObjective objective);

  const CollocationMesh& mesh() const { return mesh_; }
  const CollocationModel& model() const { return model_; }
  int intervals() const { return mesh_.intervals(); }
  int points() const { return mesh_.points(); }
  bool free_time() const { return time_.free(); }
  /// The duration variable of phase a (free final time only).
  int duration_index(int a) const { return model_.point_size() * points() + a; }
  int time_index() const { return duration_index(0); }
  /// Δ_a (s) at the variables x.
  double duration(const double* x, int a) const { return free_time() ? x[duration_index(a)] : time_.fixed; }
  /// T = Σ Δ_a (s) at the variables x.
  double final_time(const double* x) const;
  /// h_k (s) at the variables x.
  double interval_step(const double* x, int k) const {
    return mesh_.step(k, duration(x, mesh_.interval_phase(k)));
  }
  /// The time of every point (s) at the variables x.
  std::vector<double> point_times(const double* x) const;
  /// The first row of interval k's Simpson defect (its Hermite rows follow).
  int defect_row(int k) const { return 2 * model_.state_size() * k; }
  int path_row(int p) const;  ///< the first row of point p's path constraints
  /// λ(t_k + h_k/2), the minimum principle's costate at interval k's midpoint, from the constraint
  /// multipliers y (see the file's comment for the sign).
  Eigen::VectorXd costate(const std::vector<double>& y, int k) const;

  int num_variables() const override {
    return model_.point_size() * points() + (free_time() ? mesh_.phases() : 0);
  }
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
  const PointFunctions& path_of(int p) const {
    return mesh_.first_of_phase(p) ? model_.first_path() : model_.path();
  }
  int link_row(int a) const { return path_row(points()) + model_.state_size() * a; }
  int final_row() const { return link_row(mesh_.phases() - 1); }
  /// c_p / Δ: the weight of f_p in yᵀg per unit duration of its phase (every defect is linear in f_p).
  Eigen::VectorXd defect_weight(int p, const double* y) const;
  void build_jacobian_structure();
  void build_hessian_structure();

  const CollocationModel& model_;
  CollocationMesh mesh_;
  Eigen::VectorXd y0_;
  Eigen::MatrixXd final_rows_;
  Eigen::VectorXd final_values_;
  CollocationTime time_;
  CollocationObjective objective_;
  std::vector<int> jac_rows_, jac_cols_;
  std::vector<int> hess_rows_, hess_cols_;
  std::vector<std::vector<int>> hess_rhs_, hess_path_;  // per point: local pattern entry → global entry
  std::vector<std::vector<int>> hess_objective_;        // per point: control k → global entry
  // Free final time, per point: the (Δ, w) entries of the f-terms (per rhs Jacobian entry) and of the
  // objective (per control).
  std::vector<std::vector<int>> hess_time_rhs_, hess_time_objective_;
};

}  // namespace poinsot::optimal::detail
