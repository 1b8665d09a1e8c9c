// The final conditions of a multibody problem (multibody_final_conditions.hpp).
#include "multibody_final_conditions.hpp"

#include <algorithm>

#include <Eigen/Geometry>

#include "poinsot/core/linear_solvers.hpp"
#include "poinsot/multibody/observables.hpp"

namespace poinsot::optimal::detail {

bool conserves_momenta(const MultibodyProblem& problem) {
  const multibody::System& s = problem.system;
  if (s.gravity().norm() != 0.0 || !s.forces().empty() || !s.torques().empty()) return false;
  for (const multibody::Joint& j : s.joints())
    if (j.body_b == multibody::kWorld) return false;
  return std::all_of(problem.actuators.begin(), problem.actuators.end(),
                     [](const Actuator& a) { return a.kind != ActuatorKind::body_torque; });
}

Eigen::VectorXd conserved_quantities(const multibody::System& system, const multibody::State& state,
                                     double t) {
  Eigen::VectorXd q(9);
  const Vec3 P = multibody::linear_momentum(system, state);
  Vec3 moment = Vec3::Zero();
  for (std::size_t i = 0; i < state.bodies.size(); ++i)
    moment += system.bodies()[i].mass * state.bodies[i].x_space;
  q << P, multibody::angular_momentum(system, state), moment - t * P;
  return q;
}

multibody::State turn_hinge(const multibody::System& system, const multibody::State& state, int joint,
                            double phi) {
  const multibody::Joint& j = system.joints()[static_cast<std::size_t>(joint)];
  multibody::State out = state;
  multibody::BodyState& a = out.bodies[static_cast<std::size_t>(j.body_a)];
  const Vec3 axis = j.hinge_axis_a();
  const Vec3 point = a.x_space + a.R_space_body * j.point_a;
  const Vec3 omega_space = a.R_space_body * a.omega_body;
  const Vec3 point_velocity = a.v_space + omega_space.cross(a.R_space_body * j.point_a);
  a.R_space_body = a.R_space_body * Eigen::AngleAxisd(phi, axis).toRotationMatrix();
  a.omega_body = a.R_space_body.transpose() * omega_space;
  a.x_space = point - a.R_space_body * j.point_a;
  a.v_space = point_velocity - omega_space.cross(a.R_space_body * j.point_a);
  return out;
}

Eigen::MatrixXd null_space(const Eigen::MatrixXd& M) {
  if (M.rows() == 0) return Eigen::MatrixXd::Identity(M.cols(), M.cols());
  const RightSingularVectors svd = right_singular_vectors(M);
  const Eigen::VectorXd& s = svd.singular_values;
  const double tol = 1e-10 * std::max(1.0, s.size() > 0 ? s(0) : 0.0);
  Eigen::Index rank = 0;
  while (rank < s.size() && s(rank) > tol)
    ++rank;
  return svd.V.rightCols(M.cols() - rank);
}

Eigen::MatrixXd final_condition_rows(const Eigen::MatrixXd& F, const Eigen::MatrixXd& T,
                                     const Eigen::MatrixXd& G, const Eigen::MatrixXd& D) {
  if (G.rows() == 0 && D.cols() == 0) return F;
  const Eigen::MatrixXd B = null_space(G * T);
  const Eigen::MatrixXd P = null_space((B.transpose() * F * D).transpose());
  return P.transpose() * B.transpose() * F;
}

Eigen::MatrixXd model_final_rows(const MultibodyProblem& problem, const Eigen::MatrixXd& F,
                                 const Eigen::MatrixXd& T,
                                 const std::function<multibody::State(const Eigen::VectorXd&)>& decode,
                                 const std::function<Eigen::VectorXd(const multibody::State&)>& encode) {
  const Eigen::VectorXd yf = encode(problem.final_state);
  const auto n = yf.size();
  // The conserved quantities are polynomials of degree ≤ 3 in y (R J vee(RᵀV) in R-coordinates): the central
  // difference's error is ε² times their third derivatives, ~1e-12, far below the SVD's tolerance.
  constexpr double eps = 1e-6;
  Eigen::MatrixXd G(0, n);
  if (conserves_momenta(problem)) {
    G.resize(9, n);
    for (Eigen::Index c = 0; c < n; ++c) {
      Eigen::VectorXd yp = yf, ym = yf;
      yp(c) += eps;
      ym(c) -= eps;
      G.col(c) = (conserved_quantities(problem.system, decode(yp), problem.final_time) -
                  conserved_quantities(problem.system, decode(ym), problem.final_time)) /
                 (2.0 * eps);
    }
  }
  Eigen::MatrixXd D(n, static_cast<Eigen::Index>(problem.free_final_hinges.size()));
  for (std::size_t k = 0; k < problem.free_final_hinges.size(); ++k) {
    const int j = problem.free_final_hinges[k];
    D.col(static_cast<Eigen::Index>(k)) = (encode(turn_hinge(problem.system, problem.final_state, j, eps)) -
                                           encode(turn_hinge(problem.system, problem.final_state, j, -eps))) /
                                          (2.0 * eps);
  }
  return final_condition_rows(F, T, G, D);
}

}  // namespace poinsot::optimal::detail
