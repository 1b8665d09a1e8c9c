#pragma once
/// @file sparse_nlp.hpp (internal)
/// A nonlinear program min f(x) s.t. g_L ≤ g(x) ≤ g_U, x_L ≤ x ≤ x_U with exact sparse first and second
/// derivatives, independent of the solver, and its solution by Ipopt (ipopt_solve.cpp). The Jacobian and
/// the lower triangle (row ≥ col) of the Hessian of the Lagrangian σ f + yᵀg are given as triplets whose
/// structure is fixed.
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace poinsot::optimal::detail {

class SparseNlp {
 public:
  virtual ~SparseNlp() = default;
  virtual int num_variables() const = 0;
  virtual int num_constraints() const = 0;
  virtual void bounds(std::vector<double>& x_lower, std::vector<double>& x_upper,
                      std::vector<double>& g_lower, std::vector<double>& g_upper) const = 0;
  virtual double objective(const double* x) const = 0;
  virtual void objective_gradient(const double* x, double* gradient) const = 0;
  virtual void constraints(const double* x, double* g) const = 0;
  virtual int jacobian_nonzeros() const = 0;
  virtual void jacobian_structure(int* rows, int* cols) const = 0;
  virtual void jacobian_values(const double* x, double* values) const = 0;
  virtual int hessian_nonzeros() const = 0;
  virtual void hessian_structure(int* rows, int* cols) const = 0;
  virtual void hessian_values(const double* x, double sigma, const double* y, double* values) const = 0;
};

struct IpoptSettings {
  double tolerance = 1e-10;  ///< Ipopt's tol (scaled KKT error)
  /// Ipopt's acceptable_tol: a run stopped at this level counts as `acceptable`; 0 keeps Ipopt's default.
  double acceptable_tolerance = 0.0;
  int max_iterations = 1000;
  /// When positive, the first attempt of solve_with_restarts stops after at most this many iterations; the
  /// restarts keep max_iterations (restart_settings).
  int first_attempt_max_iterations = 0;
  int print_level = 0;  ///< Ipopt's print_level (0 = silent)
  /// bound_relax_factor = 0: the bounds are met exactly instead of Ipopt's default relaxation by 1e-8.
  bool exact_bounds = false;
  /// MUMPS' scaling of the KKT matrix (Ipopt's mumps_scaling): 77, Ipopt's default, lets MUMPS choose; 0
  /// none beyond Ipopt's own NLP scaling (MultibodyOptions::mumps_scaling).
  int mumps_scaling = 77;
  /// Ipopt's barrier strategy: "adaptive" (the default here) or "monotone" (Fiacco–McCormick).
  std::string mu_strategy = "adaptive";
  /// Ipopt's mu_init, the first barrier parameter; 0 keeps Ipopt's default (0.1).
  double mu_init = 0.0;
  /// A start near a solution (a previous mesh's optimum): the variables are pushed off their bounds by 1e-9
  /// instead of 1e-2 (bound_push, bound_frac and their slack counterparts), so the barrier does not move
  /// the start away from where it is.
  bool warm_start = false;
  /// The bound multipliers start at μ_init/slack (Ipopt's bound_mult_init_method "mu-based") instead of 1:
  /// with warm_start and a small mu_init, a start on its bounds keeps the complementarity of a converged
  /// iterate there, and the inactive bounds' multipliers start near 0.
  bool bound_multipliers_from_barrier = false;
  /// When positive, the run stops at the first iterate of the regular phase whose optimality error (as in
  /// NlpSolution::smallest_error) is at most this, and counts as solved (solve_with_restarts' rerun of an
  /// attempt that stalled); 0: Ipopt's own termination only.
  double stop_at_error = 0.0;
  /// Called after every Ipopt iteration with its number, the objective and the constraint violation (the
  /// terminal progress of `poinsot optimize`); empty: not called.
  std::function<void(int iteration, double objective, double infeasibility)> on_iteration;
};

struct NlpSolution {
  /// Ipopt returned Solve_Succeeded, or the run stopped at an iterate that met IpoptSettings::stop_at_error
  bool solved = false;
  bool acceptable = false;  ///< Ipopt returned Solved_To_Acceptable_Level
  int return_code = 0;      ///< Ipopt's ApplicationReturnStatus as a number
  std::string status;       ///< "solved", or Ipopt's return status in words
  int iterations = 0;       ///< Ipopt iterations
  double objective = 0.0;
  /// The smallest optimality error among the iterates of the regular phase, each the larger of Ipopt's
  /// overall NLP error (scaled: the quantity it compares with its tolerance) and its unscaled version; +∞
  /// when there were none.
  double smallest_error = std::numeric_limits<double>::infinity();
  std::vector<double> x;  ///< the last iterate (the start when Ipopt stopped before finalising)
  std::vector<double>
      y;  ///< constraint multipliers (Lagrangian σ f + yᵀg); empty when Ipopt did not finalise
};

/// Solves `nlp` from `start` with Ipopt (exact Hessian; the barrier and start options of `settings`), with
/// OpenBLAS held at one thread while it runs (ipopt_solve.cpp: bit-identical results with a threaded
/// OpenBLAS). Throws ComputationFailed if Ipopt cannot be initialised; any other outcome is returned in
/// `status`.
NlpSolution solve_with_ipopt(const SparseNlp& nlp, const std::vector<double>& start,
                             const IpoptSettings& settings);

/// How many times one NLP is given to Ipopt before the direct methods give up on it: the first settings and
/// two restarts (restart_settings).
inline constexpr int kIpoptAttempts = 3;

/// The settings of attempt `attempt` (0 to kIpoptAttempts − 1) on one NLP, from the same start, after the
/// attempts before it failed: 0 is `first` (its iterations capped at first_attempt_max_iterations); 1 the
/// monotone (Fiacco–McCormick) barrier from μ = 1e-4 with the start kept off its bounds by 1e-9 only
/// (IpoptSettings::warm_start), for a start that is near a solution where the adaptive barrier wandered off;
/// 2 the first settings with the warm start, Ipopt's own μ_init and twice the iterations. Both restarts start
/// the bound multipliers at 1 (Ipopt's default), whatever `first` did. Throws InvalidInput for another
/// attempt number.
IpoptSettings restart_settings(const IpoptSettings& first, int attempt);

/// `base` for a start at the solution of a nearby program (a previous mesh's optimum, on its bounds): the
/// start kept off its bounds by 1e-9 only (IpoptSettings::warm_start), the barrier from μ = 1e-6 and the
/// bound multipliers from μ/slack (IpoptSettings::bound_multipliers_from_barrier), so that Ipopt starts with
/// the complementarity of a converged iterate instead of pushing the start off its active bounds.
IpoptSettings near_solution_settings(IpoptSettings base);

/// What solve_with_restarts did.
struct RestartedSolution {
  NlpSolution solution;  ///< of the accepted attempt, else of the last one
  int iterations = 0;    ///< Ipopt iterations of every attempt
  int restarts = 0;      ///< Ipopt runs after the first (0 to kIpoptAttempts)
  bool accepted = false;
  /// The accepted solution is the first iterate of a stalled attempt that met nlp_stall_tolerance_factor
  /// times its tolerance.
  bool stalled = false;
};

/// Called after every Ipopt iteration of solve_with_restarts: the run (0: the first settings), then the
/// arguments of IpoptSettings::on_iteration.
using RestartProgress =
    std::function<void(int attempt, int iteration, double objective, double infeasibility)>;

/// Solves `nlp` from `start` with the settings `first`; while `accept` refuses the solution, again from the
/// same start with restart_settings' next settings, kIpoptAttempts attempts at most. The first attempt that
/// fails (neither solved nor acceptable) after an iterate came within nlp_stall_tolerance_factor of its
/// tolerance is run once more, at once, and stopped at that iterate (`stalled` when that is accepted).
/// `progress`, if not empty, sees every iteration, with the run's number (0: the first settings). Throws
/// what solve_with_ipopt throws.
RestartedSolution solve_with_restarts(const SparseNlp& nlp, const std::vector<double>& start,
                                      const IpoptSettings& first,
                                      const std::function<bool(const NlpSolution&)>& accept,
                                      const RestartProgress& progress = {});

}  // namespace poinsot::optimal::detail
