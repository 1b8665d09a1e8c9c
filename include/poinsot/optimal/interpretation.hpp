#pragma once
/// @file interpretation.hpp
/// What an optimal manoeuvre means mechanically, along the indirect solution's samples:
///  - the multipliers of Vallée & Dumitriu, Λ = Rᵀ R̈ K = (j(ω)² + j(ω̇)) K (body frame, J), whose skew part
///    is the control torque (vee(Λ − Λᵀ) = u) and whose symmetric part is the internal load;
///  - the constraint stress ∫σ dv = −R Λ Rᵀ (space frame, N·m; docs/conventions.md §6), its peak Tresca and
///  von Mises
///    values over the manoeuvre (of the symmetric part);
///  - the space angular momentum L = R J ω (kg·m²/s);
///  - the eigenaxis manoeuvre with the same bounds beside the optimum: rest to rest about the fixed axis n of
///    R_0ᵀR_f, bang-bang at the largest admissible acceleration α = min_i u_max,i / |(J n)_i| (per-axis) or
///    ū/‖J n‖ (norm), taking 2√(Θ/α) (minimum time); or the cubic θ = Θ(3s² − 2s³), cost ‖J n‖² 12Θ²/T³
///    (minimum energy). Defined only when J n ∥ n (n a principal axis or J spherical), so that no gyroscopic
///    torque acts; otherwise `eigenaxis_available` is false.
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::optimal {

struct ManoeuvreInterpretation {
  std::vector<Mat3> lambda_body;     ///< Λ at each sample of the indirect solution (J)
  std::vector<Mat3> stress_space;    ///< −R sym(Λ) Rᵀ (N·m)
  std::vector<Vec3> momentum_space;  ///< R J ω (kg·m²/s)
  double peak_tresca = 0.0;          ///< N·m
  double peak_von_mises = 0.0;       ///< N·m
  double peak_tresca_time = 0.0;     ///< s
  bool eigenaxis_available = false;
  double eigenaxis_cost = 0.0;  ///< s (minimum time) or N²·m²·s (minimum energy)
  double saving = 0.0;  ///< (eigenaxis − optimum) / eigenaxis (final time for the free-time objectives)
};

/// Throws InvalidInput for an empty solution.
ManoeuvreInterpretation interpret(const ReorientationProblem& problem, const IndirectSolution& solution);

}  // namespace poinsot::optimal
