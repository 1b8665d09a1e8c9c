#pragma once
// The minimal-coordinate model's own forward dynamics, ν̇ = −M(q)⁻¹(c(q, ν) − B u), integrated by classical
// RK4: the oracle the tests compare with the multibody layer's projected RK4 (replay_controls), on the same
// steps with the same held controls.
#include <algorithm>

#include <Eigen/Dense>

#include "../../src/optimal/multibody_minimal_model.hpp"
#include "poinsot/multibody/state.hpp"
#include "poinsot/optimal/multibody_direct.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::optimal::testing {

/// The state at the end of `controls`' time span after `steps` equal RK4 steps of the minimal model from
/// p.initial_state, the controls held at their value at each step's midpoint (control_at), as
/// replay_controls holds them.
inline multibody::State integrate_minimal_model(const MultibodyProblem& p, const MultibodyOptimum& controls,
                                                int steps) {
  const detail::MultibodyMinimalModel model(p);
  Eigen::VectorXd y = model.state_vector(p.initial_state);
  const double dt = controls.time.back() / steps;
  for (int k = 0; k < steps; ++k) {
    const Eigen::VectorXd u = control_at(controls, (k + 0.5) * dt);
    const Eigen::VectorXd k1 = model.state_derivative(y, u);
    const Eigen::VectorXd k2 = model.state_derivative(y + 0.5 * dt * k1, u);
    const Eigen::VectorXd k3 = model.state_derivative(y + 0.5 * dt * k2, u);
    const Eigen::VectorXd k4 = model.state_derivative(y + dt * k3, u);
    y += dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
  }
  return model.state_of(y.data(), controls.time.back());
}

/// The largest difference between two states of the same system over its bodies: the attitude angle (rad),
/// ω (rad/s), the centre of mass (m) and its velocity (m/s), mixed as numbers.
inline double largest_state_difference(const multibody::State& a, const multibody::State& b) {
  double d = 0.0;
  for (std::size_t i = 0; i < a.bodies.size(); ++i) {
    d = std::max({d, so3::angle_between(a.bodies[i].R_space_body, b.bodies[i].R_space_body),
                  (a.bodies[i].omega_body - b.bodies[i].omega_body).norm(),
                  (a.bodies[i].x_space - b.bodies[i].x_space).norm(),
                  (a.bodies[i].v_space - b.bodies[i].v_space).norm()});
  }
  return d;
}

}  // namespace poinsot::optimal::testing
