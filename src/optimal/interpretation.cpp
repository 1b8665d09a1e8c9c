#include "poinsot/optimal/interpretation.hpp"

#include <cmath>
#include <limits>

#include "poinsot/analysis/multipliers.hpp"
#include "poinsot/analysis/stress.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::optimal {

ManoeuvreInterpretation interpret(const ReorientationProblem& p, const IndirectSolution& s) {
  if (s.time.empty()) throw InvalidInput("interpret: the solution has no samples");
  ManoeuvreInterpretation out;
  const auto body = dynamics::RigidBody::from_inertia(p.inertia_body);
  const Mat3& J = p.inertia_body;
  const Mat3 J_inv = J.inverse();
  for (std::size_t j = 0; j < s.time.size(); ++j) {
    const Vec3& w = s.omega_body[j];
    const Vec3 w_dot = J_inv * (s.torque_body[j] - w.cross(J * w));
    const Mat3 lambda = analysis::lambda_from_omega(body, w, w_dot);
    const Mat3 stress = analysis::stress_integral_space(lambda, s.attitude[j]);
    const analysis::StressSummary sum = analysis::summarize_stress(stress);
    out.lambda_body.push_back(lambda);
    out.stress_space.push_back(stress);
    out.momentum_space.push_back(s.attitude[j] * (J * w));
    if (sum.tresca > out.peak_tresca) {
      out.peak_tresca = sum.tresca;
      out.peak_tresca_time = s.time[j];
    }
    out.peak_von_mises = std::max(out.peak_von_mises, sum.von_mises);
  }
  const bool at_rest = p.omega_initial.isZero(0.0) && p.omega_final.isZero(0.0) && !p.free_final_attitude;
  const Vec3 rotvec =
      so3::log(p.attitude_initial.toRotationMatrix().transpose() * p.attitude_final.toRotationMatrix());
  const double theta = rotvec.norm();
  if (at_rest && theta > 0.0) {
    const Vec3 n = rotvec / theta;
    const Vec3 Jn = J * n;
    if ((Jn - Jn.dot(n) * n).norm() <= 1e-12 * Jn.norm()) {
      out.eigenaxis_available = true;
      if (p.objective == Objective::minimum_energy) {
        out.eigenaxis_cost = Jn.squaredNorm() * 12.0 * theta * theta / std::pow(p.final_time, 3);
      } else {
        double alpha = p.torque_max[0] / Jn.norm();
        if (p.bound == TorqueBound::per_axis) {
          alpha = std::numeric_limits<double>::infinity();
          for (int i = 0; i < 3; ++i)
            if (std::abs(Jn[i]) > 0.0) alpha = std::min(alpha, p.torque_max[i] / std::abs(Jn[i]));
        }
        out.eigenaxis_cost = 2.0 * std::sqrt(theta / alpha);
      }
      const double optimum = p.objective == Objective::minimum_energy ? s.cost : s.final_time;
      out.saving = (out.eigenaxis_cost - optimum) / out.eigenaxis_cost;
    }
  }
  return out;
}

}  // namespace poinsot::optimal
