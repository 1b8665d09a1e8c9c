#include "poinsot/analysis/stress.hpp"

#include <cmath>

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::analysis {

Mat3 stress_integral_space(const Mat3& lambda_body, const Mat3& R) {
  return -R * symmetric_part(lambda_body) * R.transpose();
}

Mat3 stress_integral_space(const dynamics::RigidBody& body, const dynamics::State& state,
                           const dynamics::TorqueModel* torque) {
  return stress_integral_space(lambda_from_state(body, state, torque), state.R_space_body);
}

Mat3 steady_spin_stress_integral_body(const Mat3& poinsot_K, const Vec3& k_body, double rate) {
  require_finite("steady spin: axis k", k_body);
  require_finite("steady spin: rate (rad/s)", rate);
  const double norm = k_body.norm();
  if (!(norm > 0.0)) throw InvalidInput("steady spin: axis k = (0, 0, 0); expected a non-zero vector");
  const Vec3 k = k_body / norm;
  return rate * rate * (poinsot_K - k.dot(poinsot_K * k) * k * k.transpose());
}

StressSummary summarize_stress(const Mat3& tensor) {
  StressSummary s;
  s.tensor = 0.5 * (tensor + tensor.transpose());
  Eigen::SelfAdjointEigenSolver<Mat3> solver(s.tensor);
  s.principal = solver.eigenvalues();
  s.principal_axes = solver.eigenvectors();
  const Vec3& p = s.principal;
  s.tresca = 0.5 * (p[2] - p[0]);
  s.von_mises = std::sqrt(
      0.5 * ((p[0] - p[1]) * (p[0] - p[1]) + (p[1] - p[2]) * (p[1] - p[2]) + (p[2] - p[0]) * (p[2] - p[0])));
  s.trace = p.sum();
  return s;
}

ConstraintStress constraint_stress(const Mat3& lambda_body, const Mat3& R, double volume_m3) {
  require_non_negative("constraint stress: volume (m³)", volume_m3, "m³");
  ConstraintStress c;
  const Mat3 integral = stress_integral_space(lambda_body, R);
  c.integral = summarize_stress(integral);
  if (volume_m3 > 0.0) {
    c.has_mean = true;
    c.mean = summarize_stress(integral / volume_m3);
  }
  return c;
}

}  // namespace poinsot::analysis
