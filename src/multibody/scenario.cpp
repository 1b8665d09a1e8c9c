// Projection of a scenario's initial velocities onto the joints (scenario.hpp).
#include "poinsot/multibody/scenario.hpp"

#include <vector>

#include "poinsot/multibody/kkt_solver.hpp"

namespace poinsot::multibody {

void project_velocities(const System& system, State& state) {
  if (system.joint_count() == 0) return;
  KktSolver solver(system);
  solver.factor_at(state.bodies);
  std::vector<Vec6> body(state.bodies.size());
  for (std::size_t i = 0; i < body.size(); ++i) {
    const Body& b = system.bodies()[i];
    body[i] << b.mass * state.bodies[i].v_space, b.inertia * state.bodies[i].omega_body;
  }
  Eigen::VectorXd joint = Eigen::VectorXd::Zero(system.constraint_rows());
  solver.solve(body, joint);  // [M Gᵀ; G 0][v; y] = [M v₀; 0]
  for (std::size_t i = 0; i < body.size(); ++i) {
    state.bodies[i].v_space = body[i].head<3>();
    state.bodies[i].omega_body = body[i].tail<3>();
  }
}

}  // namespace poinsot::multibody
