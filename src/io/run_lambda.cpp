// The few lines on Λ in the report of a run (see run_lambda.hpp).
//
// Λ = Rᵀ R̈ K = (j(ω)² + j(ω̇)) K (paper eq. 3.2, ERRATA.md), body frame, in joules, with ω̇ from Euler's
// equations J ω̇ = τ_body − ω × J ω. Its trace is −2T (T the kinetic energy), −Λ is positive semi-definite,
// and −R Λ Rᵀ is the volume integral of the Cauchy stress that holds the body together (N·m).
#include "run_lambda.hpp"

#include <fmt/format.h>
#include <Eigen/Eigenvalues>

#include "poinsot/core/format.hpp"
#include "poinsot/so3/hat.hpp"

namespace poinsot::io::detail {
namespace {
std::string vec6(const Vec3& v) {
  return fmt::format("({}, {}, {})", format_number(v[0], 6), format_number(v[1], 6), format_number(v[2], 6));
}
}  // namespace

void lambda_report(const Scenario& sc, RunSummary& sum) {
  const auto& body = sc.body;
  const dynamics::State& s = sc.initial;
  const Vec3& w = s.omega_body;
  const Mat3& J = body.inertia();
  const Vec3 tau = sc.torque->torque_body(s.t, s.R, w);
  const Vec3 wdot = body.inertia_inverse() * (tau - w.cross(J * w));
  const Mat3 jw = so3::hat(w);
  const Mat3 lambda = (jw * jw + so3::hat(wdot)) * body.poinsot();
  sum.lambda0 = lambda;
  const Mat3 sym = 0.5 * (lambda + lambda.transpose());
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(sym, Eigen::EigenvaluesOnly);
  const Vec3 ev = eig.eigenvalues();
  const double T = dynamics::kinetic_energy(body, s);
  const double scale = std::max(std::abs(T), 1e-300);
  sum.lambda_lines.push_back(fmt::format("Λ(0) = (j(ω)² + j(ω̇)) K, eigenvalues {} J", vec6(ev)));
  sum.lambda_lines.push_back(
      fmt::format("tr Λ + 2T = {:.2e} J (relative {:.1e}); largest eigenvalue {:.3g} J (−Λ is positive "
                  "semi-definite: expected <= 0)",
                  lambda.trace() + 2.0 * T, std::abs(lambda.trace() + 2.0 * T) / scale, ev[2]));
  sum.lambda_lines.push_back(fmt::format("∫σ dv = −R Λ Rᵀ at t = 0: principal values {} N·m", vec6(-ev)));
}

}  // namespace poinsot::io::detail
