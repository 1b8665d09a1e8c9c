#pragma once
/// @file multiple_shooting.hpp (internal)
/// The shooting residual of the minimum principle in (R, ω, P, p_ω) (indirect_shooting.hpp) over M segments
/// (nodes at fixed fractions τ_m of T, by default m/M), and Newton's method on it. M = 1 is single shooting.
///
/// Unknowns x = (p_θ(0), p_ω(0), T if free, the knot times (switches or reversals), then for each interior
/// node m = 1 … M−1 at t_m = τ_m T: δ_m, ω_m, p_θ,m, p_ω,m), 12 per node. The node attitude is
/// R_m = R̄_m exp(j(δ_m)) around a fixed reference R̄_m (the guess): three coordinates on SO(3), so RᵀR = I
/// holds at every node by construction and needs neither a row nor a multiplier. The attitude costate at a
/// node is the body vector p_θ,m with P_m = ½ R_m j(p_θ,m): the gauge P → P + R S (S symmetric, the
/// orthogonality multiplier's freedom) is fixed at zero at every node, and the flow keeps it zero.
/// With a free final attitude the p_θ unknowns are held at 0 (identity Jacobian columns; p_θ ≡ 0 exactly).
/// Rows: the final conditions of indirect_shooting.hpp (6, + H(T) for a free T), one per knot
/// (σ_i(t_s) = 0, or σ·ŝ = 0 at a reversal), and 12 continuity defects per interior node:
/// ½vee(R_mᵀR⁻ − R⁻ᵀR_m) (rad), T(ω⁻ − ω_m) (rad), s_ω(p_θ⁻ − p_θ,m) and ū J⁻¹(p_ω⁻ − p_ω,m) (both in the
/// units of H; s_ω a typical ‖ω‖ of the guess, ū the torque's norm bound), where ⁻ is the end of segment m−1.
/// The Jacobian is by central differences: a node's 12 columns re-integrate its segment only (they move no
/// other segment), the other columns the whole horizon, so the Jacobian is block sparse and is factorised
/// by Eigen's SparseLU.
#include <Eigen/Sparse>
#include <functional>
#include <utility>
#include <vector>

#include "pmp_system.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "switching_structure.hpp"

namespace poinsot::optimal::detail {

class Shooter {
 public:
  /// `node_attitude` holds the reference attitudes R̄_1 … R̄_{M−1} (empty: single shooting); `omega_scale`
  /// is s_ω of the costate rows (rad/s); `node_fraction` the interior nodes' times as fractions τ_m of T,
  /// strictly ascending in (0, 1) (t_m = τ_m T; empty: τ_m = m/M).
  Shooter(const ReorientationProblem& p, const ShootingOptions& o, const SwitchGuess& s, bool bang_bang,
          std::vector<Mat3> node_attitude, double omega_scale, std::vector<double> node_fraction = {});

  int size() const { return node_base(1) + 12 * (nodes() - 1); }
  int nodes() const { return static_cast<int>(ref_.size()) + 1; }
  /// The unknown times between arcs: the switches (bang-bang) or the reversals (norm bound).
  std::size_t knot_count() const { return bang_ ? s_.axes.size() : rev_ ? s_.reversals.size() : 0; }
  int knot_base() const { return p_.free_final_time() ? 7 : 6; }
  int node_base(int m) const { return knot_base() + static_cast<int>(knot_count()) + 12 * (m - 1); }
  double switch_time(const Eigen::VectorXd& x, std::size_t k) const {
    return x[knot_base() + static_cast<int>(k)];
  }
  double final_time(const Eigen::VectorXd& x) const { return p_.free_final_time() ? x[6] : p_.final_time; }
  double node_time(const Eigen::VectorXd& x, int m) const {
    return m == 0 ? 0.0 : final_time(x) * fraction_[static_cast<std::size_t>(m - 1)];
  }
  /// The constant torque of a bang-bang arc containing t_mid.
  Vec3 arc_torque(const Eigen::VectorXd& x, double t_mid) const;
  /// The state (R, ω, P, p_ω, cost 0) at node m (m = 0: the initial state and costates).
  PmpState node_state(const Eigen::VectorXd& x, int m) const;
  /// Writes the unknowns of node m ≥ 1 for the state (R, ω, p_θ, p_ω) into x (δ relative to R̄_m).
  void set_node(Eigen::VectorXd& x, int m, const Mat3& R, const Vec3& omega, const Vec3& p_theta,
                const Vec3& p_omega) const;
  /// The reference attitudes R̄_1 … R̄_{M−1}.
  const std::vector<Mat3>& node_references() const { return ref_; }
  /// Re-seeds the interior nodes forward from the initial state: for m = 1 … M−1 in turn, segment m−1 is
  /// integrated from node m−1 (node 0: the exact initial state with x's initial costates), and node m takes
  /// the integrated R, ω and p_θ (R p_θ is constant along the flow: the space-frame attitude costate is
  /// carried through) with the switching vector σ_m = R_mᵀ λ_m, i.e. p_ω,m = J R_mᵀ λ_m, from the given
  /// space-frame switching vectors λ_m = R σ (`switching_space[m − 1]`); R̄_m becomes that R (δ_m = 0).
  /// The knots and T are those of x. False when x is outside the domain (the nodes are then unchanged).
  bool seed_nodes_forward(Eigen::VectorXd& x, const std::vector<Vec3>& switching_space);

