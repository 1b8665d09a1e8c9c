// Optimal motions of multibody systems by direct collocation (multibody_direct.hpp).
#include "poinsot/optimal/multibody_direct.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <fmt/format.h>
#include <Eigen/SVD>

#include "hermite_simpson_dae.hpp"
#include "multibody_controls.hpp"
#include "multibody_minimal_model.hpp"
#include "multibody_rate_rows.hpp"
#include "multibody_rotation_model.hpp"
#include "path_inequality_nlp.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::optimal {
namespace {

using detail::CollocationModel;
using detail::HermiteSimpsonDae;
using detail::PathInequalityNlp;
using detail::PointFunctions;
using detail::SparseNlp;

/// The rows N ᵀ of an orthonormal basis N of the null space of C (the tangent space of the constraints).
Eigen::MatrixXd tangent_rows(const Eigen::MatrixXd& C) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
  const auto& s = svd.singularValues();
  const double tol = 1e-10 * std::max(1.0, s.size() > 0 ? s(0) : 0.0);
  int rank = 0;
  while (rank < s.size() && s(rank) > tol)
    ++rank;
  return svd.matrixV().rightCols(C.cols() - rank).transpose();
}

/// Solves the transcription of `model` and fills the parts of the optimum common to both formulations.
/// `decode(w, t)` gives the multibody state of the point variables w; `rates` the hinge rates of the
/// problem's rate bounds at a point (multibody_rate_rows.hpp), bounded at every point but the first.
template <class Decode>
MultibodyOptimum solve_model(const MultibodyProblem& problem, const CollocationModel& model,
                             const Eigen::VectorXd& y0, const Eigen::VectorXd& yf,
                             const Eigen::MatrixXd& final_rows, const PointFunctions& rates,
                             const MultibodyOptions& options, Decode decode,
                             std::chrono::steady_clock::time_point start) {
  const HermiteSimpsonDae base(model, problem.intervals, problem.final_time, y0, final_rows, final_rows * yf);
  std::vector<double> rate_max;
  for (const RateBound& b : problem.rate_bounds)
    rate_max.push_back(b.rate_max);
  std::vector<double> rate_min(rate_max.size());
  std::transform(rate_max.begin(), rate_max.end(), rate_min.begin(), [](double r) { return -r; });
  const PathInequalityNlp bounded(base, rates, rate_min, rate_max);
  const SparseNlp& nlp = rates.rows() > 0 ? static_cast<const SparseNlp&>(bounded) : base;
  const int nw = model.point_size();
  const int ny = model.state_size();
  std::vector<double> guess(static_cast<std::size_t>(nlp.num_variables()), 0.0);
  for (int p = 0; p < base.points(); ++p) {
    const double s = static_cast<double>(p) / (base.points() - 1);
    Eigen::Map<Eigen::VectorXd>(guess.data() + nw * p, ny) = (1.0 - s) * y0 + s * yf;
  }
  detail::IpoptSettings settings;
  settings.tolerance = options.nlp_tolerance;
  settings.max_iterations = options.max_nlp_iterations;
  settings.print_level = options.print_level;
  const detail::NlpSolution sol = detail::solve_with_ipopt(nlp, guess, settings);
  MultibodyOptimum out;
  out.converged = sol.solved;
  out.status = sol.solved ? "converged" : "not converged: " + sol.status;
  out.nlp_iterations = sol.iterations;
  out.cost = sol.objective;
  std::vector<double> g(static_cast<std::size_t>(nlp.num_constraints()));
  nlp.constraints(sol.x.data(), g.data());
  std::vector<double> lo, up, glo, gup;
  nlp.bounds(lo, up, glo, gup);
  for (std::size_t r = 0; r < g.size(); ++r)
    out.max_constraint_error = std::max({out.max_constraint_error, glo[r] - g[r], g[r] - gup[r]});
  for (int p = 0; p < base.points(); ++p) {
    const double* w = sol.x.data() + nw * p;
    out.time.push_back(base.point_time(p));
    out.states.push_back(decode(w, base.point_time(p)));
    Eigen::VectorXd u(static_cast<Eigen::Index>(model.control_indices().size()));
    for (std::size_t k = 0; k < model.control_indices().size(); ++k)
      u(static_cast<Eigen::Index>(k)) = w[model.control_indices()[k]];
    out.controls.push_back(u);
  }
  out.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace

MultibodyOptimum solve_multibody(const MultibodyProblem& problem, const MultibodyOptions& options) {
  validate(problem);
  const auto start = std::chrono::steady_clock::now();
  if (options.coordinates == MultibodyCoordinates::minimal) {
    const detail::MultibodyMinimalModel model(problem);
    const Eigen::VectorXd y0 = model.state_vector(problem.initial_state);
    const Eigen::VectorXd yf = model.state_vector(problem.final_state);
    const Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(model.state_size(), model.state_size());
    MultibodyOptimum out = solve_model(
        problem, model, y0, yf, rows, detail::minimal_rate_rows(problem), options,
        [&](const double* w, double t) { return model.state_of(w, t); }, start);
    // No multiplier is a variable here: the reactions and Λ of the continuous equations at each point's
    // state and controls (one KKT solve each, multibody/multipliers.hpp).
    for (std::size_t p = 0; p < out.states.size(); ++p) {
      out.multipliers.push_back(multibody::exact_multipliers(
          detail::system_with_controls(problem, out.controls[p]), out.states[p]));
    }
    return out;
  }
  const detail::MultibodyRotationModel model(problem);
  const Eigen::VectorXd y0 = model.state_vector(problem.initial_state);
  const Eigen::VectorXd yf = model.state_vector(problem.final_state);
  const Eigen::MatrixXd rows = tangent_rows(model.invariant_jacobian(problem.final_state));
  std::vector<multibody::Multipliers> multipliers;
  MultibodyOptimum out = solve_model(
      problem, model, y0, yf, rows, detail::rotation_rate_rows(problem, model), options,
      [&](const double* w, double t) {
        multipliers.push_back(model.multipliers_of(w));
        return model.state_of(w, t);
      },
      start);
  out.multipliers = std::move(multipliers);
  return out;
}

Eigen::VectorXd control_at(const MultibodyOptimum& optimum, double t) {
  if (optimum.time.size() < 3 || optimum.controls.size() != optimum.time.size()) {
    throw InvalidInput(
        fmt::format("optimal control: control_at: the optimum has {} points and {} controls; "
                    "expected a solution of solve_multibody (at least 3 points, one control each)",
                    optimum.time.size(), optimum.controls.size()));
  }
  const int points = static_cast<int>(optimum.time.size());
  const int intervals = (points - 1) / 2;
  const double T = optimum.time.back();
  const double h = T / intervals;
  const int k = std::clamp(static_cast<int>(std::floor(t / h)), 0, intervals - 1);
  const double s = t / h - k;
  const auto u = [&](int p) -> const Eigen::VectorXd& {
    return optimum.controls[static_cast<std::size_t>(p)];
  };
  return 2.0 * (s - 0.5) * (s - 1.0) * u(2 * k) - 4.0 * s * (s - 1.0) * u(2 * k + 1) +
         2.0 * s * (s - 0.5) * u(2 * k + 2);
}

}  // namespace poinsot::optimal
