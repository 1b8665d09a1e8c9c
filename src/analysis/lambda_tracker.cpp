#include "poinsot/analysis/lambda_tracker.hpp"

#include <algorithm>
#include <cmath>

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/dynamics/state.hpp"

namespace poinsot::analysis {

LambdaTracker::LambdaTracker(const dynamics::RigidBody& body,
                             std::shared_ptr<const dynamics::TorqueModel> torque,
                             const dynamics::State& initial, const LambdaTrackerOptions& options)
    : body_(body), torque_(std::move(torque)), options_(options) {
  dynamics::validate_state(initial, "lambda: initial state");
  require_non_negative("lambda: volume (m³)", options_.volume_m3, "m³");
  props_.torque_free = torque_ == nullptr || torque_->is_zero();
  props_.t_initial = initial.time;
  const Mat3 lambda0 = lambda_from_state(body_, initial, torque_.get());
  props_.lambda_initial = lambda0;
  props_.eigenvalues_initial = sorted_eigenvalues(lambda0);
  props_.lambda_scale = lambda0.norm();
  props_.stress_initial = constraint_stress(lambda0, initial.R_space_body, options_.volume_m3);

  if (props_.torque_free) {
    if (const auto axi = detect_axisymmetry(body_, options_.axisymmetry_tolerance)) {
      axisymmetric_.emplace(*axi, initial.omega_body, initial.time, options_.axisymmetry_tolerance);
      const AxisymmetricLambda& a = *axisymmetric_;
      AxisymmetricCheck c;
      c.inertia = a.inertia();
      c.mu = a.mu();
      c.r = a.r();
      c.c1 = a.c1();
      c.c2 = a.c2();
      c.Delta = a.Delta();
      c.lambda123 = Vec3(a.lambda1(), a.lambda2(), a.lambda3());
      c.eigenvalues = a.eigenvalues_sorted();
      c.constant_matrix = a.constant_matrix_53();
      c.special_cases = a.special_cases();
      props_.closed_form = c;
    }
  }
  observe(initial);
}

void LambdaTracker::compare_multiplier(const dynamics::State& at, const Mat3& lambda_integrator_body) {
  const Vec3 tau =
      props_.torque_free ? Vec3::Zero() : Vec3(torque_->torque_body(at.time, at.R_space_body, at.omega_body));
  const Mat3 lambda = lambda_from_state(body_, at, torque_.get());
  LambdaProperties& p = props_;
  p.has_integrator_multiplier = true;
  p.integrator_multiplier_deviation_max =
      std::max(p.integrator_multiplier_deviation_max, (lambda_integrator_body - lambda).norm());
  p.integrator_multiplier_symmetry_error_max =
      std::max(p.integrator_multiplier_symmetry_error_max, symmetry_error(lambda_integrator_body, tau));
}

void LambdaTracker::observe(const dynamics::State& state) {
  const Vec3 tau = props_.torque_free
                       ? Vec3::Zero()
                       : Vec3(torque_->torque_body(state.time, state.R_space_body, state.omega_body));
  const Mat3 lambda = lambda_from_state(body_, state, torque_.get());
  const Vec3 eig = sorted_eigenvalues(lambda);
  LambdaProperties& p = props_;
  ++p.samples;
  p.t_final = state.time;
  p.lambda_final = lambda;
  p.eigenvalues_final = eig;
  p.eigenvalue_max_variation =
      std::max(p.eigenvalue_max_variation, (eig - p.eigenvalues_initial).cwiseAbs().maxCoeff());
  p.symmetry_error_max = std::max(p.symmetry_error_max, symmetry_error(lambda, tau));
  p.max_eigenvalue_max = std::max(p.max_eigenvalue_max, eig[2]);
  const double T = dynamics::kinetic_energy(body_, state);
  p.trace_plus_2T_max = std::max(p.trace_plus_2T_max, std::abs(lambda.trace() + 2.0 * T));
  const StressSummary s = summarize_stress(stress_integral_space(lambda, state.R_space_body));
  const double vm = options_.volume_m3 > 0.0 ? s.von_mises / options_.volume_m3 : s.von_mises;
  p.von_mises_max = std::max(p.von_mises_max, vm);

  if (axisymmetric_) {
    const AxisymmetricLambda& a = *axisymmetric_;
    AxisymmetricCheck& c = *p.closed_form;
    c.max_deviation = std::max(c.max_deviation, (eig - c.eigenvalues).cwiseAbs().maxCoeff());
    const Vec3 v = a.inertia().k.cross(state.omega_body);  // k × ω(t), C14
    const double vn = v.norm();
    if (vn > 0.0) {
      c.eigenvector_residual_max =
          std::max(c.eigenvector_residual_max, (lambda * v - a.lambda3() * v).norm() / vn);
    }
    const Mat3 E = a.E(state.time);
    c.constant_matrix_deviation_max =
        std::max(c.constant_matrix_deviation_max, (E.transpose() * lambda * E - c.constant_matrix).norm());
  }
}

}  // namespace poinsot::analysis
