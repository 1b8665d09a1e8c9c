// Exact multipliers of the continuous equations at a state (multipliers.hpp).
#include "poinsot/multibody/multipliers.hpp"

#include "acceleration_multipliers.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/kkt_solver.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {

namespace detail {

void acceleration_rhs(const System& system, const std::vector<BodyState>& bodies, const KktSolver& solver,
                      std::vector<BodyLoads>& loads, std::vector<Vec6>& body, Eigen::VectorXd& joint) {
  applied_loads(system, bodies, loads);
  body.resize(bodies.size());
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const Vec3& om = bodies[i].omega_body;
    body[i].head<3>() = loads[i].force_space;
    body[i].tail<3>() = loads[i].torque_body - om.cross(system.bodies()[i].inertia * om);
  }
  joint.resize(system.constraint_rows());
  for (std::size_t j = 0; j < system.joints().size(); ++j) {
    const Joint& jt = system.joints()[j];
    joint.segment(solver.joint_offset(static_cast<int>(j)), jt.rows()) =
        -joint_bias(jt, side_state(bodies, jt.body_a), side_state(bodies, jt.body_b));  // G a = −γ
  }
}

ExactMultipliers multipliers_from_accelerations(const System& system, const std::vector<BodyState>& bodies,
                                                const std::vector<BodyLoads>& loads,
                                                const std::vector<Vec6>& accelerations,
                                                const Eigen::VectorXd& minus_lambda,
                                                const KktSolver& solver) {
  const auto nb = static_cast<std::size_t>(system.body_count());
  const auto nj = static_cast<std::size_t>(system.joint_count());
  ExactMultipliers out;
  out.acceleration_space.resize(nb);
  out.omega_dot_body.resize(nb);
  out.Lambda_body.resize(nb);
  out.joint_force_space.resize(nj);
  out.joint_torque_space.resize(nj);
  std::vector<Mat3> phi(nb);
  for (std::size_t i = 0; i < nb; ++i) {
    out.acceleration_space[i] = accelerations[i].head<3>();
    out.omega_dot_body[i] = accelerations[i].tail<3>();
    phi[i] = loads[i].phi_body;
  }
  add_joint_loads(
      system, bodies,
      [&](int j, const Joint& joint) -> JointVector {
        return -minus_lambda.segment(solver.joint_offset(j), joint.rows());
      },
      out, phi);
  for (std::size_t i = 0; i < nb; ++i) {
    const Mat3 W = so3::hat(bodies[i].omega_body);
    const Mat3 L = (W * W + so3::hat(out.omega_dot_body[i])) * system.bodies()[i].poinsot - phi[i];
    out.Lambda_body[i] = 0.5 * (L + L.transpose());
  }
  return out;
}

}  // namespace detail

ExactMultipliers exact_multipliers(const System& system, const State& state) {
  KktSolver solver(system);
  solver.factor_at(state.bodies);
  std::vector<BodyLoads> loads;
  std::vector<Vec6> body_rhs;
  Eigen::VectorXd joint_rhs;
  detail::acceleration_rhs(system, state.bodies, solver, loads, body_rhs, joint_rhs);
  solver.solve(body_rhs, joint_rhs);  // [M Gᵀ; G 0][a; −λ] = [F; −γ]
  return detail::multipliers_from_accelerations(system, state.bodies, loads, body_rhs, joint_rhs, solver);
}

}  // namespace poinsot::multibody
