#pragma once
/// @file collocation_nlp.hpp (internal)
/// The Hermite–Simpson transcription (separated form, Betts 2010, §4.6) of a ReorientationProblem into a
/// nonlinear program, independent of the NLP solver: variables, bounds, objective, constraints and their
/// exact sparse first and second derivatives.
///
/// One phase (the default): mesh 0 = τ_0 < … < τ_N = 1, t = τ T, h_k = (τ_{k+1} − τ_k) T. Points p = 0 … 2N:
/// even p = node k = p/2, odd p = midpoint of interval (p − 1)/2. Each point carries z_p = (q, ω, u, ν)
/// (11 variables); T is the last variable (fixed by its bounds for minimum_energy).
/// Several phases (CollocationPhases; free final time only): phase a has its own normalised mesh 0 … 1 of
/// N_a intervals, its own duration Δ_a (the variables after the points, T = Σ Δ_a, h_k = (τ_{k+1} − τ_k) Δ_a)
/// and its own torque bounds; the node between two phases is duplicated (the last point of phase a and the
/// first of phase a + 1), so the control may jump there and the phase boundaries Σ_{b≤a} Δ_b are variables.
/// Constraints, in this order:
///   D_k = x_{k+1} − x_k − h_k/6 (f_k + 4 f_m + f_{k+1})          (Simpson defect, 7 per interval)
///   M_k = x_m − ½ (x_k + x_{k+1}) − h_k/8 (f_k − f_{k+1})        (Hermite midpoint, 7 per interval)
///   ‖q_p‖² − 1 = 0 for every point but the first of each phase   (the SO(3) constraint on the quaternion)
///   x_{last of phase a} − x_{first of phase a+1} = 0             (state continuity, 7 per phase boundary)
///   vec(q_f* ⊗ q_{last}) = 0                                     (final attitude, 3; none when free)
///   ‖u_p‖² ≤ u_max² for every point                              (norm bound only)
///   q_pᵀ A_c q_p ≤ cos θ_c (keep-out), ≥ cos θ_c (keep-in) for every pointing constraint c and every point
///   but the first of each phase, c fastest                       (pointing_constraint.hpp: A_c, exact)
///   −h̄_k ≤ h_k(q_p, ω_p) = q_pᵀ N_k q_p − g_kᵀ ω_p ≤ h̄_k for every wheel k and every point but the first of
///   each phase, k fastest (reaction wheels with momentum bounds: h = A⁻¹ (Rᵀ(q) L − J_b ω), N_k = Σ_i
///   (A⁻¹)_ki M_i, g_k = row k of A⁻¹ J_b; exact)
/// ν = 0 at the first point of each phase (q is unit there: given, or equal to the previous phase's last q).
/// Objective: β T + α Σ_k h_k/6 (‖u_k‖² + 4‖u_m‖² + ‖u_{k+1}‖²) (Simpson's rule for ∫‖u‖²dt), with
/// (β, α) = (1, 0), (0, 1), (1, ε) for minimum time, minimum energy, regularised minimum time.
/// Costates: with the NLP Lagrangian f + yᵀg, the multipliers of D_k estimate −λ(t_k + h_k/2), λ the costate
/// of the minimum principle (H = L + λᵀ f).
#include <array>
#include <vector>

#include "collocation_dynamics.hpp"
#include "poinsot/optimal/problem.hpp"
#include "sparse_nlp.hpp"

namespace poinsot::optimal::detail {

/// The phases of a multi-phase transcription: the number of intervals and the torque bounds (N·m, body
/// frame; lower = upper fixes a component, e.g. a bang arc) of each phase, in order.
struct CollocationPhases {
  std::vector<int> intervals;
  std::vector<Vec3> torque_lower, torque_upper;
};

class CollocationNlp final : public SparseNlp {
 public:
  static constexpr int kPointVars = 11;
  static constexpr int kStateVars = 7;

