#pragma once
/// @file multibody_minimal_model.hpp (internal)
/// The collocation point model of a multibody problem in minimal coordinates, independent of the
/// rotation-matrix equations: the joint angles θ of a tree of hinges rooted at the world.
///
/// Body i hangs from hinge i (its body_a), whose body_b p(i) is the world or a body of lower index. With the
/// relative rotation C_i = R_pᵀR_i of the initial state and the hinge axis n_i (body i's frame),
///
///     R_i = R_p C_i Rot(n_i, θ_i),   x_i = x_p + R_p B_i − R_i A_i,
///
/// so θ = 0 is the initial configuration. w = (θ, θ̇, θ̈, u); ẏ = (θ̇, θ̈); the path equation is the inverse
/// dynamics of the recursive Newton–Euler algorithm (Featherstone 2008, §5.3), outward for the velocities
/// and accelerations, inward for the joint force f_i and couple n_i (space frame):
///
///     ω_i = E_iᵀω_p + n_i θ̇_i,   ω̇_i = E_iᵀω̇_p + n_i θ̈_i + θ̇_i ω_i × n_i   (body frame, E_i = C_i Rot(n_i,
///     θ_i)), f_i = m_i (a_i − g) + Σ_c f_c,   n_i = R_i (J_i ω̇_i + ω_i × J_i ω_i) − (R_i A_i) × f_i + Σ_c
///     (n_c + (R_i B_c) × f_c), (R_i n_i)·n_i − u_i = 0 (one row per hinge),
///
/// with u_i the hinge's motor torque (0 when unactuated). The Jacobian and the Hessian of the weighted rows
/// come from forward automatic differentiation of first and second order (Eigen's AutoDiffScalar, nested):
/// exact to round-off, like the rotation-matrix model's.
#include <memory>
#include <vector>

#include "hermite_simpson_dae.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::detail {

/// The kinematic tree of hinges (see the file comment).
struct HingeTree {
  struct Link {
    int parent = -1;            ///< body index or multibody::kWorld
    Vec3 axis = Vec3::UnitZ();  ///< n_i, body frame, unit
    Mat3 C = Mat3::Identity();  ///< R_pᵀR_i at θ = 0
    Vec3 A = Vec3::Zero();      ///< joint point in body i's frame (m)
    Vec3 B = Vec3::Zero();      ///< joint point in the parent's frame (space frame for the world)
    double mass = 1.0;
    Mat3 J = Mat3::Identity();
  };
  std::vector<Link> links;  ///< one per body, in body order
  Vec3 gravity = Vec3::Zero();
};

class MultibodyMinimalModel final : public CollocationModel {
 public:
  /// Throws InvalidInput unless the system is a tree of hinges rooted at the world with hinge motors only
  /// and no constant loads besides gravity.
  explicit MultibodyMinimalModel(const MultibodyProblem& problem);
  MultibodyMinimalModel(const MultibodyMinimalModel&) = delete;  // path_ refers to tree_
  MultibodyMinimalModel& operator=(const MultibodyMinimalModel&) = delete;

  int state_size() const override { return 2 * n_; }
  int point_size() const override { return 3 * n_ + static_cast<int>(controls_.size()); }
  const std::vector<int>& control_indices() const override { return controls_; }
  const PointFunctions& rhs() const override { return rhs_; }
  const PointFunctions& first_path() const override { return *path_; }
  const PointFunctions& path() const override { return *path_; }
  void variable_bounds(bool first_node, double* lower, double* upper) const override;

  /// (θ, θ̇) of a consistent state (θ in (−π, π]).
  Eigen::VectorXd state_vector(const multibody::State& state) const;
  /// The multibody state of the point variables w (forward kinematics).
  multibody::State state_of(const double* w, double time) const;
  const HingeTree& tree() const { return tree_; }

 private:
  int n_ = 0;
  HingeTree tree_;
  std::vector<int> controls_;
  std::vector<double> bounds_;
  std::vector<int> motor_of_link_;  // control index in w, or −1
  QuadraticFunctions rhs_;
  std::unique_ptr<PointFunctions> path_;
};

}  // namespace poinsot::optimal::detail
