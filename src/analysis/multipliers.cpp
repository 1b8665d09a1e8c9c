#include "poinsot/analysis/multipliers.hpp"

#include <Eigen/Eigenvalues>

#include "poinsot/so3/hat.hpp"

namespace poinsot::analysis {

Vec3 angular_acceleration_body(const dynamics::RigidBody& body, const dynamics::State& state,
                               const dynamics::TorqueModel* torque) {
  const Vec3& w = state.omega_body;
  Vec3 rhs = -w.cross(body.inertia() * w);
  if (torque != nullptr && !torque->is_zero()) rhs += torque->torque_body(state.time, state.R_space_body, w);
  return body.inertia_inverse() * rhs;
}

Mat3 lambda_from_omega(const dynamics::RigidBody& body, const Vec3& omega_body, const Vec3& omega_dot_body) {
  // j(ω)² = ω⊗ω − |ω|² I (the double cross product): one rank-one update, no matrix product.
  const Mat3 w2 = omega_body * omega_body.transpose() - omega_body.squaredNorm() * Mat3::Identity();
  return (w2 + so3::hat(omega_dot_body)) * body.poinsot();
}

Mat3 lambda_from_state(const dynamics::RigidBody& body, const dynamics::State& state,
                       const dynamics::TorqueModel* torque) {
  return lambda_from_omega(body, state.omega_body, angular_acceleration_body(body, state, torque));
}

Mat3 symmetric_part(const Mat3& m) {
  return 0.5 * (m + m.transpose());
}

double symmetry_error(const Mat3& lambda_body, const Vec3& torque_body) {
  return (lambda_body - lambda_body.transpose() - so3::hat(torque_body)).norm();
}

Vec3 sorted_eigenvalues(const Mat3& lambda_body) {
  Eigen::SelfAdjointEigenSolver<Mat3> solver(symmetric_part(lambda_body), Eigen::EigenvaluesOnly);
  return solver.eigenvalues();  // ascending
}

}  // namespace poinsot::analysis
