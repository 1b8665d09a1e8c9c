// The tennis racket from C++: Brody's measured moments, spun mostly about the intermediate axis. Runs the
// symplectic RATTLE method and the exact solution side by side, counts the flips against the closed-form
// interval 2K(k)/ω_p, and prints how far the integrated orientation is from the exact one at the end.
//
// Build: cmake --build --preset release --target example_tennis_racket
// Run:   ./build/release/examples/example_tennis_racket
#include <cstdio>

#include "poinsot/dynamics/exact_free_body.hpp"
#include "poinsot/dynamics/free_body_theory.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/so3/distance.hpp"

int main() {
  using namespace poinsot;
  using namespace poinsot::dynamics;

  const RigidBody racket = RigidBody::from_principal_moments(Vec3(0.00121, 0.01638, 0.01748));  // kg·m²
  State initial;
  initial.omega_body = Vec3(0.05, 6.2832, 0.05);  // rad/s, about one turn a second about the handle's normal

  const FreeBodyTheory theory = free_body_theory(racket, initial.omega_body);
  std::printf("flip interval 2K(k)/w_p = %.9f s, period 4K(k)/w_p = %.9f s (k'^2 = %.3g)\n",
              theory.flip_interval(), theory.omega_period(), theory.modulus_complement2);

  IntegratorOptions options;
  options.dt = 1e-3;  // s
  SimulationOptions run;
  run.t_end = 20.0;      // s
  run.sample_dt = 0.01;  // s
  auto rattle = make_integrator("rattle", racket, TorqueModel::none(), options);
  const SimulationResult result = simulate(racket, TorqueModel::none(), initial, *rattle, run);

  std::printf(
      "rattle, dt = %g s: %zu flips, %lld steps, worst relative energy error %.2e, |L| %.2e, "
      "|R^T R - I| %.2e\n",
      options.dt, result.flip_times.size(), result.steps, result.errors.energy_rel_max,
      result.errors.L_norm_rel_max, result.errors.orthogonality_max);
  for (std::size_t i = 1; i < result.flip_times.size(); ++i) {
    std::printf("  flip %zu at t = %.6f s, interval %.6f s\n", i + 1, result.flip_times[i],
                result.flip_times[i] - result.flip_times[i - 1]);
  }
  const ExactFreeBody exact(racket, initial);
  const State reference = exact.state_at(run.t_end);
  std::printf("orientation error of rattle at t = %g s: %.3e rad\n", run.t_end,
              so3::angle_between(result.final_state.R_space_body, reference.R_space_body));
  return 0;
}
