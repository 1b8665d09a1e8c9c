// The transcription of a ReorientationProblem (collocation_nlp.hpp).
#include "collocation_nlp.hpp"

#include <string>
#include <utility>

#include "poinsot/core/error.hpp"

namespace poinsot::optimal::detail {

namespace {

CollocationTime single_body_time(const ReorientationProblem& problem, int phases) {
  if (!problem.free_final_time()) {
    if (phases != 1)
      throw InvalidInput("collocation phases: " + std::to_string(phases) +
                         " phases; expected one phase for a fixed final time");
    return CollocationTime::at(problem.final_time);
  }
  CollocationTime time;
  const auto P = static_cast<std::size_t>(phases);
  time.lower.assign(P, phases == 1 ? 0.5 * minimum_duration_bound(problem) : 0.0);
  time.upper.assign(P, kNoBound);
  return time;
}

CollocationObjective single_body_objective(const ReorientationProblem& problem) {
  switch (problem.objective) {
    case Objective::minimum_energy:
      return {0.0, 1.0};
    case Objective::minimum_time_regularised:
      return {1.0, problem.energy_weight};
    case Objective::minimum_time:
      return {1.0, 0.0};
  }
  return {};
}

CollocationPhases checked(CollocationPhases phases, std::size_t nodes) {
  const std::size_t P = phases.intervals.size();
  std::size_t expected = 0;
  for (const int n : phases.intervals)
    expected += static_cast<std::size_t>(n) + 1;
  if (P == 0 || nodes != expected || phases.torque_lower.size() != P || phases.torque_upper.size() != P)
    throw InvalidInput("collocation phases: " + std::to_string(P) + " phases with " + std::to_string(nodes) +
                       " mesh values; expected Σ(N_a + 1) values and bounds per phase");
  return phases;
}

}  // namespace

CollocationNlp::CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau)
    : model_(problem, {}),
      nlp_(model_, CollocationMesh::from_nodes(tau, {static_cast<int>(tau.size()) - 1}),
           model_.initial_state(), model_.final_rows(), model_.final_values(), single_body_time(problem, 1),
           single_body_objective(problem)) {}

CollocationNlp::CollocationNlp(const ReorientationProblem& problem, std::vector<double> tau,
                               CollocationPhases phases)
    : model_(problem, checked(std::move(phases), tau.size())),
      nlp_(model_, CollocationMesh::from_nodes(std::move(tau), model_.phases().intervals),
           model_.initial_state(), model_.final_rows(), model_.final_values(),
           single_body_time(problem, static_cast<int>(model_.phases().intervals.size())),
           single_body_objective(problem)) {}

}  // namespace poinsot::optimal::detail
