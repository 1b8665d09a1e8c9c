// Mesh refinement for the multibody transcriptions (multibody_refinement.hpp).
#include "poinsot/optimal/multibody_refinement.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "collocation_mesh.hpp"
#include "multibody_controls.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/projected_rk4.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::optimal {

std::vector<double> interval_errors(const MultibodyProblem& problem, const MultibodyOptimum& optimum,
                                    int steps) {
  const std::size_t intervals = (optimum.states.size() - 1) / 2;
  const double L = problem.system.length_scale();
  std::vector<double> out;
  for (std::size_t k = 0; k < intervals; ++k) {
    const double t0 = optimum.time[2 * k], h = optimum.time[2 * k + 2] - t0, dt = h / steps;
    multibody::State state = optimum.states[2 * k];
    for (int n = 0; n < steps; ++n) {
      const double t = t0 + n * dt;
      multibody::ProjectedRk4 rk4(detail::system_with_controls(problem, control_at(optimum, t + 0.5 * dt)),
                                  dt);
      rk4.step(state);
    }
    const multibody::State& end = optimum.states[2 * k + 2];
    double error = 0.0;
    for (std::size_t i = 0; i < state.bodies.size(); ++i) {
      const multibody::BodyState& a = state.bodies[i];
      const multibody::BodyState& b = end.bodies[i];
      error = std::max({error, so3::angle_between(a.R_space_body, b.R_space_body),
                        (a.x_space - b.x_space).norm() / L, h * (a.omega_body - b.omega_body).norm(),
                        h * (a.v_space - b.v_space).norm() / L});
    }
    out.push_back(error);
  }
  return out;
}

MultibodyProblem with_refined_mesh(MultibodyProblem problem, const std::vector<double>& errors,
                                   double tolerance) {
  std::vector<double> mesh;
  for (std::size_t k = 0; k < errors.size(); ++k) {
    const double d = problem.mesh.empty() ? 1.0 / problem.intervals : problem.mesh[k];
    const int pieces = detail::refinement_pieces(errors[k], tolerance);
    mesh.insert(mesh.end(), static_cast<std::size_t>(pieces), d / pieces);
  }
  double sum = 0.0;
  for (const double d : mesh)
    sum += d;
  for (double& d : mesh)
    d /= sum;  // a change at round-off: validate asks for a sum of 1 to 1e-12
  problem.mesh = std::move(mesh);
  problem.intervals = static_cast<int>(problem.mesh.size());
  return problem;
}

MultibodyRefinement refine_multibody(MultibodyProblem problem, MultibodyOptions options, double tolerance,
                                     int max_rounds) {
  if (!(tolerance > 0.0) || max_rounds < 0) {
    throw InvalidInput(fmt::format(
        "optimal control refinement: got tolerance {} and max_rounds {}; expected a tolerance > 0 (rad) and "
        "max_rounds ≥ 0",
        tolerance, max_rounds));
  }
  validate(problem);
  MultibodyRefinement out;
  MultibodyOptimum previous;
  for (int round = 0;; ++round) {
    out.optimum = solve_multibody(problem, options);
    const std::vector<double> errors = interval_errors(problem, out.optimum);
    const double worst = *std::max_element(errors.begin(), errors.end());
    out.rounds.push_back(
        {problem.intervals, worst, out.optimum.cost, out.optimum.nlp_iterations, out.optimum.status});
    out.tolerance_met = out.optimum.converged && worst <= tolerance;
    if (out.tolerance_met || !out.optimum.converged || round == max_rounds) break;
    MultibodyProblem refined = with_refined_mesh(problem, errors, tolerance);
    if (refined.intervals > 2000) break;
    previous = out.optimum;
    problem = std::move(refined);
    options.warm_start = &previous;
  }
  out.problem = problem;
  return out;
}

}  // namespace poinsot::optimal