  /// The end of one segment: its final state, the control there, and σ at the knots inside it.
  struct SegmentEnd {
    PmpState y{};
    Vec3 u = Vec3::Zero();
    std::vector<std::pair<std::size_t, double>> knot_sigma;  ///< (knot, scaled condition)
  };
  /// Integrates every segment; false when x is outside the domain (T ≤ 0, knots outside (0, T)).
  bool segment_ends(const Eigen::VectorXd& x, std::vector<SegmentEnd>& ends) const;
  /// The scaled residual from the segments' ends; false when it is not finite.
  bool assemble(const Eigen::VectorXd& x, const std::vector<SegmentEnd>& ends, Eigen::VectorXd& F) const;
  bool residual(const Eigen::VectorXd& x, Eigen::VectorXd& F) const;
  /// The central-difference Jacobian at x (F its residual); false when a column cannot be formed.
  bool jacobian(const Eigen::VectorXd& x, const std::vector<SegmentEnd>& ends, const Eigen::VectorXd& F,
                Eigen::SparseMatrix<double>& jac) const;

  /// Integrates 0 → T segment by segment, calling observe(t, y, u) at samples_per_arc points of each arc
  /// (arcs: the pieces of a segment between knots), with y's cost accumulated from t = 0.
  template <class Observer>
  bool propagate(const Eigen::VectorXd& x, Observer&& observe) const {
    std::vector<Knot> knots;
    if (!sorted_knots(x, knots)) return false;
    double cost = 0.0;
    for (int m = 0; m < nodes(); ++m) {
      SegmentEnd end;
      integrate_segment(x, m, knots, options_.samples_per_arc, end,
                        [&](double t, const PmpState& y, const Vec3& u) {
                          PmpState z = y;
                          z[24] += cost;
                          observe(t, z, u);
                        });
      cost += end.y[24];
    }
    return true;
  }

 private:
  using SampleFn = std::function<void(double, const PmpState&, const Vec3&)>;
  using Knot = std::pair<double, std::size_t>;  ///< (time, knot index)
  /// The knots in ascending time; false when one lies outside (0, T) or T ≤ 0.
  bool sorted_knots(const Eigen::VectorXd& x, std::vector<Knot>& knots) const;
  void integrate_segment(const Eigen::VectorXd& x, int m, const std::vector<Knot>& knots, int samples,
                         SegmentEnd& end, const SampleFn& observe) const;
  double knot_scale(std::size_t k) const { return bang_ ? p_.torque_max[s_.axes[k]] : p_.torque_max[0]; }

  const ReorientationProblem& p_;
  ShootingOptions options_;
  const SwitchGuess& s_;
  bool bang_, rev_;
  std::vector<Mat3> ref_;
  double omega_scale_;
  std::vector<double> fraction_;
  Mat3 J_inv_, R0_, Rf_;
};

/// Newton's method with a backtracking line search on the shooting residual, from x (F = its residual); where
/// the Newton step does not halve the residual, the rank-revealing steps (dense SVD, singular values below
/// 1e-8, 1e-10 and 1e-12 of the largest left out) are tried too and the best step is kept;
/// stops at norm ≤ o.tolerance, after o.max_iterations, or when no step decreases the residual. Returns the
/// iterations taken; x, F and norm are the last accepted iterate; `stalled` tells whether it stopped because
/// no step decreased the residual.
int newton(const Shooter& shooter, const ShootingOptions& o, Eigen::VectorXd& x, Eigen::VectorXd& F,
           double& norm, bool& stalled);

}  // namespace poinsot::optimal::detail
