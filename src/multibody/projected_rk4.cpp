// Classical RK4 on the index-1 multibody equations, projected onto the constraints (projected_rk4.hpp).
#include "poinsot/multibody/projected_rk4.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "acceleration_multipliers.hpp"
#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/multibody/constraints.hpp"
#include "poinsot/multibody/loads.hpp"
#include "poinsot/multibody/observables.hpp"
#include "poinsot/so3/cayley.hpp"
#include "poinsot/so3/hat.hpp"
#include "poinsot/so3/projection.hpp"

namespace poinsot::multibody {

namespace {

bool same_state(const BodyState& a, const BodyState& b) {
  return a.x_space == b.x_space && a.R_space_body == b.R_space_body && a.v_space == b.v_space &&
         a.omega_body == b.omega_body;
}

// Brings R to the nearest rotation (the orthogonal factor of its polar decomposition) by Björck–Bowie steps
// (so3::bjorck_step, E′ ≈ −¾E² for E = RᵀR − I): from |E| < 1e-8 (RK4 leaves E at O(h⁵), ~1e-12 on the
// 64-link benchmark chain) one step is at round-off and is not checked again. Returns false when E does not
// fall below 1e-15 (R far from a rotation).
bool orthonormalize(Mat3& R) {
  for (int k = 0; k < 6; ++k) {
    const Mat3 E = so3::orthogonality_defect(R);
    const double e = E.cwiseAbs().maxCoeff();
    if (e <= 1e-15) return true;
    so3::bjorck_step(R, E);
    if (e < 1e-8) return true;
  }
  return false;
}

}  // namespace

struct ProjectedRk4::Impl {
  // The RK4 sum k₁ + 2k₂ + 2k₃ + k₄ of one body's derivatives (ẋ, Ṙ, v̇, ω̇).
  struct Derivative {
    Vec3 x, v, w;
    Mat3 R;
  };

  Impl(const System& s, double step, ProjectedRk4Options o) : system(s), h(step), options(o), solver(system) {
    const auto nb = static_cast<std::size_t>(system.body_count());
    loads.resize(nb);
    first_loads.resize(nb);
    rhs_body.resize(nb);
    first_stage.resize(nb);
    start.resize(nb);
    stage.resize(nb);
    end.resize(nb);
    sum.resize(nb);
    rate.resize(nb);
    rhs_joint.resize(system.constraint_rows());
    first_minus_lambda.resize(system.constraint_rows());
    length = system.length_scale();
  }

  // The right-hand side [(f, τ − ω × Jω); −γ] of the acceleration-level KKT system at q (loads kept).
  void acceleration_rhs(const std::vector<BodyState>& q) {
    detail::acceleration_rhs(system, q, solver, loads, rhs_body, rhs_joint);
  }

  // Accelerations at q into rhs_body (and −λ into rhs_joint): one factorisation and one solve.
  void evaluate(const std::vector<BodyState>& q) {
    solver.factor_at(q);
    acceleration_rhs(q);
    solver.solve(rhs_body, rhs_joint);
  }

  // Adds weight × the derivative at the stage state (velocities of `stage`, accelerations `acc`) to the RK4
  // sum (`first`: starts it), then moves the stage state to start + c h × that derivative (c = 0: leave it).
  void accumulate(const std::vector<Vec6>& acc, double weight, double c, bool first = false) {
    // Ṙ in a pass of its own: used right after being written entry by entry, it stalled store forwarding.
    for (std::size_t i = 0; i < stage.size(); ++i)
      rate[i] = so3::times_hat(stage[i].R_space_body, stage[i].omega_body);
    for (std::size_t i = 0; i < stage.size(); ++i) {
      BodyState& y = stage[i];
      const Vec3 dx = y.v_space;
      const Mat3& dR = rate[i];
      const Vec3 dv = acc[i].head<3>();
      const Vec3 dw = acc[i].tail<3>();
      Derivative& s = sum[i];
      if (first) {
        s = {dx, dv, dw, dR};
      } else {
        s.x += weight * dx;
        s.v += weight * dv;
        s.w += weight * dw;
        s.R += weight * dR;
      }
      if (c != 0.0) {
        const BodyState& y0 = start[i];
        const double ch = c * h;
        y.x_space = y0.x_space + ch * dx;
        y.R_space_body = y0.R_space_body + ch * dR;
        y.v_space = y0.v_space + ch * dv;
        y.omega_body = y0.omega_body + ch * dw;
      }
    }
  }

