#pragma once
/// @file multibody_minimal_model.hpp (internal)
/// The collocation point model of a multibody problem in minimal coordinates, independent of the
/// rotation-matrix equations: a tree of hinges and ball joints, rooted at the world or at a floating base.
///
/// Each body i but a floating base hangs from one joint that joins it to a parent p(i) of lower index (the
/// world, the base or another body). With C_i = R_pᵀR_i of the initial state, A_i the joint point in body i's
/// frame and B_i in the parent's,
///
///     R_i = R_p E_i,   E_i = C_i Rot(n_i, θ_i) (hinge, axis n_i in body i's frame) or C_i R(e_i) (ball),
///     x_i = x_p + R_p B_i − R_i A_i,
///
/// so θ = 0 and e = (1, 0, 0, 0) are the initial configuration. R(e) = I + 2(e₀ j(ē) + j(ē)²)/|e|² is the
/// rotation of the normalised quaternion e = (e₀, ē): its norm is no coordinate of the motion (ė·e = 0 keeps
/// it in continuous time; the transcription lets it drift by its own error, which R(e) does not see), so
/// there is neither a norm row, which would over-determine the collocation equations, nor a singular
/// attitude. A ball's velocity is ν_i, the angular velocity of body i relative to its parent in body i's
/// frame, with ė_i = ½ e_i ⊗ (0, ν_i) (bilinear); a hinge's is θ̇_i (ν_i = n_i θ̇_i).
///
/// Floating base (body 0 in no joint, no joint to the world): its quaternion e₀ (R₀ = R(e₀)) and its
/// angular velocity ω₀ (body frame) come first. The translation is eliminated by the conservation of the
/// centre of mass: the system must be free floating at zero linear momentum, with no gravity or constant
/// loads, so x_com stays at its initial value, and the base's position and velocity follow from it.
///
/// w = (q, ν, ν̇, u), y = (q, ν), ẏ = (q̇(q, ν), ν̇). The path equation is the Lagrangian's M(q) ν̇ + c(q, ν) =
/// B u, evaluated without forming M as the inverse dynamics of the recursive Newton–Euler algorithm
/// (Featherstone 2008, §5.3), outward for the velocities and accelerations, inward for the joint force f_i
/// and couple n_i (space frame):
///
///     ω_i = E_iᵀω_p + ν_i,   ω̇_i = E_iᵀω̇_p + ν̇_i + ω_i × ν_i   (body frame),
///     f_i = m_i (a_i − g) + Σ_c f_c,   n_i = R_i (J_i ω̇_i + ω_i × J_i ω_i) − (R_i A_i) × f_i + Σ_c (n_c +
///     (R_i B_c) × f_c),
///     hinge: (R_i n_i)·n_i − s u_i = 0,   ball: R_iᵀ(n_i − s τ_i) = 0   (s = ±1: body i is the joint's
///     body_a or body_b; the rows are the generalised forces dual to ν, so M is symmetric),
///
/// with u_i the hinge's motor torque and τ_i the ball's (space frame; 0 when unactuated). A floating base
/// adds three rows first, R₀ᵀ n₀ = 0: the rate of change of the total angular momentum (the accelerations
/// shifted by the centre of mass's, so that Σ f = 0 and the moment is the same about any point). The Jacobian
/// and the Hessian of the weighted rows come from forward automatic differentiation of first and second order
/// (Eigen's AutoDiffScalar, nested): exact to round-off, like the rotation-matrix model's.
#include <memory>
#include <vector>

#include "hermite_simpson_nlp.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::detail {

