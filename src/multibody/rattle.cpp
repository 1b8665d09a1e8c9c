// RATTLE in rotation-matrix coordinates with a tree-order KKT solver (rattle.hpp, docs/multibody.md).
#include "poinsot/multibody/rattle.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {

using so3::hat;

struct Rattle::Impl {
  Impl(const System& s, double step, RattleOptions o) : system(s), h(step), options(o), solver(system) {
    const auto nb = static_cast<std::size_t>(system.body_count());
    const auto nj = static_cast<std::size_t>(system.joint_count());
    G_a.resize(nj);
    G_b.resize(nj);
    loads.resize(nb);
    u.resize(nb);
    w.resize(nb);
    Q.resize(nb);
    sigma.resize(nb);
    next.resize(nb);
    gen.resize(nb);
    rhs_body.resize(nb);
    const int rows = system.constraint_rows();
    nu = Eigen::VectorXd::Zero(rows);
    nu_previous = Eigen::VectorXd::Zero(rows);
    rhs_joint.resize(rows);
    factored_positions.resize(nb);
    length = system.length_scale();
    for (Multipliers* m : {&stage1, &stage2}) {
      m->Lambda_body.assign(nb, Mat3::Zero());
      m->joint_force_space.assign(nj, Vec3::Zero());
      m->joint_torque_space.assign(nj, Vec3::Zero());
    }
  }

  const BodyState& side(const std::vector<BodyState>& bodies, int index) const {
    return index == kWorld ? world_body_state() : bodies[static_cast<std::size_t>(index)];
  }

