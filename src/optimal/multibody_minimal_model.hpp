#pragma once
/// @file multibody_minimal_model.hpp (internal)
/// The collocation point model of a multibody problem in minimal coordinates, independent of the
/// rotation-matrix equations: the joint angles θ of a tree of hinges, rooted at the world or at a floating
/// base.
///
/// Body i hangs from hinge i (its body_a), whose body_b p(i) is the world, the base or a body of lower index.
/// With the relative rotation C_i = R_pᵀR_i of the initial state and the hinge axis n_i (body i's frame),
///
///     R_i = R_p C_i Rot(n_i, θ_i),   x_i = x_p + R_p B_i − R_i A_i,
///
/// so θ = 0 is the initial configuration.
///
/// Rooted at the world: q = θ, ν = θ̇. Floating base (body 0 in no joint to the world, no hinge of its own):
/// q = (e, θ) with e = (e₀, ē) a quaternion of the base's attitude, ν = (ω₀, θ̇) with ω₀ the base's angular
/// velocity (body frame), ė = ½ e ⊗ (0, ω₀) (bilinear). The attitude is R₀ = R(e/|e|), the rotation of the
/// normalised quaternion, I + 2(e₀ j(ē) + j(ē)²)/|e|²: the norm is no coordinate of the motion (ė·e = 0
/// keeps it in continuous time; the transcription lets it drift by its own error, which R₀ does not see), so
/// there is neither a norm row, which would over-determine the collocation equations, nor a singular
/// attitude. The translation is eliminated by the conservation of the centre of mass: the system must be
/// free floating at zero linear momentum, with no gravity or constant loads, so x_com stays at its initial
/// value; the base's position and velocity follow from it.
///
/// w = (q, ν, ν̇, u), y = (q, ν), ẏ = (q̇(q, ν), ν̇). The path equation is the Lagrangian's M(q) ν̇ + c(q, ν) =
/// B u, evaluated without forming M as the inverse dynamics of the recursive Newton–Euler algorithm
/// (Featherstone 2008, §5.3), outward for the velocities and accelerations, inward for the joint force f_i
/// and couple n_i (space frame):
///
///     ω_i = E_iᵀω_p + n_i θ̇_i,   ω̇_i = E_iᵀω̇_p + n_i θ̈_i + θ̇_i ω_i × n_i   (body frame, E_i = C_i Rot(n_i,
///     θ_i)), f_i = m_i (a_i − g) + Σ_c f_c,   n_i = R_i (J_i ω̇_i + ω_i × J_i ω_i) − (R_i A_i) × f_i + Σ_c
///     (n_c + (R_i B_c) × f_c), (R_i n_i)·n_i − u_i = 0 (one row per hinge),
///
/// with u_i the hinge's motor torque (0 when unactuated). A floating base adds three rows first, R₀ᵀ n₀ = 0:
/// the rate of change of the total angular momentum (the accelerations shifted by the centre of mass's, so
/// that Σ f = 0 and the moment is the same about any point). The Jacobian and the Hessian of the weighted
/// rows come from forward automatic differentiation of first and second order (Eigen's AutoDiffScalar,
/// nested): exact to round-off, like the rotation-matrix model's.
#include <memory>
#include <vector>

#include "hermite_simpson_dae.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::detail {

/// The kinematic tree of hinges (see the file comment).
struct HingeTree {
  struct Link {
    int parent = -1;            ///< body index or multibody::kWorld (unused for a floating base)
    Vec3 axis = Vec3::UnitZ();  ///< n_i, body frame, unit
    Mat3 C = Mat3::Identity();  ///< R_pᵀR_i at θ = 0
    Vec3 A = Vec3::Zero();      ///< joint point in body i's frame (m)
    Vec3 B = Vec3::Zero();      ///< joint point in the parent's frame (space frame for the world)
    double mass = 1.0;
    Mat3 J = Mat3::Identity();
  };
  std::vector<Link> links;  ///< one per body, in body order
  Vec3 gravity = Vec3::Zero();
  bool floating_base = false;  ///< body 0 is a free base (links[0] has no hinge)
};

