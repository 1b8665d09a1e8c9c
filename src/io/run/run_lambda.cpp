// The few lines on Λ in the report of a run (see run_lambda.hpp).
#include "run_lambda.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/format.hpp"

namespace poinsot::io::detail {
namespace {

std::string vec6(const Vec3& v) {
  return fmt::format("({}, {}, {})", format_number(v[0], 6), format_number(v[1], 6), format_number(v[2], 6));
}

}  // namespace

std::vector<std::string> lambda_lines(const analysis::LambdaProperties& p) {
  std::vector<std::string> out;
  const double scale = std::max(p.lambda_scale, 1e-300);
  out.push_back(fmt::format("Λ = (j(ω)² + j(ω̇)) K (body frame, paper eq. 3.2): eigenvalues at t0 {} J",
                            vec6(p.eigenvalues_initial)));
  out.push_back(fmt::format(
      "over {} samples: eigenvalues vary by at most {:.2e} J ({:.1e} of ‖Λ(t0)‖){}", p.samples,
      p.eigenvalue_max_variation, p.eigenvalue_max_variation / scale,
      p.closed_form
          ? "; constant by the paper's theorem for an axisymmetric free body"
          : (p.torque_free ? "; not constant in general: the theorem needs an axisymmetric body" : "")));
  out.push_back(
      fmt::format("checks: max |tr Λ + 2T| = {:.2e} J, max symmetry error {:.2e} J, largest eigenvalue "
                  "seen {:.3g} J (expected <= 0: −Λ is positive semi-definite)",
                  p.trace_plus_2T_max, p.symmetry_error_max, p.max_eigenvalue_max));
  if (p.closed_form) {
    const auto& c = *p.closed_form;
    out.push_back(fmt::format(
        "closed form (axisymmetric, A = {}, C = {} kg·m²): λ = (c1 ∓ √Δ)/2, −C|Ω0|²/2 = {} J; "
        "max deviation {:.2e} J",
        format_number(c.inertia.A, 6), format_number(c.inertia.C, 6), vec6(c.eigenvalues), c.max_deviation));
  }
  const auto& s = p.stress_initial.integral;
  out.push_back(
      fmt::format("constraint stress ∫σ dv = −R Λ Rᵀ at t0: principal values {} N·m, Tresca {} N·m, "
                  "von Mises {} N·m",
                  vec6(s.principal), format_number(s.tresca, 6), format_number(s.von_mises, 6)));
  return out;
}

}  // namespace poinsot::io::detail
