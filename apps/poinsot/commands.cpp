// register_commands (commands.hpp): the sub-commands of the tool, in the order `poinsot --help` lists them.
#include "commands.hpp"

namespace poinsot::cli {

void register_commands(CLI::App& app) {
  register_version(app);
  register_completion(app);
  register_rotation(app);
  register_inertia(app);   // mass properties, principal axes, validity
  register_run(app);       // a scenario file, single-body or multibody
  register_lambda(app);    // the multipliers Λ and the constraint stress
  register_view(app);      // the 3-D page of a run
  register_optimize(app);  // optimal reorientation
  register_ensemble(app);  // Monte Carlo over bodies and initial conditions
}

}  // namespace poinsot::cli