/// Where the coordinates sit in the point variables w = (q, ν, ν̇, u) (see the file comment).
struct MinimalLayout {
  bool floating = false;
  int hinges = 0;  ///< m, the number of hinge angles
  int base_q() const { return floating ? 4 : 0; }
  int base_v() const { return floating ? 3 : 0; }
  int positions() const { return base_q() + hinges; }   ///< size of q
  int velocities() const { return base_v() + hinges; }  ///< size of ν
  int first_link() const { return floating ? 1 : 0; }
  int angle(int link) const { return base_q() + link - first_link(); }
  int omega() const { return positions(); }  ///< ω₀'s first index
  int rate(int link) const { return positions() + base_v() + link - first_link(); }
  int omega_dot() const { return positions() + velocities(); }
  int acceleration(int link) const { return omega_dot() + base_v() + link - first_link(); }
  int controls_begin() const { return positions() + 2 * velocities(); }
  int base_rows() const { return base_v(); }
  int row(int link) const { return base_rows() + link - first_link(); }
};

class MultibodyMinimalModel final : public CollocationModel {
 public:
  /// Throws InvalidInput unless the system is a tree of hinges rooted at the world, or at a floating body 0
  /// (no joint to the world) with no gravity and zero initial linear momentum, with hinge motors only and no
  /// constant loads besides gravity.
  explicit MultibodyMinimalModel(const MultibodyProblem& problem);
  MultibodyMinimalModel(const MultibodyMinimalModel&) = delete;  // path_ refers to tree_
  MultibodyMinimalModel& operator=(const MultibodyMinimalModel&) = delete;

  int state_size() const override { return layout_.positions() + layout_.velocities(); }
  int point_size() const override { return layout_.controls_begin() + static_cast<int>(controls_.size()); }
  const std::vector<int>& control_indices() const override { return controls_; }
  const PointFunctions& rhs() const override { return rhs_; }
  const PointFunctions& first_path() const override { return *path_; }
  const PointFunctions& path() const override { return *path_; }
  void variable_bounds(bool first_node, double* lower, double* upper) const override;

  /// y = (q, ν) of a consistent state (θ in (−π, π]; the base's quaternion of the sign nearest the initial
  /// state's, so that attitudes within a half-turn of it are encoded continuously).
  Eigen::VectorXd state_vector(const multibody::State& state) const;
  /// The multibody state of the point variables w (forward kinematics; with a floating base the centre of
  /// mass at its initial place, at rest).
  multibody::State state_of(const double* w, double time) const;
  /// The Lagrangian's mass matrix M(q) (kg·m², symmetric positive definite) and c(q, ν) − B u (N·m) at the
  /// state y and controls u (actuator order): the path rows at ν̇ = 0 and their change with each ν̇_j.
  void equations_of_motion(const Eigen::VectorXd& y, const Eigen::VectorXd& u, Eigen::MatrixXd& mass,
                           Eigen::VectorXd& bias) const;
  /// ẏ = (q̇, ν̇) with ν̇ = −M⁻¹(c − B u): the forward dynamics.
  Eigen::VectorXd state_derivative(const Eigen::VectorXd& y, const Eigen::VectorXd& u) const;
  /// The local coordinates of the state near y (multibody_final_conditions.hpp: F, with T = Fᵀ): the
  /// identity, except for a base quaternion e, whose three are those of an orthonormal basis of e's
  /// orthogonal complement (its norm is no coordinate of the attitude).
  Eigen::MatrixXd local_coordinates(const Eigen::VectorXd& y) const;
  const HingeTree& tree() const { return tree_; }
  const MinimalLayout& layout() const { return layout_; }

 private:
  MinimalLayout layout_;
  HingeTree tree_;
  Vec3 com_space_ = Vec3::Zero();  ///< floating base: x_com (m)
  Eigen::Vector4d sign_reference_ = Eigen::Vector4d::UnitX();
  std::vector<int> controls_;
  std::vector<double> bounds_;
  std::vector<int> motor_of_link_;  // control index in w, or −1
  QuadraticFunctions rhs_;
  std::unique_ptr<PointFunctions> path_;
};

}  // namespace poinsot::optimal::detail
