#pragma once
/// @file single_body_model.hpp (internal)
/// One rigid body (or a gyrostat with reaction wheels) as a point model of the Hermite–Simpson transcription
/// (hermite_simpson_nlp.hpp).
///
/// Point variables w = (q, ω, u, ν) (11): q = (w, x, y, z) the body → space quaternion, ω the body rate
/// (rad/s), u the body torque or the wheels' motor torques (N·m), ν the multiplier that keeps ‖q‖ = 1
/// (collocation_dynamics.hpp). State y = (q, ω) (7), controls u.
///
/// Path rows at every point but the first of each phase (whose q is given or linked), in this order:
///   ‖q‖² − 1 = 0                                  (the SO(3) constraint on the quaternion)
///   ‖u‖² ≤ ū²                                     (norm bound only; also at the first point of each phase)
///   qᵀ A_c q ≤ cos θ_c (keep-out), ≥ cos θ_c (keep-in) for every pointing constraint c
///                                                 (pointing_constraint.hpp: A_c)
///   −h̄_k ≤ h_k(q, ω) = qᵀ N_k q − g_kᵀ ω ≤ h̄_k for every wheel k with a momentum bound (reaction wheels:
///   h = A⁻¹ (Rᵀ(q) L − J_b ω), N_k = Σ_i (A⁻¹)_ki M_i, g_k = row k of A⁻¹ J_b)
/// Every row is a polynomial of degree 2, so its derivatives are exact (QuadraticFunctions).
///
/// Bounds on the variables: the torque bounds (per axis, or ±ū per component with the norm bound, or those of
/// the point's phase), ±r on ω with a rate bound, ν = 0 at the first point of each phase, the initial q and
/// ω at the first point and the final ω at the last.
#include <array>
#include <memory>
#include <vector>

#include "collocation_dynamics.hpp"
#include "hermite_simpson_nlp.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal::detail {

/// The phases of a multi-phase transcription: the number of intervals and the torque bounds (N·m, body
/// frame; lower = upper fixes a component, e.g. a bang arc) of each phase, in order.
struct CollocationPhases {
  std::vector<int> intervals;
  std::vector<Vec3> torque_lower, torque_upper;
};

class SingleBodyModel final : public CollocationModel {
 public:
  static constexpr int kPointVars = 11;
  static constexpr int kStateVars = 7;

  /// `phases`: the torque bounds of each phase (empty bounds: the problem's). The problem must be valid.
  SingleBodyModel(const ReorientationProblem& problem, CollocationPhases phases);

  int state_size() const override { return kStateVars; }
  int point_size() const override { return kPointVars; }
  const std::vector<int>& control_indices() const override { return controls_; }
  const PointFunctions& rhs() const override { return *rhs_; }
  const PointFunctions& first_path() const override { return first_path_; }
  const PointFunctions& path() const override { return path_; }
  void path_bounds(bool first_of_phase, double* lower, double* upper) const override;
  void variable_bounds(const PointRole& role, double* lower, double* upper) const override;

  const ReorientationProblem& problem() const { return problem_; }
  const CollocationDynamics& dynamics() const { return dyn_; }
  const CollocationPhases& phases() const { return phases_; }
  /// y₀ = (q₀, ω₀).
  Eigen::VectorXd initial_state() const;
  /// vec(q_f* ⊗ q) = 0 on the last q: the rows (3; none when the final attitude is free) …
  Eigen::MatrixXd final_rows() const;
  /// … and their values, 0.
  Eigen::VectorXd final_values() const { return Eigen::VectorXd::Zero(final_row_count()); }
  /// The rows of pointing constraint c and of wheel k's momentum bound within path().
  int pointing_offset(int c) const { return 1 + norm_rows() + c; }
  int momentum_offset(int k) const {
    return 1 + norm_rows() + static_cast<int>(problem_.pointing.size()) + k;
  }
  bool momentum_bounded() const { return momentum_bounded_; }

 private:
  int final_row_count() const { return problem_.free_final_attitude ? 0 : 3; }
  int norm_rows() const { return problem_.bound == TorqueBound::norm ? 1 : 0; }
  void build_paths();

  ReorientationProblem problem_;
  CollocationPhases phases_;
  CollocationDynamics dyn_;
  std::vector<int> controls_{7, 8, 9};
  std::unique_ptr<PointFunctions> rhs_;
  QuadraticFunctions first_path_, path_;
  bool momentum_bounded_ = false;
};

}  // namespace poinsot::optimal::detail
