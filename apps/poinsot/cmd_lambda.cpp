// `poinsot lambda`: runs a rigid body and checks the theorems of Vallée & Dumitriu (2002) on the Lagrange
// multipliers Λ along the run (analysis::analyse_lambda), printing a report or, with --json, one object
// (keys in docs/lambda.md). The body, initial state, torque and integrator come from a scenario file
// (`poinsot lambda SCENARIO.toml`, docs/scenario.md), or from flags: principal moments or axisymmetric (A, C,
// k) and --omega0. Explicit --method, --dt, --t-end, --sample-dt override the scenario's values.
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "lambda_json.hpp"
#include "poinsot/analysis/axisymmetric.hpp"
#include "poinsot/analysis/lambda_report.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/io/scenario.hpp"

namespace poinsot::cli {
namespace {

struct LambdaOptions {
  std::string scenario;  // path of a scenario file; empty: the body comes from the flags
  bool has_method = false, has_dt = false, has_t_end = false, has_sample_dt = false;
  std::vector<double> moments;  // I1 I2 I3
  double A = 0.0;
  double C = 0.0;
  std::vector<double> k{0.0, 0.0, 1.0};
  std::vector<double> omega0;
  double t_end = 10.0;
  double dt = 1e-3;
  double sample_dt = 0.01;
  std::string method{dynamics::kDefaultLambdaMethod};
  double volume = 0.0;
  bool json = false;
};

Vec3 vec3(const std::vector<double>& v) {
  return Vec3(v[0], v[1], v[2]);
}

nlohmann::ordered_json vec_json(const Vec3& v) {
  return nlohmann::ordered_json::array({v[0], v[1], v[2]});
}

nlohmann::ordered_json mat_json(const Mat3& m) {
  auto out = nlohmann::ordered_json::array();
  for (int i = 0; i < 3; ++i)
    out.push_back(nlohmann::ordered_json::array({m(i, 0), m(i, 1), m(i, 2)}));
  return out;
}

nlohmann::ordered_json stress_json(const analysis::StressSummary& s) {
  nlohmann::ordered_json j;
  j["tensor"] = mat_json(s.tensor);
  j["principal"] = vec_json(s.principal);
  j["tresca"] = s.tresca;
  j["von_mises"] = s.von_mises;
  return j;
}

dynamics::RigidBody make_body(const LambdaOptions& o) {
  const bool axi = o.A != 0.0 || o.C != 0.0;
  if (axi == !o.moments.empty()) {
    throw InvalidInput(
        "lambda: body: got both --moments and --A/--C or neither; expected exactly one of --moments I1 I2 I3 "
        "or --A A --C C [--k x y z]");
  }
  if (!axi) return dynamics::RigidBody::from_principal_moments(vec3(o.moments));
  if (!(o.A > 0.0) || !(o.C > 0.0)) {
    throw InvalidInput(fmt::format("lambda: --A {} --C {} kg·m²; expected both > 0", format_number(o.A),
                                   format_number(o.C)));
  }
  const Vec3 k = vec3(o.k);
  if (!(k.norm() > 0.0) || !k.allFinite()) {
    throw InvalidInput(fmt::format("lambda: --k {}; expected a finite non-zero vector", format_vector(k)));
  }
  return dynamics::RigidBody::from_inertia(analysis::AxisymmetricInertia{o.A, o.C, k.normalized()}.inertia());
}

/// The scenario file's body, state, torque and integrator, with the flags that were given on top.
analysis::LambdaReport run_scenario(const LambdaOptions& o) {
  if (!o.moments.empty() || o.A != 0.0 || o.C != 0.0 || !o.omega0.empty()) {
    throw InvalidInput(
        fmt::format("lambda: got the scenario file {} and body flags (--moments, --A, --C, --omega0); "
                    "expected one or the other",
                    o.scenario));
  }
  io::Scenario sc = io::load_scenario(o.scenario);
  io::ScenarioOverrides ov;
  if (o.has_method) ov.method = o.method;
  ov.has_dt = o.has_dt;
  ov.dt = o.dt;
  ov.has_t_end = o.has_t_end;
  ov.t_end = o.t_end;
  ov.has_sample_dt = o.has_sample_dt;
  ov.sample_dt = o.sample_dt;
  io::apply_overrides(sc, ov);
  analysis::LambdaAnalysisOptions a;
  a.method = sc.method;
  a.integrator = sc.integrator;
  a.t_end = sc.simulation.t_end;
  a.sample_dt = sc.simulation.sample_dt;
  a.torque = sc.torque;
  a.volume_m3 = o.volume;
  return analysis::analyse_lambda(sc.body, sc.initial, a);
}

analysis::LambdaReport run_flags(const LambdaOptions& o) {
  if (o.omega0.empty()) {
    throw InvalidInput("lambda: --omega0 is missing; expected --omega0 x y z (rad/s) or a scenario file");
  }
  const dynamics::RigidBody body = make_body(o);
  dynamics::State initial;
  initial.omega_body = vec3(o.omega0);
  analysis::LambdaAnalysisOptions a;
  a.method = o.method;
  a.integrator.dt = o.dt;
  a.t_end = o.t_end;
  a.sample_dt = o.sample_dt;
  a.volume_m3 = o.volume;
  return analysis::analyse_lambda(body, initial, a);
}

void run(const LambdaOptions& o) {
  const analysis::LambdaReport report = o.scenario.empty() ? run_flags(o) : run_scenario(o);
  if (o.json) {
    fmt::print("{}\n", lambda_report_json(report).dump(2));
  } else {
    fmt::print("{}", analysis::format_lambda_report(report));
  }
}

}  // namespace

nlohmann::ordered_json lambda_report_json(const analysis::LambdaReport& r) {
  const analysis::LambdaProperties& p = r.properties;
  nlohmann::ordered_json j;
  j["eigenvalues_initial"] = vec_json(p.eigenvalues_initial);
  j["eigenvalues_final"] = vec_json(p.eigenvalues_final);
  j["eigenvalue_max_variation"] = p.eigenvalue_max_variation;
  j["symmetry_error_max"] = p.symmetry_error_max;
  j["max_eigenvalue_max"] = p.max_eigenvalue_max;
  j["trace_plus_2T_max"] = p.trace_plus_2T_max;
  j["stress_integral_initial"] = mat_json(p.stress_initial.integral.tensor);
  if (p.closed_form) {
    const analysis::AxisymmetricCheck& c = *p.closed_form;
    nlohmann::ordered_json cf;
    cf["c1"] = c.c1;
    cf["c2"] = c.c2;
    cf["Delta"] = c.Delta;
    cf["eigenvalues"] = vec_json(c.eigenvalues);
    cf["max_deviation"] = c.max_deviation;
    cf["A"] = c.inertia.A;
    cf["C"] = c.inertia.C;
    cf["k"] = vec_json(c.inertia.k);
    cf["mu"] = c.mu;
    cf["r"] = c.r;
    cf["lambda1"] = c.lambda123[0];
    cf["lambda2"] = c.lambda123[1];
    cf["lambda3"] = c.lambda123[2];
    cf["eigenvector_residual_max"] = c.eigenvector_residual_max;
    cf["constant_matrix_deviation_max"] = c.constant_matrix_deviation_max;
    const analysis::AxisymmetricSpecialCases& sc = c.special_cases;
    cf["special_cases"] = {{"ball", sc.ball},
                           {"flat", sc.flat},
                           {"axial_spin", sc.axial_spin},
                           {"equatorial_spin", sc.equatorial_spin},
                           {"zero_discriminant", sc.zero_discriminant},
                           {"zero_velocity", sc.zero_velocity}};
    j["closed_form"] = cf;
  } else {
    j["closed_form"] = nullptr;
  }
  j["method"] = r.method;
  j["torque"] = r.torque;
  j["principal_moments"] = vec_json(r.principal_moments);
  j["t_initial"] = r.t_initial;
  j["t_end"] = r.t_end;
  j["dt"] = r.dt;
  j["sample_dt"] = r.sample_dt;
  j["samples"] = p.samples;
  j["steps"] = r.steps;
  j["lambda_initial"] = mat_json(p.lambda_initial);
  j["lambda_final"] = mat_json(p.lambda_final);
  j["lambda_scale"] = p.lambda_scale;
  if (p.has_integrator_multiplier) {
    j["integrator_multiplier"] = {{"deviation_max", p.integrator_multiplier_deviation_max},
                                  {"symmetry_error_max", p.integrator_multiplier_symmetry_error_max}};
  } else {
    j["integrator_multiplier"] = nullptr;
  }
  j["stress_initial"] = stress_json(p.stress_initial.integral);
  j["volume"] = r.volume_m3;
  j["mean_stress_initial"] = p.stress_initial.has_mean ? stress_json(p.stress_initial.mean) : nullptr;
  j["von_mises_max"] = p.von_mises_max;
  j["invariant_errors"] = {{"energy_rel_max", r.invariant_errors.energy_rel_max},
                           {"L_space_rel_max", r.invariant_errors.L_space_rel_max},
                           {"L_norm_rel_max", r.invariant_errors.L_norm_rel_max},
                           {"orthogonality_max", r.invariant_errors.orthogonality_max}};
  return j;
}

void register_lambda(CLI::App& app) {
  auto opts = std::make_shared<LambdaOptions>();
  auto* cmd =
      app.add_subcommand("lambda",
                         "Check the Lagrange multipliers Λ of R''K = RΛ (Vallée & Dumitriu 2002) and the "
                         "constraint stress along a torque-free run");
  cmd->add_option("--moments", opts->moments, "principal moments I1 I2 I3 (kg·m²)")->expected(3);
  cmd->add_option("--A", opts->A, "axisymmetric body: moment about any axis normal to k (kg·m²)");
  cmd->add_option("--C", opts->C, "axisymmetric body: moment about the symmetry axis k (kg·m²)");
  cmd->add_option("--k", opts->k, "axisymmetric body: symmetry axis x y z, body frame (default 0 0 1)")
      ->expected(3);
  cmd->add_option("scenario", opts->scenario, "scenario file (docs/scenario.md) instead of the body flags");
  cmd->add_option("--omega0", opts->omega0, "initial angular velocity x y z, body frame (rad/s); R(0) = I")
      ->expected(3);
  auto* t_end = cmd->add_option("--t-end", opts->t_end, "final time (s, default 10)");
  auto* dt = cmd->add_option("--dt", opts->dt, "integrator step (s, default 1e-3)");
  auto* sample_dt =
      cmd->add_option("--sample-dt", opts->sample_dt, "interval between checked states (s, default 0.01)");
  auto* method = cmd->add_option(
      "--method", opts->method,
      fmt::format("integrator: {} (default {})", dynamics::method_names(), dynamics::kDefaultLambdaMethod));
  cmd->add_option("--volume", opts->volume, "body volume (m³) for the mean stress (default: unknown)");
  cmd->add_flag("--json", opts->json, "print one JSON object (keys in docs/lambda.md)");
  cmd->callback([opts, t_end, dt, sample_dt, method] {
    opts->has_t_end = t_end->count() > 0;
    opts->has_dt = dt->count() > 0;
    opts->has_sample_dt = sample_dt->count() > 0;
    opts->has_method = method->count() > 0;
    run(*opts);
  });
}

}  // namespace poinsot::cli