/// The kinematic tree (see the file comment) and where each coordinate sits in the point variables w = (q, ν,
/// ν̇, u).
struct MinimalTree {
  struct Link {
    int parent = -1;            ///< body index or multibody::kWorld (unused for a floating base)
    bool ball = false;          ///< a ball joint (relative quaternion), else a hinge (angle)
    Vec3 axis = Vec3::UnitZ();  ///< hinge: n_i, body frame, unit
    Mat3 C = Mat3::Identity();  ///< R_pᵀR_i at the initial state
    Vec3 A = Vec3::Zero();      ///< joint point in body i's frame (m)
    Vec3 B = Vec3::Zero();      ///< joint point in the parent's frame (space frame for the world)
    double mass = 1.0;
    Mat3 J = Mat3::Identity();
    int q = 0;       ///< first position index in w (θ, or the quaternion's 4)
    int v = 0;       ///< first velocity index in w (θ̇, or ν's 3; its acceleration at v + velocities)
    int row = 0;     ///< first path row (1 for a hinge, 3 for a ball)
    int motor = -1;  ///< first control index in w, or −1
    /// +1 when body i is the joint's body_a (the motor's torque acts +u on it), else −1.
    double motor_sign = 1.0;
  };
  std::vector<Link> links;  ///< one per body, in body order (links[0] the base when floating)
  Vec3 gravity = Vec3::Zero();
  bool floating = false;  ///< body 0 is a free base: e at w[0..4), ω₀ at w[positions ..+3), 3 rows first
  int positions = 0;      ///< size of q
  int velocities = 0;     ///< size of ν
  int rows = 0;           ///< path rows
  int first_link() const { return floating ? 1 : 0; }
};

class MultibodyMinimalModel final : public CollocationModel {
 public:
  /// Throws InvalidInput unless the system is a tree of hinges and ball joints (each body but a floating
  /// base the higher-indexed body of exactly one joint) rooted at the world, or at a floating body 0 (no
  /// joint to the world) with no gravity and zero initial linear momentum, with hinge and ball motors only,
  /// no constant loads besides gravity and no no-twist condition.
  explicit MultibodyMinimalModel(const MultibodyProblem& problem);
  MultibodyMinimalModel(const MultibodyMinimalModel&) = delete;  // path_ refers to tree_
  MultibodyMinimalModel& operator=(const MultibodyMinimalModel&) = delete;

  int state_size() const override { return tree_.positions + tree_.velocities; }
  int point_size() const override {
    return state_size() + tree_.velocities + static_cast<int>(controls_.size());
  }
  const std::vector<int>& control_indices() const override { return controls_; }
  const PointFunctions& rhs() const override { return rhs_; }
  const PointFunctions& first_path() const override { return *path_; }
  const PointFunctions& path() const override { return *path_; }
  void variable_bounds(const PointRole& role, double* lower, double* upper) const override;

  /// y = (q, ν) of a consistent state (θ in (−π, π]; each quaternion of the sign nearest its initial value,
  /// so that attitudes within a half-turn of it are encoded continuously).
  Eigen::VectorXd state_vector(const multibody::State& state) const;
  /// The multibody state of the point variables w, or of a state vector y, which is their head: only the
  /// state's entries are read (forward kinematics; with a floating base the centre of mass at its initial
  /// place, at rest).
  multibody::State state_of(const double* w, double time) const;
  /// The Lagrangian's mass matrix M(q) (kg·m², symmetric positive definite) and c(q, ν) − B u (N·m) at the
  /// state y and controls u (actuator order): the path rows at ν̇ = 0 and their change with each ν̇_j.
  void equations_of_motion(const Eigen::VectorXd& y, const Eigen::VectorXd& u, Eigen::MatrixXd& mass,
                           Eigen::VectorXd& bias) const;
  /// ẏ = (q̇, ν̇) with ν̇ = −M⁻¹(c − B u): the forward dynamics.
  Eigen::VectorXd state_derivative(const Eigen::VectorXd& y, const Eigen::VectorXd& u) const;
  /// The local coordinates of the state near y (multibody_final_conditions.hpp: F, with T = Fᵀ): the
  /// identity, except for each quaternion e, whose three are those of an orthonormal basis of e's orthogonal
  /// complement (its norm is no coordinate of the attitude).
  Eigen::MatrixXd local_coordinates(const Eigen::VectorXd& y) const;
  const MinimalTree& tree() const { return tree_; }

 private:
  MinimalTree tree_;
  Vec3 com_space_ = Vec3::Zero();                              ///< floating base: x_com (m)
  Eigen::Vector4d sign_reference_ = Eigen::Vector4d::UnitX();  ///< floating base: e at the initial state
  std::vector<int> controls_;
  std::vector<double> bounds_;
  QuadraticFunctions rhs_;
  std::unique_ptr<PointFunctions> path_;
};

}  // namespace poinsot::optimal::detail
