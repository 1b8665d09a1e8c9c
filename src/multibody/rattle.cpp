// RATTLE in rotation-matrix coordinates with a tree-order KKT solver (rattle.hpp, docs/multibody_theory.md
// §2).
#include "poinsot/multibody/rattle.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "acceleration_multipliers.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::multibody {

using so3::hat;

namespace {

// A relative momentum residual this small counts as zero: where the residual keeps falling geometrically
// instead of reaching zero (a body whose w × Jw is far below its terms, as on a slider), what it leaves moves
// the energy by ε²·h|ω| of the terms a step, ~1e-25 over 10¹⁰ steps. Anything a step's rounding leaves (an
// ulp of w moves the gyroscopic term by ~ε·h|ω|) is far above it, so the iteration still runs to the
// floating-point fixed point.
constexpr double kMomentumResidualNegligible =
    std::numeric_limits<double>::epsilon() * std::numeric_limits<double>::epsilon();

// Largest absolute entry: the residual norms of the Newton test (no square root on the hot path).
template <class V>
double max_abs(const V& v) {
  return v.cwiseAbs().maxCoeff();
}

}  // namespace

struct Rattle::Impl {
  // One RATTLE substep of a composition: its size and the multipliers ν of the three previous steps' same
  // substep. ν varies smoothly from step to step: its quadratic extrapolation is O(h³) off (relative), which
  // starts Newton 10-100 times closer than the linear one on the 64-link chain and saves a tenth of the
  // iterations.
  //
  // Likewise the Newton correction of each body's w over its explicit start (below), d = w − w₀, of the three
  // previous steps: extrapolated, it starts the free body's Newton O(h|ω|) closer to its fixed point, one
  // iteration fewer.
  struct Substep {
    double h = 0.0;
    Eigen::VectorXd nu, nu_previous, nu_before;
    std::vector<Vec3> dw, dw_previous, dw_before;
  };

  Impl(const System& s, double step, RattleOptions o) : system(s), h(step), options(o), solver(system) {
    const auto nb = static_cast<std::size_t>(system.body_count());
    const auto nj = static_cast<std::size_t>(system.joint_count());
    G_a.resize(nj);
    G_b.resize(nj);
    loads.resize(nb);
    loads_start.resize(nb);
    u.resize(nb);
    w.resize(nb);
    w_start.resize(nb);
    Jw.resize(nb);
    gyro_solved.resize(nb);
    scale_w.resize(nb);
    Q_minus_I.resize(nb);
    Q_minus_I_first.resize(nb);
    sigma.resize(nb);
    next.resize(nb);
    start.resize(nb);
    gen.resize(nb);
    rhs_body.resize(nb);
    momentum.resize(nb);
    momentum_step.resize(nb);
    momentum_of.resize(nb);
    phi.resize(nb);
    RtRddK.resize(nb);
    const int rows = system.constraint_rows();
    // Order 4: the symmetric triple jump of Yoshida (1990) / Suzuki (1990), γ₁ = 1/(2 − 2^{1/3}),
    // γ₂ = 1 − 2γ₁ (< 0): the composition of a symmetric second-order method with these steps is of order 4
    // and, each substep being symplectic and momentum-conserving, so is the whole step.
    std::vector<double> fractions{1.0};
    if (options.order == 4) {
      const double g1 = 1.0 / (2.0 - std::cbrt(2.0));
      fractions = {g1, 1.0 - 2.0 * g1, g1};
    }
    for (double f : fractions) {
      substeps.push_back({f * h, Eigen::VectorXd::Zero(rows), Eigen::VectorXd::Zero(rows),
                          Eigen::VectorXd::Zero(rows), std::vector<Vec3>(nb, Vec3::Zero()),
                          std::vector<Vec3>(nb, Vec3::Zero()), std::vector<Vec3>(nb, Vec3::Zero())});
    }
    rhs_joint.resize(rows);
    extrapolated.resize(rows);
    lambda_first.resize(rows);
    lambda_last.resize(rows);
    factored_positions.resize(nb);
    length = system.length_scale();
    for (Multipliers* m : {&stage1, &stage2}) {
      m->Lambda_body.assign(nb, Mat3::Zero());
      m->joint_force_space.assign(nj, Vec3::Zero());
      m->joint_torque_space.assign(nj, Vec3::Zero());
    }
  }

