#pragma once
/// @file run_summary.hpp
/// What a single-body run produced (run.hpp), as the report (report.hpp) and summary.json (summary.hpp) read
/// it.

#include <optional>
#include <string>
#include <vector>

#include "poinsot/analysis/lambda_tracker.hpp"
#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/top_prediction.hpp"

namespace poinsot::io {

/// A top of a run (heavy top, or torque-free axisymmetric body): the theory's predictions
/// (dynamics::predict_top) and what the run measured.
struct TopEvents : dynamics::TopPrediction {
  std::optional<double> precession_rate_mean;  ///< measured (rad/s)
  std::optional<double> nutation_frequency;    ///< measured (rad/s)
  double theta_min = 0.0, theta_max = 0.0;     ///< range of the axis's polar angle, measured (rad)
};

/// Everything a run produced, for the report and summary.json.
struct RunSummary {
  std::string scenario, source, title, method, torque, body_description, symmetry;
  Vec3 principal_moments = Vec3::Zero();  ///< kg·m², ascending (about the rotation point)
  Mat3 inertia = Mat3::Identity();        ///< J about the rotation point, body frame (kg·m²)
  dynamics::State initial;
  double energy0 = 0.0;                 ///< J, T + V at t = 0
  Vec3 L_space0 = Vec3::Zero();         ///< kg·m²/s
  double t_end = 0.0, sample_dt = 0.0;  ///< s
  dynamics::SimulationResult result;    ///< final state, steps, worst errors, flip times, wall time
  long long samples = 0;
  std::string failure;  ///< the message of a ComputationFailed that stopped the run (empty: none)
  /// Torque-free body: the regime of the Euler-Poinsot motion ("largest axis", "axisymmetric", ...); empty
  /// with a torque.
  std::string free_body_regime;
  /// Torque-free asymmetric body off the separatrix: the closed form 2K(k)/ω_p between flips (s); the period
  /// of ω (s): 4K(k)/ω_p for an asymmetric body, 2π/ω_p for an axisymmetric one.
  std::optional<double> flip_interval_theory, period_theory;
  std::optional<TopEvents> top;
  /// Λ along the samples (analysis layer): eigenvalues, their variation, checks, closed form, stress.
  std::optional<analysis::LambdaProperties> lambda;
  std::vector<std::string> lambda_lines;  ///< a few lines for the report
  std::string out_dir;                    ///< empty: no files written
  std::string trajectory_file, summary_file;
};

}  // namespace poinsot::io
