#pragma once
/// @file lambda_json.hpp
/// The JSON form of the Λ report (analysis/lambda_report.hpp) and of its parts: the one serialiser behind
/// `poinsot lambda --json` and the dicts of Python's `poinsot.analysis` (`lambda_report`,
/// `lambda_properties`, `summarize_stress`, `constraint_stress`), so that both give the same keys and values.
/// Keys are stable and documented in docs/lambda.md; values in SI units (J, N·m, Pa, m³, s), vectors as
/// arrays, matrices row by row, a non-finite number as null. Every function returns pretty-printed text
/// (2 spaces, no trailing newline).

#include <string>

#include "poinsot/analysis/axisymmetric.hpp"
#include "poinsot/analysis/lambda_report.hpp"
#include "poinsot/analysis/lambda_tracker.hpp"
#include "poinsot/analysis/stress.hpp"

namespace poinsot::io {

/// A stress summary: `tensor` (3×3), `principal` (ascending), `principal_axes` (3×3, the axes as columns),
/// `tresca`, `von_mises`, `trace` (N·m for ∫σ dv, Pa for a mean stress).
std::string stress_summary_json(const analysis::StressSummary& stress);

/// The constraint stress: `integral` (∫σ dv, N·m) and `mean` (Pa; null without a volume), each as
/// stress_summary_json.
std::string constraint_stress_json(const analysis::ConstraintStress& stress);

/// The special cases of the axisymmetric closed form (axisymmetric.hpp): `ball`, `flat`, `axial_spin`,
/// `equatorial_spin`, `zero_discriminant`, `zero_velocity` (booleans).
std::string special_cases_json(const analysis::AxisymmetricSpecialCases& cases);

/// The properties of Λ along a trajectory (lambda_tracker.hpp): `samples`, `t_initial`, `t_final`,
/// `torque_free`, `lambda_initial`, `lambda_final`, `lambda_scale`, `eigenvalues_initial`,
/// `eigenvalues_final`, `eigenvalue_max_variation`, `symmetry_error_max`, `max_eigenvalue_max`,
/// `trace_plus_2T_max`, `stress_integral_initial`, `stress_initial` and `mean_stress_initial` (as
/// stress_summary_json; the mean null without a volume), `von_mises_max`, `integrator_multiplier` (null, or
/// `deviation_max`, `symmetry_error_max`) and `closed_form` (null unless axisymmetric and free).
std::string lambda_properties_json(const analysis::LambdaProperties& properties);

/// The report of `poinsot lambda`: the run (`method`, `torque`, `principal_moments`, `t_initial`, `t_end`,
/// `dt`, `sample_dt`, `steps`, `volume`), every key of lambda_properties_json, and `invariant_errors`
/// (`energy_rel_max`, `L_space_rel_max`, `L_norm_rel_max`, `orthogonality_max`). Deterministic: the wall
/// time is left out.
std::string lambda_report_json(const analysis::LambdaReport& report);

}  // namespace poinsot::io
