#pragma once
/// @file multibody_rotation_model.hpp (internal)
/// The collocation point model of a multibody problem in rotation-matrix coordinates: the multibody layer's
/// equations (docs/multibody_theory.md (1)), with the constant mass matrix blockdiag(m I, K ⊗ I), written so
/// that every function is a polynomial of degree ≤ 2 in the point's variables (QuadraticFunctions: exact
/// derivatives by construction).
///
/// Per body, states y = (x, R, v, V) (24: R and V = Ṙ column-major) and algebraic variables
/// z = (a, A, Λ, S) (24: a = v̇, A = V̇, Λ and S symmetric, 6 each); per joint the reaction λ and a
/// projection multiplier μ (one each per joint row); then the controls. The differential equations are the
/// stabilised index-2 form of Gear, Gupta & Leimkuhler (1985):
///
///     ẋ = v + Gₓᵀμ,   Ṙ = V + R S + G_Rᵀμ,   v̇ = a,   V̇ = A,
///
/// and the path equations at every point except node 0:
///
///     m a = f + Gₓᵀλ,   A K = R Λ + F_R + G_Rᵀλ + F_R(u),                 (dynamics, linear in a, A, Λ, λ)
///     RᵀV + VᵀR = 0,  ġ(x, R, v, V) = 0,                                  (velocity level)
///     RᵀR = I,  g(x, R) = 0,                                              (position level)
///
/// so that every body stays a rotation and every joint holds at every collocation point; μ and S vanish on
/// the exact solution (they absorb the discretisation's drift, O(h⁴)). At node 0, where y is given and
/// consistent, the position and velocity rows are replaced by their second derivatives (AᵀR + 2VᵀV + RᵀA = 0,
/// g̈ = 0), which fix the initial multipliers, and μ, S are fixed to 0. Elsewhere they may be bounded (the
/// constructor): unbounded, the discrete equations admit a spurious jump of a body across a half-turn Q
/// inside one interval at no cost, R (Q − I) being of the form R S with S symmetric. A hinge
/// motor's torque u gives F_R = ½ u R_a j(axis_a) on body a and −½ u R_b j(axis_b) on body b; a body torque τ
/// (body frame) gives F_R = ½ R j(τ) (loads.hpp).
#include <algorithm>
#include <vector>

#include "hermite_simpson_nlp.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::detail {

class MultibodyRotationModel final : public CollocationModel {
 public:
  int state_size() const override { return 24 * bodies_; }
  int point_size() const override { return size_; }
  const std::vector<int>& control_indices() const override { return controls_; }
  const PointFunctions& rhs() const override { return rhs_; }
  const PointFunctions& first_path() const override { return first_path_; }
  const PointFunctions& path() const override { return path_; }
  void variable_bounds(const PointRole& role, double* lower, double* upper) const override;

  /// With `stabilisation_step` c > 0, every stabilising variable at every point but node 0 is bounded by
  /// σ = c/h (h = T/N): |S_kl| ≤ σ (1/s), |μ| ≤ σ for a joint's perpendicularity rows and σ ℓ for its point
  /// rows (point_row_scale). Over one interval (R_{k+1} − R_k = h/6 (f_k + 4 f_m + f_{k+1}), R a rotation
  /// at every point) the terms R S then move R by at most 3c in the Frobenius norm (‖R S‖ = ‖S‖ ≤ 3σ) and
  /// the terms G_Rᵀμ = μ pᵀ by at most √3 c ℓ |p| ≤ √3 c, so for c < 0.6 a jump across a half-turn (‖R (Q −
  /// I)‖ = 2√2) must be made by V, i.e. by angular velocity. On a solution of the continuous problem
  /// S = μ = 0. With c = 0 (the default) they are unbounded.
  MultibodyRotationModel(const MultibodyProblem& problem, double stabilisation_step);
  explicit MultibodyRotationModel(const MultibodyProblem& problem) : MultibodyRotationModel(problem, 0.0) {}

  /// ℓ = L / max(1, L²) with L = System::length_scale() (numerically, in metres): the point rows' μ moves x
  /// by at most c ℓ ≤ c L and R by at most √3 c ℓ |p| ≤ √3 c (|p| ≤ L).
  double point_row_scale() const {
    const double L = problem_.system.length_scale();
    return L / std::max(1.0, L * L);
  }
  /// The step the stabilising variables carry at the point variables w: the largest h|S_kl|, h|μ_k| of a
  /// perpendicularity row and h|μ_k|/ℓ of a point row (dimensionless; ≤ c when bounded).
  double stabilisation_step(const double* w) const;

  /// The state y of `state` (bodies' x, R, v, V = R j(ω)).
  Eigen::VectorXd state_vector(const multibody::State& state) const;
  /// The multibody state of the point variables w, or of a state vector y, which is their head: only the
  /// state's entries are read (ω = vee(RᵀV), R as stored).
  multibody::State state_of(const double* w, double time) const;
  /// The joint reactions and each body's Λ at the point variables w.
  multibody::Multipliers multipliers_of(const double* w) const;
  /// The position and velocity rows (orthogonality and joints) at y: their Jacobian ∂/∂y at `state`, for the
  /// tangent-space final conditions.
  Eigen::MatrixXd invariant_jacobian(const multibody::State& state) const;

  // Layout of w.
  int x(int body) const { return 24 * body; }
  int R(int body, int r, int c) const { return 24 * body + 3 + r + 3 * c; }
  int v(int body) const { return 24 * body + 12; }
  int V(int body, int r, int c) const { return 24 * body + 15 + r + 3 * c; }
  int a(int body) const { return z_ + 24 * body; }
  int A(int body, int r, int c) const { return z_ + 24 * body + 3 + r + 3 * c; }
  int Lambda(int body, int k, int l) const { return z_ + 24 * body + 12 + sym(k, l); }
  int S(int body, int k, int l) const { return z_ + 24 * body + 18 + sym(k, l); }
  int lambda(int joint) const { return joint_offset_[static_cast<std::size_t>(joint)]; }
  int mu(int joint) const;
  int control(int actuator) const { return control_offset_[static_cast<std::size_t>(actuator)]; }

 private:
  static int sym(int k, int l);
  void build_rhs();
  void build_path(QuadraticFunctions& out, bool first_node);
  /// Rows of the constraints at derivative `level` (0: RᵀR = I and g = 0; 1: their first, 2: their second
  /// time derivatives), appended to `out`.
  void add_invariant_rows(QuadraticFunctions& out, int level) const;

  MultibodyProblem problem_;
  double stabilisation_step_ = 0.0;
  int bodies_ = 0, z_ = 0, size_ = 0;
  std::vector<int> joint_offset_, control_offset_, controls_;
  QuadraticFunctions rhs_, first_path_, path_, invariants0_, invariants1_;
};

}  // namespace poinsot::optimal::detail