  // The largest joint residual relative to its tolerance scale at q; fills rhs_joint with −g.
  double joint_residuals(const std::vector<BodyState>& q) {
    double err = 0.0;
    for (std::size_t j = 0; j < system.joints().size(); ++j) {
      const Joint& joint = system.joints()[j];
      err = std::max(err, scaled_joint_value(joint, q[static_cast<std::size_t>(joint.body_a)],
                                             side_state(q, joint.body_b), -1.0, length,
                                             rhs_joint.data() + solver.joint_offset(static_cast<int>(j))));
    }
    return err;
  }

  // The M-orthogonal projection of the positions onto g = 0 (simplified Newton with the factorisation in
  // place, the last stage's).
  void project_positions(std::vector<BodyState>& q, double time) {
    iterations = 0;
    for (;;) {
      const double err = joint_residuals(q);
      if (err <= options.tolerance) return;
      if (++iterations > options.max_iterations) {
        throw ComputationFailed(
            fmt::format("multibody: at t = {} s the projection onto the joints did not converge in {} "
                        "iterations (relative gap {:.3g}; reduce dt)",
                        time, options.max_iterations, err));
      }
      for (Vec6& r : rhs_body)
        r.setZero();
      solver.solve(rhs_body, rhs_joint);
      for (std::size_t i = 0; i < q.size(); ++i) {
        q[i].x_space += rhs_body[i].head<3>();
        const Vec3 dtheta = rhs_body[i].tail<3>();
        // An exact rotation keeps R orthogonal; for |δθ| < 1e-8 (the usual case, the gaps RK4 leaves are
        // ~1e-10 m) I + j(δθ) is one to |δθ|²/2 < 5e-17, below round-off, and cheaper.
        if (dtheta.squaredNorm() < 1e-16) {
          q[i].R_space_body += q[i].R_space_body * so3::hat(dtheta);
        } else {
          q[i].R_space_body = q[i].R_space_body * so3::cayley(0.5 * dtheta);
        }
      }
    }
  }

