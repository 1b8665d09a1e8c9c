#pragma once
/// @file multibody_final_conditions.hpp (internal)
/// The final conditions of a multibody problem as independent linear rows A y(T) = A y_f, for either point
/// model. A model describes the state near the target by k local coordinates β (its tangent space):
/// δy = T β with T (n × k) and β = F δy with F (k × n), F T = I. The rows A = Pᵀ Bᵀ F then leave out
///
/// - the directions the conserved quantities fix (G, c × n, their gradients at the target): B is an
///   orthonormal basis of the null space of G T. Imposing them too would make the rows dependent on the
///   dynamics' own invariants (a rank-deficient constraint Jacobian at the optimum);
/// - the free directions D (n × f, e.g. a reaction wheel's angle): P is an orthonormal basis of the null
/// space
///   of (Bᵀ F D)ᵀ.
///
/// With neither, A = F (the rows are kept as given, bit for bit).
#include <functional>

#include "poinsot/core/types.hpp"
#include "poinsot/multibody/state.hpp"
#include "poinsot/optimal/multibody_problem.hpp"

namespace poinsot::optimal::detail {

/// Whether the system conserves its linear and angular momenta: no joint to the world, no gravity, no
/// constant force or torque, and only hinge and ball motors (internal couples) as actuators.
bool conserves_momenta(const MultibodyProblem& problem);

/// The conserved quantities of a free-floating system at time t (s): the linear momentum P (kg·m/s), the
/// angular momentum about the space origin H (kg·m²/s) and M x_com − t P (kg·m), 9 numbers.
Eigen::VectorXd conserved_quantities(const multibody::System& system, const multibody::State& state,
                                     double t);

/// The state with hinge `joint` turned by φ (rad): its body_a rotated about the hinge axis through the joint
/// point, the joint point's velocity and body_a's angular velocity in space kept (the rate across the hinge
/// unchanged). Valid for a hinge whose body_a is in no other joint (validate checks it).
multibody::State turn_hinge(const multibody::System& system, const multibody::State& state, int joint,
                            double phi);

/// A = Pᵀ Bᵀ F of the file comment. G and D may have no rows / columns.
Eigen::MatrixXd final_condition_rows(const Eigen::MatrixXd& F, const Eigen::MatrixXd& T,
                                     const Eigen::MatrixXd& G, const Eigen::MatrixXd& D);

/// The rows of a model: G by central differences of conserved_quantities(decode(y), T) (exact to
/// round-off for their polynomials of degree ≤ 3 in y), D by central differences of encode(turn_hinge(…))
/// for every free hinge.
Eigen::MatrixXd model_final_rows(const MultibodyProblem& problem, const Eigen::MatrixXd& F,
                                 const Eigen::MatrixXd& T,
                                 const std::function<multibody::State(const Eigen::VectorXd&)>& decode,
                                 const std::function<Eigen::VectorXd(const multibody::State&)>& encode);

/// An orthonormal basis of the null space of M (columns), by SVD with the relative tolerance 1e-10.
Eigen::MatrixXd null_space(const Eigen::MatrixXd& M);

}  // namespace poinsot::optimal::detail
