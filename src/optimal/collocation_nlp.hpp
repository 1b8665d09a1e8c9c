#pragma once
/// @file collocation_nlp.hpp (internal)
/// The transcription of a ReorientationProblem: the one body's point model (single_body_model.hpp) in the
/// Hermite–Simpson transcription (hermite_simpson_nlp.hpp), with the problem's mesh, phases, boundary
/// conditions and objective:
///   y₀ = (q₀, ω₀); vec(q_f* ⊗ q_last) = 0 (3 rows; none when the final attitude is free);
///   objective β T + α ∫‖u‖²dt with (β, α) = (1, 0), (0, 1), (1, ε) for minimum time, minimum energy and
///   regularised minimum time;
///   T free: one duration variable per phase (T ≥ half the problem's minimum-duration bound with one phase,
///   each Δ_a ≥ 0 with several); T fixed (minimum energy): one phase and no time variable.
/// Several phases (CollocationPhases; free final time only) have their own torque bounds, so a control may
/// jump at the node between two phases.
#include <vector>

#include "hermite_simpson_nlp.hpp"
#include "poinsot/optimal/problem.hpp"
#include "single_body_model.hpp"

namespace poinsot::optimal::detail {

class CollocationNlp final : public SparseNlp {
 public:
  static constexpr int kPointVars = SingleBodyModel::kPointVars;
  static constexpr int kStateVars = SingleBodyModel::kStateVars;

  /// One phase. `tau`: the normalised mesh (N + 1 increasing values from 0 to 1). The problem must be valid.
  CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau);
  /// Several phases. `tau`: the phases' normalised meshes (each N_a + 1 increasing values from 0 to 1)
  /// concatenated. Throws InvalidInput when the sizes disagree or the final time is fixed.
  CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau, CollocationPhases phases);

  const HermiteSimpsonNlp& transcription() const { return nlp_; }
  const CollocationMesh& mesh() const { return nlp_.mesh(); }
  int phases() const { return mesh().phases(); }
  int intervals() const { return mesh().intervals(); }
  int points() const { return mesh().points(); }
  bool free_time() const { return nlp_.free_time(); }
  /// The duration variable of phase a (T itself with one phase); free final time only.
  int duration_index(int a) const { return nlp_.duration_index(a); }
  int time_index() const { return nlp_.time_index(); }
  /// The normalised meshes of the phases, concatenated (the mesh with one phase).
  const std::vector<double>& tau() const { return mesh().tau(); }
  int interval_phase(int k) const { return mesh().interval_phase(k); }
  /// The point index of the left node of interval k (its midpoint and right node follow).
  int interval_first_point(int k) const { return mesh().interval_first_point(k); }
  /// h_k (s) at the variables z.
  double interval_step(const double* z, int k) const { return nlp_.interval_step(z, k); }
  /// The time of every point (s) at the variables z.
  std::vector<double> point_times(const double* z) const { return nlp_.point_times(z); }
  /// T = Σ Δ_a (s).
  double final_time(const double* z) const { return nlp_.final_time(z); }
  const ReorientationProblem& problem() const { return model_.problem(); }
  const CollocationDynamics& dynamics() const { return model_.dynamics(); }
  /// λ(t_k + h_k/2) from the constraint multipliers y (hermite_simpson_nlp.hpp).
  Vec7 costate(const std::vector<double>& y, int k) const { return nlp_.costate(y, k); }
  /// The row of pointing constraint c at point p, or −1 at the first point of a phase (none there).
  int pointing_row(int p, int c) const {
    return mesh().first_of_phase(p) ? -1 : nlp_.path_row(p) + model_.pointing_offset(c);
  }
  /// The row of wheel k's momentum bound at point p, or −1 (the first point of a phase, or no bound).
  int momentum_row(int p, int k) const {
    return mesh().first_of_phase(p) || !model_.momentum_bounded()
               ? -1
               : nlp_.path_row(p) + model_.momentum_offset(k);
  }

  int num_variables() const override { return nlp_.num_variables(); }
  int num_constraints() const override { return nlp_.num_constraints(); }
  void bounds(std::vector<double>& x_lower, std::vector<double>& x_upper, std::vector<double>& g_lower,
              std::vector<double>& g_upper) const override {
    nlp_.bounds(x_lower, x_upper, g_lower, g_upper);
  }
  double objective(const double* z) const override { return nlp_.objective(z); }
  void objective_gradient(const double* z, double* grad) const override { nlp_.objective_gradient(z, grad); }
  void constraints(const double* z, double* g) const override { nlp_.constraints(z, g); }
  int jacobian_nonzeros() const override { return nlp_.jacobian_nonzeros(); }
  void jacobian_structure(int* rows, int* cols) const override { nlp_.jacobian_structure(rows, cols); }
  void jacobian_values(const double* z, double* values) const override { nlp_.jacobian_values(z, values); }
  int hessian_nonzeros() const override { return nlp_.hessian_nonzeros(); }
  void hessian_structure(int* rows, int* cols) const override { nlp_.hessian_structure(rows, cols); }
  void hessian_values(const double* z, double sigma, const double* y, double* values) const override {
    nlp_.hessian_values(z, sigma, y, values);
  }

 private:
  SingleBodyModel model_;
  HermiteSimpsonNlp nlp_;
};

/// The variables of one collocation point, the stride of the NLP vector z (CollocationNlp::kPointVars).
inline constexpr int kP = CollocationNlp::kPointVars;

}  // namespace poinsot::optimal::detail