  // Jacobians at the positions of `bodies`, and the factorisation of the KKT matrix there.
  void factor_at(const std::vector<BodyState>& bodies) {
    for (std::size_t j = 0; j < G_a.size(); ++j) {
      const Joint& joint = system.joints()[j];
      joint_jacobians(joint, bodies[static_cast<std::size_t>(joint.body_a)], side_state(bodies, joint.body_b),
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

  // Whether `momentum` is that of the velocities of `bodies` (the state the last step returned).
  bool momentum_belongs_to(const std::vector<BodyState>& bodies) const {
    if (!momentum_valid) return false;
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      if (bodies[i].v_space != momentum_of[i].first || bodies[i].omega_body != momentum_of[i].second) {
        return false;
      }
    }
    return true;
  }

  // gen[i] = Σ_j G_{j,i}ᵀ y_j (6-vector per body) for stacked multipliers y, with the Jacobians factor_at
  // computed.
  void accumulate_generalized(const Eigen::VectorXd& y) {
    for (Vec6& g : gen)
      g.setZero();
    for (std::size_t j = 0; j < G_a.size(); ++j) {
      const Joint& joint = system.joints()[j];
      Vec6* gb = joint.body_b == kWorld ? nullptr : &gen[static_cast<std::size_t>(joint.body_b)];
      add_joint_generalized_forces(joint, G_a[j], G_b[j],
                                   y.segment(solver.joint_offset(static_cast<int>(j)), joint.rows()),
                                   gen[static_cast<std::size_t>(joint.body_a)], gb);
    }
  }

  // Joint reactions and Λ from stacked multipliers λ (N, N·m) at `bodies`; `rtrddk[i]` = Rᵀ R̈ K estimate.
  void fill_multipliers(Multipliers& out, const std::vector<BodyState>& bodies, const Eigen::VectorXd& lam,
                        const std::vector<BodyLoads>& applied, const std::vector<Mat3>& rtrddk) {
    for (std::size_t i = 0; i < bodies.size(); ++i)
      phi[i] = applied[i].phi_body;
    detail::add_joint_loads(
        system, bodies,
        [&](int j, const Joint& joint) -> JointVector {
          return lam.segment(solver.joint_offset(j), joint.rows());
        },
        out, phi);
    for (std::size_t i = 0; i < bodies.size(); ++i) {
      const Mat3 L = rtrddk[i] - phi[i];
      out.Lambda_body[i] = 0.5 * (L + L.transpose());
    }
  }

  // The position stage's multipliers (at tₙ, G at qₙ, first substep of size h₀): λ = 2ν/h₀ and Λ from the
  // symmetric part of the R-equation, Rₙᵀ(V½ − Vₙ)K·2/h₀ = ((Q − I)/h₀ − j(ωₙ))K·2/h₀.
  const Multipliers& position_stage() {
    if (!stage1_ready && steps_taken > 0) {
      const double h0 = substeps.front().h;
      for (std::size_t i = 0; i < start.size(); ++i) {
        RtRddK[i] =
            (2.0 / h0) * (Q_minus_I_first[i] / h0 - hat(start[i].omega_body)) * system.bodies()[i].poinsot;
      }
      fill_multipliers(stage1, start, lambda_first, loads_start, RtRddK);
    }
    stage1_ready = true;
    return stage1;
  }

  // The velocity stage's multipliers (at tₙ₊₁, last substep of size h₁): λ = 2μ/h₁ and
  // R_{n+1}ᵀ(V_{n+1} − V½)K·2/h₁ with R_{n+1}ᵀV½ = (I − Qᵀ)/h₁.
  const Multipliers& velocity_stage() {
    if (!stage2_ready && steps_taken > 0) {
      const double h1 = substeps.back().h;
      for (std::size_t i = 0; i < next.size(); ++i) {
        RtRddK[i] = (2.0 / h1) * (hat(next[i].omega_body) + Q_minus_I[i].transpose() / h1) *
                    system.bodies()[i].poinsot;
      }
      fill_multipliers(stage2, next, lambda_last, loads, RtRddK);
    }
    stage2_ready = true;
    return stage2;
  }

  // Newton residuals of the position stage at the current (u, w, ν): fills next[] positions, Q, σ, rhs_body
  // and rhs_joint (with the sign of a Newton right-hand side); returns {momentum error, joint error}.
  //
  // `full` evaluates the momentum rows from their terms. After a Newton update it is not needed: those rows
  // are linear in (u, w, ν) except for the gyroscopic term σ w × Jw, and the KKT solve makes the linear part
  // of the new residual vanish (M Δx + Gᵀ Δy = r), so the new residual is exactly the change of the
  // gyroscopic term, zero in the translation rows. This saves G(qₙ)ᵀν and the load terms in every iteration.
  std::pair<double, double> position_residuals(const std::vector<BodyState>& q, double hs, double time,
                                               bool full) {
    const auto& bodies = system.bodies();
    const std::size_t nb = q.size();
    if (full) accumulate_generalized(nu());  // G(qₙ)ᵀν: independent of the new positions
    // Momentum residuals are measured relative to the sum of the magnitudes of their terms (so the test is at
    // round-off, whatever the size of the reactions): not relative to L/h, because a velocity error is
    // carried on by the next steps and would accumulate.
    double err_body = 0.0;
    for (std::size_t i = 0; i < nb; ++i) {
      const Vec3 a = hs * w[i];
      const double s2 = a.squaredNorm();
      if (!(s2 < 1.0)) {
        throw ComputationFailed(fmt::format(
            "multibody: at t = {} s body '{}' turns by h|ω| = {} rad in one step; expected < 1 (reduce dt)",
            time, bodies[i].name, std::sqrt(s2)));
      }
      // Q = I + j(a) + j(a)²/(1 + c) with j(a)² = a aᵀ − |a|² I, kept as Q − I and applied as the increment
      // R + R (Q − I): the identity never meets the small terms, so that only the sum rounds. Rounded into
      // Q, the 1 (or c = 1 − |a|²/(1 + c)) would make nearly the same rounding step after step and RᵀR − I,
      // the energy and the momenta drift linearly instead of random-walking (Brouwer's law).
      const double c = std::sqrt(1.0 - s2);
      const double inv = 1.0 / (1.0 + c);
      Mat3& A = Q_minus_I[i];
      A.noalias() = inv * a * a.transpose();
      A(0, 0) -= inv * s2;
      A(1, 1) -= inv * s2;
      A(2, 2) -= inv * s2;
      A(1, 0) += a.z();
      A(0, 1) -= a.z();
      A(0, 2) += a.y();
      A(2, 0) -= a.y();
      A(2, 1) += a.x();
      A(1, 2) -= a.x();
      sigma[i] = hs * inv;
      next[i].x_space = q[i].x_space + hs * u[i];
      next[i].R_space_body.noalias() = q[i].R_space_body * A;
      next[i].R_space_body += q[i].R_space_body;

      const Body& b = bodies[i];
      Jw[i].noalias() = b.inertia * w[i];
      const Vec3 gyro = sigma[i] * w[i].cross(Jw[i]);
      if (!full) {
        rhs_body[i].head<3>().setZero();
        rhs_body[i].tail<3>() = gyro_solved[i] - gyro;
        gyro_solved[i] = gyro;
        // The terms' magnitude as in the full evaluation, with G(qₙ)ᵀν's part carried by the first evaluation
        // (the reaction moves Jw by about as much, so the scale follows it when it started near zero).
        const double scale =
            std::max(scale_w[i], max_abs(Jw[i]) + max_abs(gyro) + max_abs(momentum[i].tail<3>()));
        err_body = std::max(err_body, max_abs(rhs_body[i].tail<3>()) / scale);
        continue;
      }
      const Vec3 f_half = 0.5 * hs * loads[i].force_space;
      const Vec3 tau_half = 0.5 * hs * loads[i].torque_body;
      const Vec6& g = gen[i];
      const Vec3 p_n = momentum[i].head<3>();
      rhs_body[i].head<3>() = p_n + f_half + g.head<3>() - b.mass * u[i];
      rhs_body[i].tail<3>() = momentum[i].tail<3>() + tau_half + g.tail<3>() - Jw[i] - gyro;
      const double scale_u =
          b.mass * max_abs(u[i]) + max_abs(p_n) + max_abs(f_half) + max_abs(g.head<3>()) + 1e-300;
      scale_w[i] = max_abs(Jw[i]) + max_abs(gyro) + max_abs(momentum[i].tail<3>()) + max_abs(tau_half) +
                   max_abs(g.tail<3>()) + 1e-300;
      gyro_solved[i] = gyro;
      err_body = std::max(err_body, std::max(max_abs(rhs_body[i].head<3>()) / scale_u,
                                             max_abs(rhs_body[i].tail<3>()) / scale_w[i]));
    }
    double err_joint = 0.0;
    const double minus_inv_h = -1.0 / hs;
    for (std::size_t j = 0; j < G_a.size(); ++j) {
      const Joint& joint = system.joints()[j];
      const double err = scaled_joint_value(joint, next[static_cast<std::size_t>(joint.body_a)],
                                            side_state(next, joint.body_b), minus_inv_h, length,
                                            rhs_joint.data() + solver.joint_offset(static_cast<int>(j)));
      err_joint = std::max(err_joint, err);
    }
    return {err_body, err_joint};
  }

  Eigen::VectorXd& nu() { return substeps[current].nu; }

  // One RATTLE step of size hs from q (factored at q) to q (factored at the new positions).
  void rattle_substep(State& state, Substep& sub, bool first, bool last) {
    std::vector<BodyState>& q = state.bodies;
    const auto nb = q.size();
    const double hs = sub.h;
    const auto& bodies = system.bodies();
    applied_loads(system, q, loads);  // at qₙ with vₙ (dampers)
    if (first) loads_start = loads;
    if (steps_taken >= 3) {
      extrapolated = 3.0 * sub.nu - 3.0 * sub.nu_previous + sub.nu_before;
      sub.nu_before = sub.nu_previous;
      sub.nu_previous = sub.nu;
      sub.nu = extrapolated;
    } else if (steps_taken >= 2) {
      extrapolated = 2.0 * sub.nu - sub.nu_previous;
      sub.nu_before = sub.nu_previous;
      sub.nu_previous = sub.nu;
      sub.nu = extrapolated;
    } else {
      sub.nu_before = sub.nu_previous;
      sub.nu_previous = sub.nu;
    }
    // Position stage: simplified Newton on (u, w, ν) with the KKT matrix at qₙ.
    accumulate_generalized(sub.nu);
    for (std::size_t i = 0; i < nb; ++i) {
      const Body& b = bodies[i];
      const Vec3& om = q[i].omega_body;
      u[i] = q[i].v_space + (0.5 * hs * loads[i].force_space + gen[i].head<3>()) / b.mass;
      w[i] = om + b.inertia_inverse * (0.5 * hs * loads[i].torque_body + gen[i].tail<3>() -
                                       0.5 * hs * om.cross(momentum[i].tail<3>()));
      w_start[i] = w[i];
      if (steps_taken >= 3) {
        w[i] += 3.0 * sub.dw[i] - 3.0 * sub.dw_previous[i] + sub.dw_before[i];
      } else if (steps_taken >= 2) {
        w[i] += 2.0 * sub.dw[i] - sub.dw_previous[i];
      }
    }
    const double tol = options.tolerance;
    int its = 0;
    double previous_err_body = std::numeric_limits<double>::infinity();
    for (;;) {
      const auto [err_body, err_joint] = position_residuals(q, hs, state.time, its == 0);
      // The momentum rows are solved to their floating-point fixed point, not only to the tolerance: the
      // simplified Newton contracts with a steady ratio and sign from one step to the next, so a residual
      // left unsolved is nearly the same error every step, and the velocity stage turns it into a drift of
      // the momenta and the energy (Brouwer's law needs the rounding alone). Converged once the positions are
      // and the momentum residual is zero (the last update left the gyroscopic term unchanged: w no longer
      // moves; or below kMomentumResidualNegligible), or, already tiny, stopped falling: long chains carry
      // large reactions whose sums cannot cancel below ~1e-13. Stopping at a residual of ε of the terms
      // instead (a few ulps of Π, h|ω| times smaller in the energy) left the free body's energy drifting by
      // ~5e-20 a step (at 4ε by more): its signed mean over 100 members was +244 ± 34 ε after 10⁶ steps of 1
      // ms, −52 ± 34 ε now (bench/brouwer_growth --signed; docs/measurements/integrators.md).
      const bool falling = err_body <= 0.25 * previous_err_body;
      if (err_joint <= tol &&
          (err_body <= kMomentumResidualNegligible || (err_body <= 1e3 * tol && !falling)))
        break;
      previous_err_body = err_body;
      if (++its > options.max_iterations) {
        throw ComputationFailed(fmt::format(
            "multibody: at t = {} s the position stage did not converge in {} Newton iterations (residual "
            "{:.3g} in positions, {:.3g} in momenta; reduce dt)",
            state.time, options.max_iterations, err_joint, err_body));
      }
      solver.solve(rhs_body, rhs_joint);
      for (std::size_t i = 0; i < nb; ++i) {
        u[i] += rhs_body[i].head<3>();
        w[i] += rhs_body[i].tail<3>();
      }
      sub.nu -= rhs_joint;
    }
    iterations += its;
    std::swap(sub.dw_before, sub.dw_previous);
    std::swap(sub.dw_previous, sub.dw);
    for (std::size_t i = 0; i < nb; ++i)
      sub.dw[i] = w[i] - w_start[i];
    // The momenta at t_{n+1} are carried as increments of those at tₙ (below): the first half of the
    // increment, ½h·(f, τ)ₙ + G(qₙ)ᵀν − 2σ w × Jw, with G still at qₙ. Jw + σ w × Jw = Jωₙ + ½hτₙ + G(qₙ)ᵀν
    // holds only to the Newton residual; computed as Jw − σ w × Jw, the new momentum would carry that
    // residual (not a random rounding: the last, lost Newton increments have a steady sign), where the
    // increment form meets it only through its product with h|ω| (Hairer, McLachlan & Razakarivony 2008).
    accumulate_generalized(sub.nu);
    for (std::size_t i = 0; i < nb; ++i) {
      momentum_step[i].head<3>() = 0.5 * hs * loads[i].force_space + gen[i].head<3>();
      momentum_step[i].tail<3>() = 0.5 * hs * loads[i].torque_body + gen[i].tail<3>() - 2.0 * gyro_solved[i];
    }
    if (first) {  // what position_stage() needs, computed only when asked for
      lambda_first = (2.0 / hs) * sub.nu;
      Q_minus_I_first = Q_minus_I;
    }

    // Velocity stage at q_{n+1}: dampers see the extrapolated velocities 2V½ − Vₙ.
    for (std::size_t i = 0; i < nb; ++i) {
      next[i].v_space = 2.0 * u[i] - q[i].v_space;
      next[i].omega_body = 2.0 * w[i] - q[i].omega_body;
    }
    factor_at(next);
    applied_loads(system, next, loads);
    for (std::size_t i = 0; i < nb; ++i) {
      const Body& b = bodies[i];
      rhs_body[i].head<3>() = b.mass * u[i] + 0.5 * hs * loads[i].force_space;
      rhs_body[i].tail<3>() = Jw[i] - gyro_solved[i] + 0.5 * hs * loads[i].torque_body;
    }
    rhs_joint.setZero();
    solver.solve(rhs_body, rhs_joint);
    if (last) lambda_last = (-2.0 / hs) * rhs_joint;
    // M v_{n+1} = M V½ + ½h·(f, τ)_{n+1} − G(q_{n+1})ᵀy: the second half of the increment. The increment is
    // summed first and added to the momenta once, so that only that sum rounds; the velocities are the
    // solve's, the momenta never pass through the rounded J⁻¹ and back (a fixed relative error of a few
    // ulps per step, ε/4 on a moment of 3 kg·m², made |L| and the energy drift linearly).
    accumulate_generalized(rhs_joint);
    for (std::size_t i = 0; i < nb; ++i) {
      next[i].v_space = rhs_body[i].head<3>();
      next[i].omega_body = rhs_body[i].tail<3>();
      momentum_step[i].head<3>() += 0.5 * hs * loads[i].force_space - gen[i].head<3>();
      momentum_step[i].tail<3>() += 0.5 * hs * loads[i].torque_body - gen[i].tail<3>();
      momentum[i] += momentum_step[i];
    }
    std::copy(next.begin(), next.end(), q.begin());
    state.time += hs;
  }

  void step(State& state) {
    check_body_count(system, state);
    const auto nb = state.bodies.size();
    if (!factored_for(state.bodies)) {  // a new trajectory: no history to warm-start from
      factor_at(state.bodies);
      for (Substep& s : substeps)
        s.nu.setZero();
      steps_taken = 0;
      momentum_valid = false;
    }
    // The momenta (M v per body: m v_space, J ω_body) are carried from the last step when the state is the
    // one it returned; otherwise (a new trajectory, a state changed by the caller) computed from the state.
    if (!momentum_belongs_to(state.bodies)) {
      for (std::size_t i = 0; i < nb; ++i) {
        const Body& body = system.bodies()[i];
        momentum[i].head<3>() = body.mass * state.bodies[i].v_space;
        momentum[i].tail<3>().noalias() = body.inertia * state.bodies[i].omega_body;
      }
    }
    const double t0 = state.time;
    start = state.bodies;
    iterations = 0;
    try {
      for (std::size_t k = 0; k < substeps.size(); ++k) {
        current = k;
        rattle_substep(state, substeps[k], k == 0, k + 1 == substeps.size());
      }
    } catch (const ComputationFailed&) {  // leave the state as it was before the step
      std::copy(start.begin(), start.end(), state.bodies.begin());
      state.time = t0;
      factored = false;
      momentum_valid = false;
      steps_taken = 0;  // no multipliers from a failed step
      for (Multipliers* m : {&stage1, &stage2}) {
        std::fill(m->Lambda_body.begin(), m->Lambda_body.end(), Mat3::Zero());
        std::fill(m->joint_force_space.begin(), m->joint_force_space.end(), Vec3::Zero());
        std::fill(m->joint_torque_space.begin(), m->joint_torque_space.end(), Vec3::Zero());
      }
      stage1_ready = stage2_ready = true;
      throw;
    }
    // The substeps' sizes add up to h only to round-off: land the time exactly on t₀ + h.
    state.time = t0 + h;
    for (std::size_t i = 0; i < nb; ++i)
      momentum_of[i] = {state.bodies[i].v_space, state.bodies[i].omega_body};
    momentum_valid = true;
    ++steps_taken;
    stage1_ready = stage2_ready = false;
  }

  System system;
  double h;
  RattleOptions options;
  KktSolver solver;
  std::vector<Substep> substeps;
  std::size_t current = 0;
  double length = 1.0;
  std::vector<JointJacobian> G_a, G_b;
  std::vector<BodyLoads> loads, loads_start;
  std::vector<Vec3> u, w, Jw;
  std::vector<Vec3> w_start;      // the explicit start of w's Newton iteration in the current substep
  std::vector<Vec3> gyro_solved;  // σ w × Jw in the residual last evaluated (at the final w once converged)
  std::vector<double> scale_w;    // magnitude of the terms of each body's rotation rows, N·m·s
  std::vector<Mat3> Q_minus_I, Q_minus_I_first;  // the relative rotations Q of the substeps, less I
  std::vector<double> sigma;
  std::vector<BodyState> next, start;
  std::vector<Vec6> gen, rhs_body;
  std::vector<Vec6> momentum;       // M v per body (m v_space, J ω_body), carried from step to step
  std::vector<Vec6> momentum_step;  // its increment over the current substep
  std::vector<std::pair<Vec3, Vec3>> momentum_of;  // the velocities (v_space, ω_body) `momentum` belongs to
  bool momentum_valid = false;
  Eigen::VectorXd rhs_joint, extrapolated, lambda_first, lambda_last;
  long steps_taken = 0;
  std::vector<std::pair<Vec3, Mat3>> factored_positions;
  bool factored = false;
  bool stage1_ready = false, stage2_ready = false;
  int iterations = 0;
  std::vector<Mat3> phi, RtRddK;
  Multipliers stage1, stage2;
};

Rattle::Rattle(const System& system, double dt, RattleOptions options) {
  require_positive("multibody: time step dt", dt, "s");
  require_positive("multibody: Newton tolerance", options.tolerance);
  if (options.max_iterations < 1) {
    throw InvalidInput(fmt::format("multibody: max_iterations {} must be >= 1", options.max_iterations));
  }
  if (options.order != 2 && options.order != 4) {
    throw InvalidInput(fmt::format("multibody: order {} is not available; expected 2 or 4", options.order));
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
int Rattle::order() const {
  return impl_->options.order;
}
const System& Rattle::system() const {
  return impl_->system;
}
bool Rattle::uses_tree_solver() const {
  return impl_->solver.is_tree();
}
KktMethod Rattle::kkt_method() const {
  return impl_->solver.method();
}
int Rattle::last_iterations() const {
  return impl_->iterations;
}
const Multipliers& Rattle::position_stage() const {
  return impl_->position_stage();
}
const Multipliers& Rattle::velocity_stage() const {
  return impl_->velocity_stage();
}

}  // namespace poinsot::multibody
