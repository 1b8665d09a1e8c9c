#include "poinsot/optimal/verification.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include "pmp_system.hpp"
#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/dop853.hpp"
#include "poinsot/so3/distance.hpp"

namespace poinsot::optimal {

namespace {

/// The control-dependent part of H: L(u) + σᵀu.
double control_hamiltonian(const ReorientationProblem& p, const Vec3& sigma, const Vec3& u) {
  return detail::running_cost(p, u) + sigma.dot(u);
}

/// The smooth torque at `time` from its samples: the cubic through the four samples nearest to `time` on its
/// arc (fewer where the arc has fewer: quadratic, linear). Arcs are separated by a repeated time (the two
/// sides of a knot or a node). The interpolation error is O(h⁴ ü⁽⁴⁾) instead of the O(h² ü) of the
/// piecewise-linear table: a control that turns with the body (stopping the tumbling racket, 6 rad/s) is
/// replayed from 64 samples per segment to 1e-9 of ū instead of 1e-5, which an unstable tumble would
/// amplify past the check's 1e-6 rad.
Vec3 sampled_torque_at(const std::vector<double>& t, const std::vector<Vec3>& u, double time) {
  const auto it = std::upper_bound(t.begin(), t.end(), time);
  const std::size_t b = std::clamp<std::size_t>(it - t.begin(), 1, t.size() - 1), a = b - 1;
  if (!(t[b] > t[a])) return u[b];
  std::size_t lo = a, hi = b;
  if (lo > 0 && t[lo - 1] < t[lo]) --lo;
  if (hi + 1 < t.size() && t[hi + 1] > t[hi]) ++hi;
  const double x = std::clamp(time, t[a], t[b]);
  Vec3 out = Vec3::Zero();
  for (std::size_t i = lo; i <= hi; ++i) {
    double w = 1.0;
    for (std::size_t k = lo; k <= hi; ++k)
      if (k != i) w *= (x - t[k]) / (t[i] - t[k]);
    out += w * u[i];
  }
  return out;
}

/// Replays the indirect solution's torque through DOP853; returns the final state.
dynamics::State resimulate(const ReorientationProblem& p, const IndirectSolution& s) {
  const auto body = dynamics::RigidBody::from_inertia(p.inertia_body);
  auto arc_torque = std::make_shared<Vec3>(Vec3::Zero());
  std::shared_ptr<const dynamics::TorqueModel> torque;
  if (s.bang_bang) {
    // The torque of the current arc, set before the arc is integrated: no stage sees the next arc.
    torque = dynamics::TorqueModel::callback(
        [arc_torque](double, const Mat3&, const Vec3&) { return *arc_torque; }, false,
        "optimal bang-bang torque");
  } else {
    const auto* t = &s.time;
    const auto* u = &s.torque_body;
    torque = dynamics::TorqueModel::callback(
        [t, u](double time, const Mat3&, const Vec3&) { return sampled_torque_at(*t, *u, time); }, false,
        "optimal tabulated torque");
  }
  dynamics::IntegratorOptions opt;
  opt.dt = s.final_time / 16.0;
  opt.rtol = opt.atol = 1e-13;
  dynamics::Dop853Integrator integrator(body, torque, opt);
  dynamics::State state;
  state.R_space_body = p.attitude_initial.toRotationMatrix();
  state.omega_body = p.omega_initial;
  std::vector<ControlArc> arcs = s.arcs;
  if (!s.bang_bang) arcs = {{0.0, s.final_time, Vec3::Zero()}};
  double dt = opt.dt;
  for (const auto& arc : arcs) {
    *arc_torque = arc.torque_body;
    while (arc.t_end - state.time > 1e-14 * s.final_time) {
      const auto r = integrator.step(state, std::min(dt, arc.t_end - state.time));
      dt = std::max(r.dt_next, 1e-12);
    }
  }
  return state;
}

}  // namespace

VerificationReport verify(const ReorientationProblem& p, const DirectSolution& d, const IndirectSolution& s,
                          const VerificationTolerances& tol) {
  VerificationReport r;
  auto fail = [&](const std::string& what) { r.failures.push_back(what); };
  if (!d.converged) fail("direct method: " + d.status);
  if (!s.converged) fail("indirect method: " + s.status);
  if (s.time.empty()) {
    r.passed = false;
    return r;
  }
  const Mat3 J_inv = p.inertia_body.inverse();
  const auto body = dynamics::RigidBody::from_inertia(p.inertia_body);
  double h_sum = 0.0;
  for (double h : s.hamiltonian)
    h_sum += h;
  r.hamiltonian_mean = h_sum / static_cast<double>(s.hamiltonian.size());
  const Vec3 pi0 = s.attitude.front() * s.costate_attitude_body.front();
  // The drift of R p_θ relative to ‖p_θ(0)‖, or to max ‖p_ω‖/T (the same units) where p_θ vanishes (a free
  // final attitude: p_θ ≡ 0, and the nodes of multiple shooting leave it at round-off, not exactly 0).
  double p_omega_max = 0.0;
  for (const auto& q : s.costate_omega)
    p_omega_max = std::max(p_omega_max, q.norm());
  const double costate_scale = std::max({pi0.norm(), p_omega_max / s.final_time, 1e-300});
  double sigma_max = 0.0;
  double control_scale = 0.0;
  for (std::size_t j = 0; j < s.time.size(); ++j) {
    const Vec3& sg = s.switching_function[j];
    sigma_max = std::max(sigma_max, sg.cwiseAbs().maxCoeff());
    control_scale = std::max(control_scale, sg.norm() * minimising_control(p, s.costate_omega[j]).norm());
  }
  for (std::size_t j = 0; j < s.time.size(); ++j) {
    r.hamiltonian_deviation =
        std::max(r.hamiltonian_deviation, std::abs(s.hamiltonian[j] - r.hamiltonian_mean));
    const Vec3& sigma = s.switching_function[j];
    const Vec3& u = s.torque_body[j];
    const Vec3 u_best = minimising_control(p, s.costate_omega[j]);
    // Relative to the size of the control-dependent part of H, ‖σ‖ ‖u*‖ (ū‖σ‖ for minimum time, ‖σ‖²/2 for
    // energy), at its largest over the solution: where σ vanishes (a switch, a norm-bound reversal) the
    // minimiser is not determined by σ and the pointwise ratio would measure round-off.
    const double scale = std::max(control_scale, 1e-300);
    r.control_gap = std::max(
        r.control_gap, (control_hamiltonian(p, sigma, u) - control_hamiltonian(p, sigma, u_best)) / scale);
    if (s.bang_bang)
      for (int i = 0; i < 3; ++i)
        if (u[i] * sigma[i] > 0.0 && std::abs(sigma[i]) > 1e-9 * sigma_max) ++r.switching_sign_violations;
    r.costate_drift =
        std::max(r.costate_drift, (s.attitude[j] * s.costate_attitude_body[j] - pi0).norm() / costate_scale);
    r.orthogonality =
        std::max(r.orthogonality, (s.attitude[j].transpose() * s.attitude[j] - Mat3::Identity()).norm());
    const Vec3 omega_dot = J_inv * (u - s.omega_body[j].cross(p.inertia_body * s.omega_body[j]));
    const Mat3 lambda = analysis::lambda_from_omega(body, s.omega_body[j], omega_dot);
    r.lambda_torque_error = std::max(
        r.lambda_torque_error, (so3::vee(lambda - lambda.transpose()) - u).norm() / p.torque_norm_limit());
  }
  const dynamics::State end = resimulate(p, s);
  // With a free final attitude the re-simulation is compared with the indirect solution's own R(T).
  r.resimulated_attitude_error = so3::angle_between(
      end.R_space_body, p.free_final_attitude ? s.attitude.back() : p.attitude_final.toRotationMatrix());
  r.resimulated_rate_error = (end.omega_body - p.omega_final).norm();
  r.direct_indirect_difference = std::abs(d.cost - s.cost) / std::max(std::abs(s.cost), 1e-300);

  const double h_level = p.free_final_time() ? std::abs(r.hamiltonian_mean) : 0.0;
  if (r.hamiltonian_deviation > tol.hamiltonian || h_level > tol.hamiltonian)
    fail("Hamiltonian: mean " + format_number(r.hamiltonian_mean, 3) + ", deviation " +
         format_number(r.hamiltonian_deviation, 3) + " (expected constant" +
         (p.free_final_time() ? " and 0" : "") + " to " + format_number(tol.hamiltonian) + ")");
  if (r.control_gap > tol.control)
    fail("the control does not minimise H: gap " + format_number(r.control_gap, 3));
  if (r.switching_sign_violations > 0)
    fail(std::to_string(r.switching_sign_violations) + " samples with a torque of the sign of σ");
  if (r.costate_drift > tol.costate)
    fail("space attitude costate drifts by " + format_number(r.costate_drift, 3));
  if (r.orthogonality > tol.orthogonality) fail("RᵀR − I reaches " + format_number(r.orthogonality, 3));
  if (r.lambda_torque_error > 1e-12)
    fail("vee(Λ − Λᵀ) differs from u by " + format_number(r.lambda_torque_error, 3));
  const double att_tol = s.bang_bang ? tol.resimulated_attitude : tol.resimulated_attitude_smooth;
  if (r.resimulated_attitude_error > att_tol)
    fail("re-simulation misses the target attitude by " + format_number(r.resimulated_attitude_error, 3) +
         " rad");
  if (r.resimulated_rate_error > att_tol)
    fail("re-simulation misses the target rate by " + format_number(r.resimulated_rate_error, 3) + " rad/s");
  if (r.direct_indirect_difference > tol.direct_indirect)
    fail("direct and indirect costs differ by " + format_number(r.direct_indirect_difference, 3) +
         " (relative)");
  r.passed = r.failures.empty();
  return r;
}

}  // namespace poinsot::optimal
