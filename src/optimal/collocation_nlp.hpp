#pragma once
/// @file collocation_nlp.hpp (internal)
/// The Hermite–Simpson transcription (separated form, Betts 2010, §4.6) of a ReorientationProblem into a
/// nonlinear program, independent of the NLP solver: variables, bounds, objective, constraints and their
/// exact sparse first and second derivatives.
///
/// Mesh 0 = τ_0 < … < τ_N = 1, t = τ T, h_k = (τ_{k+1} − τ_k) T. Points p = 0 … 2N: even p = node k = p/2,
/// odd p = midpoint of interval (p − 1)/2. Each point carries z_p = (q, ω, u, ν) (11 variables); T is the
/// last variable (fixed by its bounds for minimum_energy). Constraints, in this order:
///   D_k = x_{k+1} − x_k − h_k/6 (f_k + 4 f_m + f_{k+1})          (Simpson defect, 7 per interval)
///   M_k = x_m − ½ (x_k + x_{k+1}) − h_k/8 (f_k − f_{k+1})        (Hermite midpoint, 7 per interval)
///   ‖q_p‖² − 1 = 0 for p = 1 … 2N                              (the SO(3) constraint on the quaternion)
///   vec(q_f* ⊗ q_{2N}) = 0                                      (final attitude, 3; none when free)
///   ‖u_p‖² ≤ u_max² for p = 0 … 2N                              (norm bound only)
/// Objective: β T + α Σ_k h_k/6 (‖u_k‖² + 4‖u_m‖² + ‖u_{k+1}‖²) (Simpson's rule for ∫‖u‖²dt), with
/// (β, α) = (1, 0), (0, 1), (1, ε) for minimum time, minimum energy, regularised minimum time.
/// Costates: with the NLP Lagrangian f + yᵀg, the multipliers of D_k estimate −λ(t_k + h_k/2), λ the costate
/// of the minimum principle (H = L + λᵀ f).
#include <vector>

#include "collocation_dynamics.hpp"
#include "poinsot/optimal/problem.hpp"
#include "sparse_nlp.hpp"

namespace poinsot::optimal::detail {

class CollocationNlp final : public SparseNlp {
 public:
  static constexpr int kPointVars = 11;
  static constexpr int kStateVars = 7;

  /// `tau`: the normalised mesh (N + 1 increasing values from 0 to 1). The problem must be valid.
  CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau);

  int intervals() const { return static_cast<int>(tau_.size()) - 1; }
  int points() const { return 2 * intervals() + 1; }
  int num_variables() const override { return kPointVars * points() + 1; }
  int num_constraints() const override;
  int time_index() const { return kPointVars * points(); }
  const std::vector<double>& tau() const { return tau_; }
  const ReorientationProblem& problem() const { return problem_; }
  const CollocationDynamics& dynamics() const { return dyn_; }

  void variable_bounds(std::vector<double>& lower, std::vector<double>& upper) const;
  void constraint_bounds(std::vector<double>& lower, std::vector<double>& upper) const;
  void bounds(std::vector<double>& x_lower, std::vector<double>& x_upper, std::vector<double>& g_lower,
              std::vector<double>& g_upper) const override {
    variable_bounds(x_lower, x_upper);
    constraint_bounds(g_lower, g_upper);
  }

  double objective(const double* z) const override;
  void objective_gradient(const double* z, double* grad) const override;
  void constraints(const double* z, double* g) const override;
  /// Triplets of ∂g/∂z: the structure (rows, cols) is fixed; values in the same order.
  int jacobian_nonzeros() const override;
  void jacobian_structure(int* rows, int* cols) const override;
  void jacobian_values(const double* z, double* values) const override;
  /// Lower triangle (row ≥ col) of ∇²(σ f + yᵀ g).
  int hessian_nonzeros() const override;
  void hessian_structure(int* rows, int* cols) const override;
  void hessian_values(const double* z, double sigma, const double* y, double* values) const override;

  /// Rows of the first Simpson defect row of interval k / of the constraints after the defects.
  static int defect_row(int k) { return 14 * k; }

 private:
  Vec11 point(const double* z, int p) const { return Eigen::Map<const Vec11>(z + kPointVars * p); }
  double step_fraction(int k) const { return tau_[k + 1] - tau_[k]; }
  /// Simpson quadrature weight of point p as a fraction of T (w_p T multiplies ‖u_p‖²).
  double quadrature_weight(int p) const;
  double energy_weight() const;
  double time_weight() const;
  int norm_rows_begin() const { return 14 * intervals(); }
  int final_rows_begin() const { return norm_rows_begin() + 2 * intervals(); }
  int final_rows() const { return problem_.free_final_attitude ? 0 : 3; }
  int torque_norm_rows_begin() const { return final_rows_begin() + final_rows(); }

  ReorientationProblem problem_;
  std::vector<double> tau_;
  CollocationDynamics dyn_;
  Eigen::Matrix<double, 3, 4> final_attitude_rows_;  // vec(q_f* ⊗ q) = final_attitude_rows_ q
};

}  // namespace poinsot::optimal::detail