  // Jacobians at the positions of `bodies`, and the factorisation of the KKT matrix there.
  void factor_at(const std::vector<BodyState>& bodies) {
    for (std::size_t j = 0; j < G_a.size(); ++j) {
      const Joint& joint = system.joints()[j];
      joint_jacobians(joint, bodies[static_cast<std::size_t>(joint.body_a)], side(bodies, joint.body_b),
                      G_a[j], G_b[j]);
    }
    solver.factor(G_a, G_b);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      factored_positions[i] = {bodies[i].x_space, bodies[i].R_space_body};
    }
    factored = true;
  }

  bool factored_for(const std::vector<BodyState>& bodies) const {
    if (!factored) return false;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].x_space != factored_positions[i].first ||
          bodies[i].R_space_body != factored_positions[i].second) {
        return false;
      }
    }
    return true;
  }

  // gen[i] = Σ_j G_{j,i}ᵀ y_j (6-vector per body) for stacked multipliers y.
  void accumulate_generalized(const Eigen::VectorXd& y) {
    for (Vec6& g : gen)
      g.setZero();
    for (std::size_t j = 0; j < G_a.size(); ++j) {
      const Joint& joint = system.joints()[j];
      const int offset = solver.joint_offset(static_cast<int>(j));
      Vec6& ga = gen[static_cast<std::size_t>(joint.body_a)];
      if (joint.rows() == 3) {  // ball joints: fixed-size products
        const Vec3 seg = y.segment<3>(offset);
        ga.noalias() += G_a[j].topRows<3>().transpose() * seg;
        if (joint.body_b != kWorld) {
          gen[static_cast<std::size_t>(joint.body_b)].noalias() += G_b[j].topRows<3>().transpose() * seg;
        }
        continue;
      }
      const auto seg = y.segment(offset, joint.rows());
      ga.noalias() += G_a[j].transpose() * seg;
      if (joint.body_b != kWorld)
        gen[static_cast<std::size_t>(joint.body_b)].noalias() += G_b[j].transpose() * seg;
    }
  }

  // Joint reactions and Λ from stacked multipliers λ (N, N·m) at `bodies`; `Rdot_term[i]` = Rᵀ R̈ K estimate.
  void fill_multipliers(Multipliers& out, const std::vector<BodyState>& bodies, const Eigen::VectorXd& lam,
                        const std::vector<BodyLoads>& applied, const std::vector<Mat3>& rtrddk) {
    for (std::size_t i = 0; i < bodies.size(); ++i)
      phi[i] = applied[i].phi_body;
    for (std::size_t j = 0; j < G_a.size(); ++j) {
      const Joint& joint = system.joints()[j];
      const JointVector l = lam.segment(solver.joint_offset(static_cast<int>(j)), joint.rows());
      const JointLoads jl =
          joint_loads(joint, bodies[static_cast<std::size_t>(joint.body_a)], side(bodies, joint.body_b), l);
      out.joint_force_space[j] = jl.force_a_space;
      out.joint_torque_space[j] = jl.torque_a_space;
      phi[static_cast<std::size_t>(joint.body_a)] += jl.phi_a_body;
      if (joint.body_b != kWorld) phi[static_cast<std::size_t>(joint.body_b)] += jl.phi_b_body;
    }
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Mat3 L = rtrddk[i] - phi[i];
      out.Lambda_body[i] = 0.5 * (L + L.transpose());
    }
  }

  void step(State& state) {
    const auto nb = state.bodies.size();
    if (nb != static_cast<std::size_t>(system.body_count())) {
      throw InvalidInput(fmt::format("multibody: state has {} bodies; expected {}", nb, system.body_count()));
    }
    std::vector<BodyState>& q = state.bodies;
    if (!factored_for(q)) {  // a new trajectory: no history to warm-start from
      factor_at(q);
      nu.setZero();
      steps_taken = 0;
    }
    applied_loads(system, q, loads);
    const auto& bodies = system.bodies();

    // Position stage: simplified Newton on (u, w, ν), warm-started by extrapolating the last two steps' ν
    // (ν varies smoothly: the linear extrapolation is O(h³) off, which saves about one iteration).
    if (steps_taken >= 2) {
      rhs_joint = nu;
      nu = 2.0 * nu - nu_previous;
      nu_previous = rhs_joint;
    } else {
      nu_previous = nu;
    }
    accumulate_generalized(nu);
    for (std::size_t i = 0; i < nb; ++i) {
      const Body& b = bodies[i];
      const Vec3& om = q[i].omega_body;
      u[i] = q[i].v_space + (0.5 * h * loads[i].force_space + gen[i].head<3>()) / b.mass;
      w[i] = om + b.inertia_inverse * (0.5 * h * loads[i].torque_body + gen[i].tail<3>() -
                                       0.5 * h * om.cross(b.inertia * om));
    }
    const double tol = options.tolerance;
    iterations = 0;
    double previous_err_body = std::numeric_limits<double>::infinity();
    for (;;) {
      for (std::size_t i = 0; i < nb; ++i) {
        const Vec3 a = h * w[i];
        const double s2 = a.squaredNorm();
        if (!(s2 < 1.0)) {
          throw ComputationFailed(fmt::format(
              "multibody: at t = {} s body '{}' turns by h|ω| = {} rad in one step; expected < 1 (reduce dt)",
              state.time, bodies[i].name, std::sqrt(s2)));
        }
        const double c = std::sqrt(1.0 - s2);
        const Mat3 A = hat(a);
        Q[i] = Mat3::Identity() + A + A * A / (1.0 + c);
        sigma[i] = h / (1.0 + c);
        next[i].x_space = q[i].x_space + h * u[i];
        next[i].R_space_body = q[i].R_space_body * Q[i];
      }
      accumulate_generalized(nu);
      // Momentum residuals are measured relative to the sum of the magnitudes of their terms (so the test is
      // at round-off, whatever the size of the reactions): not relative to L/h, because a velocity error is
      // carried on by the next steps and would accumulate.
      double err_body = 0.0;
      for (std::size_t i = 0; i < nb; ++i) {
        const Body& b = bodies[i];
        const Vec3 Jw = b.inertia * w[i];
        const Vec3 Jom = b.inertia * q[i].omega_body;
        rhs_body[i].head<3>() =
            -(b.mass * (u[i] - q[i].v_space) - 0.5 * h * loads[i].force_space - gen[i].head<3>());
        rhs_body[i].tail<3>() =
            -(Jw + sigma[i] * w[i].cross(Jw) - Jom - 0.5 * h * loads[i].torque_body - gen[i].tail<3>());
        const double scale_u = b.mass * (u[i].norm() + q[i].v_space.norm()) +
                               0.5 * h * loads[i].force_space.norm() + gen[i].head<3>().norm() + 1e-300;
        const double scale_w =
            Jw.norm() + Jom.norm() + 0.5 * h * loads[i].torque_body.norm() + gen[i].tail<3>().norm() + 1e-300;
        err_body = std::max(
            {err_body, rhs_body[i].head<3>().norm() / scale_u, rhs_body[i].tail<3>().norm() / scale_w});
      }
      double err_joint = 0.0;
      for (std::size_t j = 0; j < G_a.size(); ++j) {
        const Joint& joint = system.joints()[j];
        const JointVector g =
            joint_value(joint, next[static_cast<std::size_t>(joint.body_a)], side(next, joint.body_b));
        err_joint = std::max(err_joint, g.head<3>().cwiseAbs().maxCoeff() / length);
        if (joint.perpendicular_count > 0)
          err_joint = std::max(err_joint, g.tail(joint.perpendicular_count).cwiseAbs().maxCoeff());
        rhs_joint.segment(solver.joint_offset(static_cast<int>(j)), joint.rows()) = -g / h;
      }
      if (err_body <= tol && err_joint <= tol) break;
      // Round-off floor: the positions have converged and the momentum residual, already tiny, stopped
      // decreasing (long chains carry large reactions whose sums cannot cancel to 1e-13).
      if (err_joint <= tol && err_body <= 1e3 * tol && err_body > 0.25 * previous_err_body) break;
      previous_err_body = err_body;
      if (++iterations > options.max_iterations) {
        throw ComputationFailed(
            fmt::format("multibody: at t = {} s the position stage did not converge in {} Newton iterations "
                        "(residual {:.3g} "
                        "in positions, {:.3g} in momenta; reduce dt)",
                        state.time, options.max_iterations, err_joint, err_body));
      }
      solver.solve(rhs_body, rhs_joint);
      for (std::size_t i = 0; i < nb; ++i) {
        u[i] += rhs_body[i].head<3>();
        w[i] += rhs_body[i].tail<3>();
      }
      nu -= rhs_joint;
    }

    // Multipliers of the position stage (at t_n, G at q_n): λ = 2ν/h; Λ from the symmetric part of the
    // R-equation, Rₙᵀ(V½ − Vₙ)K·2/h = ((Q − I)/h − j(ωₙ))K·2/h.
    lambda = (2.0 / h) * nu;
    for (std::size_t i = 0; i < nb; ++i) {
      RtRddK[i] = (2.0 / h) * ((Q[i] - Mat3::Identity()) / h - hat(q[i].omega_body)) * bodies[i].poinsot;
    }
    fill_multipliers(stage1, q, lambda, loads, RtRddK);

    // Velocity stage at q_{n+1}: dampers see the extrapolated velocities 2V½ − Vₙ.
    for (std::size_t i = 0; i < nb; ++i) {
      next[i].v_space = 2.0 * u[i] - q[i].v_space;
      next[i].omega_body = 2.0 * w[i] - q[i].omega_body;
    }
    factor_at(next);
    applied_loads(system, next, loads);
    for (std::size_t i = 0; i < nb; ++i) {
      const Body& b = bodies[i];
      const Vec3 Jw = b.inertia * w[i];
      rhs_body[i].head<3>() = b.mass * u[i] + 0.5 * h * loads[i].force_space;
      rhs_body[i].tail<3>() = Jw - sigma[i] * w[i].cross(Jw) + 0.5 * h * loads[i].torque_body;
    }
    rhs_joint.setZero();
    solver.solve(rhs_body, rhs_joint);
    lambda = (-2.0 / h) * rhs_joint;
    for (std::size_t i = 0; i < nb; ++i) {
      next[i].v_space = rhs_body[i].head<3>();
      next[i].omega_body = rhs_body[i].tail<3>();
      // R_{n+1}ᵀ(V_{n+1} − V½)K·2/h with R_{n+1}ᵀV½ = (I − Qᵀ)/h.
      RtRddK[i] = (2.0 / h) * (hat(next[i].omega_body) - (Mat3::Identity() - Q[i].transpose()) / h) *
                  bodies[i].poinsot;
    }
    fill_multipliers(stage2, next, lambda, loads, RtRddK);
    for (std::size_t i = 0; i < nb; ++i) {
      q[i] = next[i];
      factored_positions[i] = {q[i].x_space, q[i].R_space_body};
    }
    state.time += h;
    ++steps_taken;
  }

  System system;
  double h;
  RattleOptions options;
  KktSolver solver;
  double length = 1.0;
  std::vector<JointJacobian> G_a, G_b;
  std::vector<BodyLoads> loads;
  std::vector<Vec3> u, w;
  std::vector<Mat3> Q;
  std::vector<double> sigma;
  std::vector<BodyState> next;
  std::vector<Vec6> gen, rhs_body;
  Eigen::VectorXd nu, nu_previous, rhs_joint, lambda;
  long steps_taken = 0;
  std::vector<std::pair<Vec3, Mat3>> factored_positions;
  bool factored = false;
  int iterations = 0;
  std::vector<Mat3> phi = std::vector<Mat3>(static_cast<std::size_t>(system.body_count()));
  std::vector<Mat3> RtRddK = std::vector<Mat3>(static_cast<std::size_t>(system.body_count()));
  Multipliers stage1, stage2;
};

Rattle::Rattle(const System& system, double dt, RattleOptions options) {
  require_positive("multibody: time step dt", dt, "s");
  require_positive("multibody: Newton tolerance", options.tolerance);
  if (options.max_iterations < 1) {
    throw InvalidInput(fmt::format("multibody: max_iterations {} must be >= 1", options.max_iterations));
  }
  impl_ = std::make_unique<Impl>(system, dt, options);
}
Rattle::~Rattle() = default;
Rattle::Rattle(Rattle&&) noexcept = default;
Rattle& Rattle::operator=(Rattle&&) noexcept = default;

void Rattle::step(State& state) {
  impl_->step(state);
}
double Rattle::dt() const {
  return impl_->h;
}
const System& Rattle::system() const {
  return impl_->system;
}
bool Rattle::uses_tree_solver() const {
  return impl_->solver.is_tree();
}
int Rattle::last_iterations() const {
  return impl_->iterations;
}
const Multipliers& Rattle::position_stage() const {
  return impl_->stage1;
}
const Multipliers& Rattle::velocity_stage() const {
  return impl_->stage2;
}

}  // namespace poinsot::multibody
