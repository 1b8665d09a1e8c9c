// `poinsot lambda`: runs a rigid body and checks the theorems of Vallée & Dumitriu (2002) on the Lagrange
// multipliers Λ along the run (analysis::analyse_lambda), printing a report or, with --json, one object
// (io/run/lambda_json.hpp, keys in docs/lambda.md; the same text Python's poinsot.analysis.lambda_report
// reads). The body, initial state, torque and integrator come from a scenario file
// (`poinsot lambda SCENARIO.toml`, docs/scenario.md), or from flags: principal moments or axisymmetric (A, C,
// k) and --omega0. Explicit --method, --dt, --t-end, --sample-dt override the scenario's values.
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/analysis/axisymmetric.hpp"
#include "poinsot/analysis/lambda_report.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/io/run/lambda_json.hpp"
#include "poinsot/io/scenario/scenario.hpp"

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

dynamics::RigidBody make_body(const LambdaOptions& o) {
  const bool axi = o.A != 0.0 || o.C != 0.0;
  if (axi == !o.moments.empty()) {
    throw InvalidInput(
        "lambda: body: got both --moments and --A/--C or neither; expected exactly one of --moments I1 I2 I3 "
        "or --A A --C C [--k x y z]");
  }
  if (!axi) return dynamics::RigidBody::from_principal_moments(vec3_from_list(o.moments));
  if (!(o.A > 0.0) || !(o.C > 0.0)) {
    throw InvalidInput(fmt::format("lambda: --A {} --C {} kg·m²; expected both > 0", format_number(o.A),
                                   format_number(o.C)));
  }
  const Vec3 k = vec3_from_list(o.k);
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
  if (o.has_dt) ov.dt = o.dt;
  if (o.has_t_end) ov.t_end = o.t_end;
  if (o.has_sample_dt) ov.sample_dt = o.sample_dt;
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
  initial.omega_body = vec3_from_list(o.omega0);
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
    fmt::print("{}\n", io::lambda_report_json(report));
  } else {
    fmt::print("{}", analysis::format_lambda_report(report));
  }
}

}  // namespace

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
