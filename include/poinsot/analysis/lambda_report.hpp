#pragma once
/// @file lambda_report.hpp
/// One call that runs a simulation and checks the theorems of Vallée & Dumitriu (2002) on Λ along it: the
/// engine behind `poinsot lambda` (and `poinsot run` when it reports Λ). See docs/lambda.md.
///
/// The run uses dynamics::simulate with the named integrator; every sample goes through a LambdaTracker
/// (Λ from the state, eq. 3.2). With "rattle" the integrator's own multipliers (centred on the midpoint of
/// each step) are compared with the state formula at that midpoint, reached by one RK4 half-step back from
/// the sample (local error O(h⁵), far below rattle's O(h²)).

#include <memory>
#include <string>

#include "poinsot/analysis/lambda_tracker.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::analysis {

struct LambdaAnalysisOptions {
  std::string method{dynamics::kDefaultLambdaMethod};   ///< a name of the method registry (methods.hpp)
  dynamics::IntegratorOptions integrator;               ///< dt (s), tolerances
  double t_end = 10.0;                                  ///< s, the final time (> initial.time)
  double sample_dt = 0.01;                              ///< s, the interval between checked states
  std::shared_ptr<const dynamics::TorqueModel> torque;  ///< nullptr: torque-free
  double volume_m3 = 0.0;                               ///< m³; > 0 adds the mean stress (Pa)
  double axisymmetry_tolerance = 1e-12;                 ///< relative tolerance on equal principal moments
};

struct LambdaReport {
  std::string method;
  std::string torque;                     ///< TorqueModel::describe()
  Vec3 principal_moments = Vec3::Zero();  ///< kg·m², ascending
  double t_initial = 0.0;                 ///< s
  double t_end = 0.0;                     ///< s
  double sample_dt = 0.0;                 ///< s
  double dt = 0.0;                        ///< s, the integrator's nominal step (0 for exact)
  double volume_m3 = 0.0;                 ///< m³ (0: unknown)
  LambdaProperties properties;            ///< the checks (lambda_tracker.hpp)
  long long steps = 0;
  dynamics::InvariantErrors invariant_errors;  ///< the driver's energy / momentum / orthogonality errors
  double wall_time_s = 0.0;
};

/// Runs `body` from `initial` to options.t_end and checks Λ at every sample. Throws InvalidInput for bad
/// options (unknown method, t_end ≤ t0, "exact" with a torque, ...) and ComputationFailed if the run fails.
LambdaReport analyse_lambda(const dynamics::RigidBody& body, const dynamics::State& initial,
                            const LambdaAnalysisOptions& options);

/// The report as human-readable text (several lines, SI units named).
std::string format_lambda_report(const LambdaReport& report);

}  // namespace poinsot::analysis