  /// One phase. `tau`: the normalised mesh (N + 1 increasing values from 0 to 1). The problem must be valid.
  CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau);
  /// Several phases. `tau`: the phases' normalised meshes (each N_a + 1 increasing values from 0 to 1)
  /// concatenated. Throws InvalidInput when the sizes disagree or the final time is fixed.
  CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau, CollocationPhases phases);

  int phases() const { return static_cast<int>(phase_first_interval_.size()) - 1; }
  int intervals() const { return static_cast<int>(tau_.size()) - phases(); }
  int points() const { return 2 * intervals() + phases(); }
  int num_variables() const override { return kPointVars * points() + phases(); }
  int num_constraints() const override;
  /// The duration variable of phase a (T itself with one phase).
  int duration_index(int a) const { return kPointVars * points() + a; }
  int time_index() const { return duration_index(0); }
  /// The normalised meshes of the phases, concatenated (the mesh with one phase).
  const std::vector<double>& tau() const { return tau_; }
  int interval_phase(int k) const { return interval_phase_[k]; }
  /// The point index of the left node of interval k (its midpoint and right node follow).
  int interval_first_point(int k) const { return 2 * k + interval_phase_[k]; }
  /// h_k (s) at the variables z.
  double interval_step(const double* z, int k) const {
    return step_fraction(k) * z[duration_index(interval_phase_[k])];
  }
  /// The time of every point (s) at the variables z.
  std::vector<double> point_times(const double* z) const;
  /// T = Σ Δ_a (s).
  double final_time(const double* z) const;
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
  /// The row of pointing constraint c at point p, or −1 at the first point of a phase (none there).
  int pointing_row(int p, int c) const {
    return norm_row_[p] < 0 ? -1 : pointing_rows_begin() + norm_row_[p] * pointing_count() + c;
  }
  /// The row of wheel k's momentum bound at point p, or −1 (the first point of a phase, or no bound).
  int momentum_row(int p, int k) const {
    return norm_row_[p] < 0 || !momentum_bounded_ ? -1 : momentum_rows_begin() + 3 * norm_row_[p] + k;
  }

 private:
  void set_up();
  Vec11 point(const double* z, int p) const { return Eigen::Map<const Vec11>(z + kPointVars * p); }
  double step_fraction(int k) const {
    const int n = k + interval_phase_[k];
    return tau_[n + 1] - tau_[n];
  }
  /// Simpson quadrature weight of point p as a fraction of its phase's duration (w_p Δ multiplies ‖u_p‖²).
  double quadrature_weight(int p) const;
  /// c_p / Δ: the weight of f_p in yᵀg per unit duration of its phase (every defect is linear in f_p).
  Vec7 defect_weight(int p, const double* y) const;
  double energy_weight() const;
  double time_weight() const;
  int norm_rows_begin() const { return 14 * intervals(); }
  int link_rows_begin() const { return norm_rows_begin() + points() - phases(); }
  int final_rows_begin() const { return link_rows_begin() + 7 * (phases() - 1); }
  int final_rows() const { return problem_.free_final_attitude ? 0 : 3; }
  int torque_norm_rows_begin() const { return final_rows_begin() + final_rows(); }
  int pointing_rows_begin() const {
    return torque_norm_rows_begin() + (problem_.bound == TorqueBound::norm ? points() : 0);
  }
  int pointing_count() const { return static_cast<int>(pointing_forms_.size()); }
  int momentum_rows_begin() const { return pointing_rows_begin() + pointing_count() * (points() - phases()); }
  /// h_k(q, ω) at a point's variables (N·m·s; wheels).
  double wheel_momentum(const Vec11& zp, int k) const {
    const Vec4 q = zp.head<4>();
    return q.dot(momentum_forms_[k] * q) - momentum_rate_rows_.row(k).dot(zp.segment<3>(4));
  }
  int phase_first_point(int a) const { return 2 * phase_first_interval_[a] + a; }
  int phase_last_point(int a) const { return phase_first_point(a + 1) - 1; }

  ReorientationProblem problem_;
  std::vector<double> tau_;
  CollocationPhases phases_;
  std::vector<int> phase_first_interval_;  // P + 1 entries, the last = N
  std::vector<int> interval_phase_;        // per interval
  std::vector<int> point_phase_;           // per point
  std::vector<int> norm_row_;  // per point: its ‖q‖² row offset, −1 at the first point of a phase
  CollocationDynamics dyn_;
  Eigen::Matrix<double, 3, 4> final_attitude_rows_;  // vec(q_f* ⊗ q) = final_attitude_rows_ q
  std::vector<Eigen::Matrix4d> pointing_forms_;      // A_c of every pointing constraint
  bool momentum_bounded_ = false;                    // wheel momentum rows
  std::array<Eigen::Matrix4d, 3> momentum_forms_{};  // N_k
  Mat3 momentum_rate_rows_ = Mat3::Zero();           // A⁻¹ J_b (rows g_k)
};

/// The variables of one collocation point, the stride of the NLP vector z (CollocationNlp::kPointVars).
inline constexpr int kP = CollocationNlp::kPointVars;

}  // namespace poinsot::optimal::detail
