#include "poinsot/analysis/lambda_report.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/rk4.hpp"

namespace poinsot::analysis {

LambdaReport analyse_lambda(const dynamics::RigidBody& body, const dynamics::State& initial,
                            const LambdaAnalysisOptions& options) {
  const auto torque = options.torque ? options.torque : dynamics::TorqueModel::none();
  std::unique_ptr<dynamics::Integrator> integrator =
      dynamics::make_integrator(options.method, body, torque, options.integrator);
  LambdaTrackerOptions tracker_options;
  tracker_options.volume_m3 = options.volume_m3;
  tracker_options.axisymmetry_tolerance = options.axisymmetry_tolerance;
  LambdaTracker tracker(body, torque, initial, tracker_options);

  // rattle: its multiplier is centred on the midpoint of its last step. The driver cuts each sample
  // interval [a, b] into n = ⌈(b − a)/h⌉ equal steps (simulation.cpp), so the last step is (b − a)/n long.
  const double h_nominal = integrator->nominal_step();
  dynamics::Rk4Integrator back(body, torque, {.dt = h_nominal > 0.0 ? h_nominal : 1.0});
  double previous_t = initial.time;
  bool first = true;
  const dynamics::Observer observer = [&](const dynamics::State& s) {
    if (first) {  // the initial state: already observed by the tracker's constructor
      first = false;
      return true;
    }
    tracker.observe(s);
    Mat3 lambda_integrator;
    if (!integrator->is_adaptive() && h_nominal > 0.0 && integrator->last_multiplier(lambda_integrator)) {
      const double span = s.time - previous_t;
      const double n = std::max(1.0, std::ceil(span / h_nominal - 1e-9));
      dynamics::State mid = s;
      back.step(mid, -0.5 * span / n);
      tracker.compare_multiplier(mid, lambda_integrator);
    }
    previous_t = s.time;
    return true;
  };
  dynamics::SimulationOptions sim;
  sim.t_end = options.t_end;
  sim.sample_dt = options.sample_dt;
  sim.locate_flips = false;
  const dynamics::SimulationResult result =
      dynamics::simulate(body, torque, initial, *integrator, sim, observer);

  LambdaReport report;
  report.method = std::string(integrator->name());
  report.torque = torque->describe();
  report.principal_moments = body.principal_moments();
  report.t_initial = initial.time;
  report.t_end = options.t_end;
  report.sample_dt = options.sample_dt;
  report.dt = h_nominal;
  report.volume_m3 = options.volume_m3;
  report.properties = tracker.properties();
  report.steps = result.steps;
  report.invariant_errors = result.errors;
  report.wall_time_s = result.wall_time_s;
  return report;
}

namespace {

std::string g(double x) {
  return format_number(x, 10);
}
std::string v(const Vec3& x) {
  return fmt::format("({}, {}, {})", g(x[0]), g(x[1]), g(x[2]));
}

}  // namespace

std::string format_lambda_report(const LambdaReport& r) {
  const LambdaProperties& p = r.properties;
  std::string out;
  auto line = [&out](const std::string& s) {
    out += s;
    out += '\n';
  };
  line(fmt::format("Lagrange multipliers Λ = (j(ω)² + j(ω̇))K (Vallée & Dumitriu 2002), body frame, J"));
  line(fmt::format("body: principal moments {} kg·m²; torque: {}", v(r.principal_moments), r.torque));
  line(fmt::format("run: {} from t = {} s to {} s, {}, {} samples every {} s, {} steps", r.method,
                   g(r.t_initial), g(r.t_end), r.dt > 0.0 ? fmt::format("step {} s", g(r.dt)) : "closed form",
                   p.samples, g(r.sample_dt), r.steps));
  line(fmt::format("eigenvalues of Λ at t0 (ascending, J):     {}", v(p.eigenvalues_initial)));
  line(fmt::format("eigenvalues of Λ at t_end (ascending, J):  {}", v(p.eigenvalues_final)));
  line(fmt::format("largest eigenvalue variation (J):          {}{}", g(p.eigenvalue_max_variation),
                   p.closed_form ? "   (axisymmetric: constant in theory)"
                                 : "   (general body: not constant, docs/conventions.md C3)"));
  line(fmt::format("largest eigenvalue seen (J, must be <= 0): {}", g(p.max_eigenvalue_max)));
  line(fmt::format("symmetry error max |Λ − Λᵀ − j(τ)| (J):    {}", g(p.symmetry_error_max)));
  line(fmt::format("max |tr Λ + 2T| (J):                       {}", g(p.trace_plus_2T_max)));
  line(fmt::format("scale |Λ(t0)|_F (J):                       {}", g(p.lambda_scale)));
  if (p.has_integrator_multiplier) {
    line(fmt::format("integrator multipliers vs state formula:   max |ΔΛ|_F = {} J, symmetry error {} J",
                     g(p.integrator_multiplier_deviation_max),
                     g(p.integrator_multiplier_symmetry_error_max)));
  }
  if (p.closed_form) {
    const AxisymmetricCheck& c = *p.closed_form;
    line(fmt::format("axisymmetric: A = {} kg·m², C = {} kg·m², k = {}", g(c.inertia.A), g(c.inertia.C),
                     v(c.inertia.k)));
    line(fmt::format("  mu = {} rad/s, r = {} rad/s, c1 = {} J, c2 = {} J², Delta = {} J²", g(c.mu), g(c.r),
                     g(c.c1), g(c.c2), g(c.Delta)));
    line(fmt::format("  closed form λ1, λ2, λ3 = {} J (ascending {})", v(c.lambda123), v(c.eigenvalues)));
    line(fmt::format("  max deviation of eig Λ(t) from the closed form (J): {}", g(c.max_deviation)));
    line(fmt::format("  max |Λ v − λ3 v|/|v|, v = k × ω(t) (J):             {}",
                     g(c.eigenvector_residual_max)));
    line(fmt::format("  max |EᵀΛE − EᵀΛE(t0)|_F (J):                        {}",
                     g(c.constant_matrix_deviation_max)));
    std::string cases;
    const AxisymmetricSpecialCases& sc = c.special_cases;
    if (sc.ball) cases += " ball(A=C)";
    if (sc.flat) cases += " flat(A=C/2)";
    if (sc.axial_spin) cases += " r=0";
    if (sc.equatorial_spin) cases += " mu=0";
    if (sc.zero_discriminant) cases += " Delta=0";
    if (sc.zero_velocity) cases += " at-rest";
    line(fmt::format("  special cases:{}", cases.empty() ? " none" : cases));
  }
  const StressSummary& s = p.stress_initial.integral;
  line(fmt::format("stress integral ∫σ dv = −RΛRᵀ at t0 (space frame, N·m): {}", format_matrix(s.tensor)));
  line(fmt::format("  principal values {} N·m, Tresca {} N·m, von Mises {} N·m", v(s.principal), g(s.tresca),
                   g(s.von_mises)));
  if (p.stress_initial.has_mean) {
    const StressSummary& m = p.stress_initial.mean;
    line(fmt::format("  mean stress (÷ {} m³): principal {} Pa, Tresca {} Pa, von Mises {} Pa",
                     g(r.volume_m3), v(m.principal), g(m.tresca), g(m.von_mises)));
  }
  line(fmt::format("  largest von Mises over the run: {} {}", g(p.von_mises_max),
                   r.volume_m3 > 0 ? "Pa" : "N·m"));
  line(fmt::format("integrator: max relative energy error {}, |L| error {}, orthogonality {}",
                   g(r.invariant_errors.energy_rel_max), g(r.invariant_errors.L_norm_rel_max),
                   g(r.invariant_errors.orthogonality_max)));
  return out;
}

}  // namespace poinsot::analysis
