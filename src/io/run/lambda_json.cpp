// The JSON form of the Λ report (see lambda_json.hpp).
#include "poinsot/io/run/lambda_json.hpp"

#include "run_json.hpp"

namespace poinsot::io {
namespace {

using detail::json;
using detail::mat;
using detail::num;
using detail::vec;

json stress(const analysis::StressSummary& s) {
  return {
      {"tensor", mat(s.tensor)}, {"principal", vec(s.principal)}, {"principal_axes", mat(s.principal_axes)},
      {"tresca", num(s.tresca)}, {"von_mises", num(s.von_mises)}, {"trace", num(s.trace)}};
}

json special_cases(const analysis::AxisymmetricSpecialCases& sc) {
  return {{"ball", sc.ball},
          {"flat", sc.flat},
          {"axial_spin", sc.axial_spin},
          {"equatorial_spin", sc.equatorial_spin},
          {"zero_discriminant", sc.zero_discriminant},
          {"zero_velocity", sc.zero_velocity}};
}

json closed_form(const analysis::AxisymmetricCheck& c) {
  return {{"c1", num(c.c1)},
          {"c2", num(c.c2)},
          {"Delta", num(c.Delta)},
          {"eigenvalues", vec(c.eigenvalues)},
          {"max_deviation", num(c.max_deviation)},
          {"A", c.inertia.A},
          {"C", c.inertia.C},
          {"k", vec(c.inertia.k)},
          {"mu", num(c.mu)},
          {"r", num(c.r)},
          {"lambda1", num(c.lambda123[0])},
          {"lambda2", num(c.lambda123[1])},
          {"lambda3", num(c.lambda123[2])},
          {"constant_matrix", mat(c.constant_matrix)},
          {"eigenvector_residual_max", num(c.eigenvector_residual_max)},
          {"constant_matrix_deviation_max", num(c.constant_matrix_deviation_max)},
          {"special_cases", special_cases(c.special_cases)}};
}

}  // namespace

json detail::lambda_properties_value(const analysis::LambdaProperties& p) {
  json j;
  j["samples"] = p.samples;
  j["t_initial"] = p.t_initial;
  j["t_final"] = p.t_final;
  j["torque_free"] = p.torque_free;
  j["lambda_initial"] = mat(p.lambda_initial);
  j["lambda_final"] = mat(p.lambda_final);
  j["lambda_scale"] = num(p.lambda_scale);
  j["eigenvalues_initial"] = vec(p.eigenvalues_initial);
  j["eigenvalues_final"] = vec(p.eigenvalues_final);
  j["eigenvalue_max_variation"] = num(p.eigenvalue_max_variation);
  j["symmetry_error_max"] = num(p.symmetry_error_max);
  j["max_eigenvalue_max"] = num(p.max_eigenvalue_max);
  j["trace_plus_2T_max"] = num(p.trace_plus_2T_max);
  j["stress_integral_initial"] = mat(p.stress_initial.integral.tensor);
  j["stress_initial"] = stress(p.stress_initial.integral);
  j["mean_stress_initial"] = p.stress_initial.has_mean ? stress(p.stress_initial.mean) : json(nullptr);
  j["von_mises_max"] = num(p.von_mises_max);
  j["integrator_multiplier"] =
      p.has_integrator_multiplier
          ? json{{"deviation_max", num(p.integrator_multiplier_deviation_max)},
                 {"symmetry_error_max", num(p.integrator_multiplier_symmetry_error_max)}}
          : json(nullptr);
  j["closed_form"] = p.closed_form ? closed_form(*p.closed_form) : json(nullptr);
  return j;
}

std::string stress_summary_json(const analysis::StressSummary& s) {
  return stress(s).dump(2);
}

std::string special_cases_json(const analysis::AxisymmetricSpecialCases& cases) {
  return special_cases(cases).dump(2);
}

std::string constraint_stress_json(const analysis::ConstraintStress& c) {
  const json j = {{"integral", stress(c.integral)}, {"mean", c.has_mean ? stress(c.mean) : json(nullptr)}};
  return j.dump(2);
}

std::string lambda_properties_json(const analysis::LambdaProperties& p) {
  return detail::lambda_properties_value(p).dump(2);
}

std::string lambda_report_json(const analysis::LambdaReport& r) {
  json j;
  j["method"] = r.method;
  j["torque"] = r.torque;
  j["principal_moments"] = vec(r.principal_moments);
  j["t_initial"] = r.t_initial;
  j["t_end"] = r.t_end;
  j["dt"] = r.dt;
  j["sample_dt"] = r.sample_dt;
  j["steps"] = r.steps;
  j["volume"] = r.volume_m3;
  j.update(detail::lambda_properties_value(r.properties));  // its t_initial is the report's
  j["invariant_errors"] = {{"energy_rel_max", num(r.invariant_errors.energy_rel_max)},
                           {"L_space_rel_max", num(r.invariant_errors.L_space_rel_max)},
                           {"L_norm_rel_max", num(r.invariant_errors.L_norm_rel_max)},
                           {"orthogonality_max", num(r.invariant_errors.orthogonality_max)}};
  return j.dump(2);
}

}  // namespace poinsot::io