  void step(State& state) {
    check_body_count(system, state);
    const auto nb = state.bodies.size();
    bool resumed = have_first;
    for (std::size_t i = 0; resumed && i < nb; ++i)
      resumed = same_state(state.bodies[i], end[i]);
    const double t0 = state.time;
    start = state.bodies;
    try {
      if (!resumed) {  // a new trajectory (or a state changed by the caller): first stage from scratch
        evaluate(start);
        keep_first_stage();
      }
      stage = start;
      const double time = state.time;
      accumulate(first_stage, 1.0, 0.5, true);
      evaluate(stage);
      accumulate(rhs_body, 2.0, 0.5);
      evaluate(stage);
      accumulate(rhs_body, 2.0, 1.0);
      evaluate(stage);
      accumulate(rhs_body, 1.0, 0.0);
      for (std::size_t i = 0; i < nb; ++i) {
        const BodyState& y0 = start[i];
        const Derivative& s = sum[i];
        BodyState& y = end[i];
        y.x_space = y0.x_space + (h / 6.0) * s.x;
        y.R_space_body = y0.R_space_body + (h / 6.0) * s.R;
        y.v_space = y0.v_space + (h / 6.0) * s.v;
        y.omega_body = y0.omega_body + (h / 6.0) * s.w;
        if (!orthonormalize(y.R_space_body)) {
          throw ComputationFailed(
              fmt::format("multibody: at t = {} s body '{}' left the rotations in one step (reduce dt)", time,
                          system.bodies()[i].name));
        }
      }
      project_positions(end, time);
      // Velocities: the M-orthogonal projection onto G(qₙ₊₁) V = 0, as the correction ΔV of
      // [M Gᵀ; G 0][ΔV; y] = [0; −G V], added to V. Solved for V itself from [M V; 0], V would pass through
      // M and the rounded M⁻¹ every step (J ω → J⁻¹(J ω)): a fixed relative error of a few ulps per step that
      // made the energy and the momenta of a free body drift linearly; the correction is zero there, and
      // small (the joints' velocity error) elsewhere.
      solver.factor_at(end);
      for (std::size_t i = 0; i < nb; ++i)
        rhs_body[i].setZero();
      for (std::size_t j = 0; j < system.joints().size(); ++j) {
        const Joint& joint = system.joints()[j];
        rhs_joint.segment(solver.joint_offset(static_cast<int>(j)), joint.rows()) =
            -joint_velocity(joint, end[static_cast<std::size_t>(joint.body_a)], side_state(end, joint.body_b))
                 .head(joint.rows());
      }
      solver.solve(rhs_body, rhs_joint);
      for (std::size_t i = 0; i < nb; ++i) {
        end[i].v_space += rhs_body[i].head<3>();
        end[i].omega_body += rhs_body[i].tail<3>();
      }
      // The next step's first stage, with the factorisation at qₙ₊₁ already in place.
      acceleration_rhs(end);
      solver.solve(rhs_body, rhs_joint);
      keep_first_stage();
    } catch (const ComputationFailed&) {  // leave the state as it was before the step
      std::copy(start.begin(), start.end(), state.bodies.begin());
      state.time = t0;
      have_first = false;
      exact = ExactMultipliers{};  // no multipliers from a failed step
      multipliers_ready = true;
      throw;
    }
    std::copy(end.begin(), end.end(), state.bodies.begin());
    state.time = t0 + h;
    have_first = true;
    multipliers_ready = false;
  }

  void keep_first_stage() {
    first_stage = rhs_body;
    first_minus_lambda = rhs_joint;
    first_loads = loads;
  }

  const ExactMultipliers& multipliers() {
    if (!multipliers_ready && have_first) {
      exact = detail::multipliers_from_accelerations(system, end, first_loads, first_stage,
                                                     first_minus_lambda, solver);
    }
    multipliers_ready = true;
    return exact;
  }

  System system;
  double h;
  ProjectedRk4Options options;
  KktSolver solver;
  double length = 1.0;
  std::vector<BodyLoads> loads, first_loads;
  std::vector<Vec6> rhs_body, first_stage;
  Eigen::VectorXd rhs_joint, first_minus_lambda;
  std::vector<BodyState> start, stage, end;
  std::vector<Derivative> sum;
  std::vector<Mat3> rate;  // Ṙ of the stage state
  bool have_first = false;
  bool multipliers_ready = false;
  int iterations = 0;
  ExactMultipliers exact;
};

ProjectedRk4::ProjectedRk4(const System& system, double dt, ProjectedRk4Options options) {
  require_positive("multibody: time step dt", dt, "s");
  require_positive("multibody: projection tolerance", options.tolerance);
  if (options.max_iterations < 1) {
    throw InvalidInput(fmt::format("multibody: max_iterations {} must be >= 1", options.max_iterations));
  }
  impl_ = std::make_unique<Impl>(system, dt, options);
}
ProjectedRk4::~ProjectedRk4() = default;
ProjectedRk4::ProjectedRk4(ProjectedRk4&&) noexcept = default;
ProjectedRk4& ProjectedRk4::operator=(ProjectedRk4&&) noexcept = default;

void ProjectedRk4::step(State& state) {
  impl_->step(state);
}
double ProjectedRk4::dt() const {
  return impl_->h;
}
const System& ProjectedRk4::system() const {
  return impl_->system;
}
KktMethod ProjectedRk4::kkt_method() const {
  return impl_->solver.method();
}
int ProjectedRk4::last_iterations() const {
  return impl_->iterations;
}
const ExactMultipliers& ProjectedRk4::multipliers() const {
  return impl_->multipliers();
}

}  // namespace poinsot::multibody
