// Ipopt's view of a SparseNlp (sparse_nlp.hpp).
#include <dlfcn.h>
#include <IpIpoptApplication.hpp>
#include <IpIpoptCalculatedQuantities.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "sparse_nlp.hpp"

namespace poinsot::optimal::detail {
namespace {

/// OpenBLAS's function `name` in the process: through the already loaded libopenblas.so.0 (its symbols are
/// not global where a Python extension loaded it), else in the global scope; nullptr when absent (another
/// BLAS).
void* openblas_symbol(const char* name) {
  if (void* lib = dlopen("libopenblas.so.0", RTLD_LAZY | RTLD_NOLOAD)) {
    void* f = dlsym(lib, name);
    dlclose(lib);  // RTLD_NOLOAD took a reference: give it back (the library stays loaded)
    if (f != nullptr) return f;
  }
  return dlsym(RTLD_DEFAULT, name);
}

/// MUMPS' fill-reducing ordering of the KKT matrix (Ipopt's mumps_pivot_order, MUMPS' ICNTL(7)): 6, the
/// approximate minimum degree with quasi-dense rows detected (QAMD), which has no random choices. Ipopt's
/// default (7) lets MUMPS choose, and for the larger matrices (the phase-per-arc re-solve of a per-axis slew:
/// 8246 variables) it chose SCOTCH, whose ordering was not reproducible (also with SCOTCH's random generator
/// reset to a fixed seed at the start): the same problem gave other rounding and another Ipopt path from run
/// to run (6, 7 or 9 iterations, switch times differing by 1e-12 s). Of the reproducible orderings, QAMD
/// ended the most problems of the benchmark with an answer; plain AMD (0) was a quarter faster on the
/// two-link arm and the keep-out slews, and solved the tumbling racket with the reference BLAS in 164 s where
/// QAMD had not finished after eight minutes, but left two more problems of seed 2 at the CPU limit
/// (measurements/optimal_control.md, "Speed").
constexpr int kMumpsOrderingQamd = 6;

/// MUMPS' column permutation of the KKT matrix before its ordering (Ipopt's mumps_permuting_scaling, MUMPS'
/// ICNTL(6)): 0, none. Ipopt's default (7) lets MUMPS choose, and on these symmetric indefinite matrices it
/// computed a maximum weighted matching (`dmumps_mtransw`) at every analysis: 11 % of the CPU of a
/// rate-bounded slew refined to 1550 intervals (`perf`). Without it the benchmark's per_axis, spin,
/// nonprincipal and rate families took 0.53 to 0.76 of the CPU and the others 0.92 to 1.04. Of 288 problems
/// compared, 287 ended as before; one converged to a local optimum that Ipopt, stalling there, had left
/// before (measurements/optimal_control.md, "Speed"). MUMPS' threshold pivoting keeps the factorisation
/// stable without the matching; Ipopt's gradient-based NLP scaling stays.
constexpr int kMumpsNoColumnPermutation = 0;

/// One BLAS thread while Ipopt runs, so that its results are bit-identical from run to run on a machine.
/// MUMPS calls the BLAS that Debian's alternatives select for libblas.so.3: the reference BLAS, or OpenBLAS
/// (scripts/setup.sh installs it). A threaded OpenBLAS may split a product's sums between threads, whose
/// number then changes the rounding, and Ipopt's path with it. OpenBLAS's `openblas_get_num_threads` and
/// `openblas_set_num_threads` are looked up at run time (no link dependency: with another BLAS they are
/// absent and nothing is done); one thread is set for the object's lifetime, the previous count restored.
class SingleBlasThread {
 public:
  using GetThreads = int (*)();
  using SetThreads = void (*)(int);
  SingleBlasThread()
      : get_(reinterpret_cast<GetThreads>(openblas_symbol("openblas_get_num_threads"))),
        set_(reinterpret_cast<SetThreads>(openblas_symbol("openblas_set_num_threads"))) {
    if (get_ == nullptr || set_ == nullptr) return;
    previous_ = get_();
    if (previous_ != 1) set_(1);
  }
  ~SingleBlasThread() {
    if (previous_ > 1) set_(previous_);
  }
  SingleBlasThread(const SingleBlasThread&) = delete;
  SingleBlasThread& operator=(const SingleBlasThread&) = delete;

 private:
  GetThreads get_ = nullptr;
  SetThreads set_ = nullptr;
  int previous_ = 0;
};

class SparseNlpAdapter : public Ipopt::TNLP {
 public:
  SparseNlpAdapter(const SparseNlp& nlp, const std::vector<double>& start, const IpoptSettings& settings)
      : nlp_(nlp), x_(start), settings_(settings) {}

  bool get_nlp_info(Ipopt::Index& n, Ipopt::Index& m, Ipopt::Index& nnz_jac, Ipopt::Index& nnz_h,
                    IndexStyleEnum& style) override {
    n = nlp_.num_variables();
    m = nlp_.num_constraints();
    nnz_jac = nlp_.jacobian_nonzeros();
    nnz_h = nlp_.hessian_nonzeros();
    style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Ipopt::Index, Ipopt::Number* xl, Ipopt::Number* xu, Ipopt::Index, Ipopt::Number* gl,
                       Ipopt::Number* gu) override {
    std::vector<double> a, b, c, d;
    nlp_.bounds(a, b, c, d);
    std::copy(a.begin(), a.end(), xl);
    std::copy(b.begin(), b.end(), xu);
    std::copy(c.begin(), c.end(), gl);
    std::copy(d.begin(), d.end(), gu);
    return true;
  }
  bool get_starting_point(Ipopt::Index, bool init_x, Ipopt::Number* x, bool, Ipopt::Number*, Ipopt::Number*,
                          Ipopt::Index, bool, Ipopt::Number*) override {
    if (init_x) std::copy(x_.begin(), x_.end(), x);
    return true;
  }
  bool eval_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number& f) override {
    f = nlp_.objective(x);
    return std::isfinite(f);
  }
  bool eval_grad_f(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number* g) override {
    nlp_.objective_gradient(x, g);
    return true;
  }
  bool eval_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index m, Ipopt::Number* g) override {
    nlp_.constraints(x, g);
    return std::all_of(g, g + m, [](double v) { return std::isfinite(v); });
  }
  bool eval_jac_g(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Index, Ipopt::Index, Ipopt::Index* rows,
                  Ipopt::Index* cols, Ipopt::Number* values) override {
    if (values == nullptr)
      nlp_.jacobian_structure(rows, cols);
    else
      nlp_.jacobian_values(x, values);
    return true;
  }
  bool eval_h(Ipopt::Index, const Ipopt::Number* x, bool, Ipopt::Number sigma, Ipopt::Index,
              const Ipopt::Number* lambda, bool, Ipopt::Index, Ipopt::Index* rows, Ipopt::Index* cols,
              Ipopt::Number* values) override {
    if (values == nullptr)
      nlp_.hessian_structure(rows, cols);
    else
      nlp_.hessian_values(x, sigma, lambda, values);
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Ipopt::Index n, const Ipopt::Number* x, const Ipopt::Number*,
                         const Ipopt::Number*, Ipopt::Index m, const Ipopt::Number*,
                         const Ipopt::Number* lambda, Ipopt::Number f, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    x_.assign(x, x + n);
    y_.assign(lambda, lambda + m);
    f_ = f;
  }
  bool intermediate_callback(Ipopt::AlgorithmMode mode, Ipopt::Index iteration, Ipopt::Number objective,
                             Ipopt::Number infeasibility, Ipopt::Number, Ipopt::Number, Ipopt::Number,
                             Ipopt::Number, Ipopt::Number, Ipopt::Number, Ipopt::Index,
                             const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities* quantities) override {
    // The restoration phase's quantities are those of its own problem, not of this NLP.
    if (mode == Ipopt::RegularMode && quantities != nullptr) {
      // The scaled error is Ipopt's own test; the unscaled one keeps large multipliers (dependent
      // constraints) from scaling a poor iterate's dual infeasibility away.
      const double error = std::max(quantities->curr_nlp_error(), quantities->unscaled_curr_nlp_error());
      smallest_error_ = std::min(smallest_error_, error);
      stopped_at_error_ = settings_.stop_at_error > 0.0 && error <= settings_.stop_at_error;
    }
    if (settings_.on_iteration) settings_.on_iteration(iteration, objective, infeasibility);
    return !stopped_at_error_;
  }

  const std::vector<double>& x() const { return x_; }
  const std::vector<double>& y() const { return y_; }
  double f() const { return f_; }
  double smallest_error() const { return smallest_error_; }
  /// The run was stopped at an iterate that met IpoptSettings::stop_at_error.
  bool stopped_at_error() const { return stopped_at_error_; }

 private:
  const SparseNlp& nlp_;
  std::vector<double> x_, y_;
  const IpoptSettings& settings_;
  double f_ = 0.0;
  double smallest_error_ = std::numeric_limits<double>::infinity();
  bool stopped_at_error_ = false;
};

const char* status_words(Ipopt::ApplicationReturnStatus s) {
  switch (s) {
    case Ipopt::Solve_Succeeded:
      return "solved";
    case Ipopt::Solved_To_Acceptable_Level:
      return "solved to the acceptable level only";
    case Ipopt::Infeasible_Problem_Detected:
      return "infeasible problem detected";
    case Ipopt::Search_Direction_Becomes_Too_Small:
      return "search direction too small";
    case Ipopt::Diverging_Iterates:
      return "diverging iterates";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "maximum iterations exceeded";
    case Ipopt::Restoration_Failed:
      return "restoration failed";
    case Ipopt::Error_In_Step_Computation:
      return "error in step computation";
    case Ipopt::Maximum_CpuTime_Exceeded:
      return "maximum CPU time exceeded";
    case Ipopt::Invalid_Number_Detected:
      return "invalid number detected";
    default:
      return "failed";
  }
}

}  // namespace

IpoptSettings restart_settings(const IpoptSettings& first, int attempt) {
  if (attempt < 0 || attempt >= kIpoptAttempts) {
    throw InvalidInput(
        fmt::format("restart_settings: attempt {}; expected 0 to {}", attempt, kIpoptAttempts - 1));
  }
  IpoptSettings ipopt = first;
  if (attempt == 0 && first.first_attempt_max_iterations > 0)
    ipopt.max_iterations = std::min(first.max_iterations, first.first_attempt_max_iterations);
  if (attempt >= 1) {
    ipopt.warm_start = true;
    ipopt.bound_multipliers_from_barrier = false;
  }
  if (attempt == 1) {
    ipopt.mu_strategy = "monotone";
    ipopt.mu_init = 1e-4;
  }
  if (attempt == 2) {
    ipopt.mu_init = 0.0;
    ipopt.max_iterations = 2 * first.max_iterations;
  }
  return ipopt;
}

IpoptSettings near_solution_settings(IpoptSettings base) {
  base.warm_start = true;
  base.mu_init = 1e-6;
  base.bound_multipliers_from_barrier = true;
  return base;
}

RestartedSolution solve_with_restarts(const SparseNlp& nlp, const std::vector<double>& start,
                                      const IpoptSettings& first,
                                      const std::function<bool(const NlpSolution&)>& accept,
                                      const RestartProgress& progress) {
  RestartedSolution out;
  int run = 0;
  // One Ipopt run with `ipopt`; true when `accept` takes its solution.
  const auto solve = [&](IpoptSettings ipopt) {
    if (progress) {
      ipopt.on_iteration = [&progress, run](int iteration, double objective, double infeasibility) {
        progress(run, iteration, objective, infeasibility);
      };
    }
    out.solution = solve_with_ipopt(nlp, start, ipopt);
    out.iterations += out.solution.iterations;
    out.restarts = run++;
    out.accepted = accept(out.solution);
    return out.accepted;
  };
  bool stall_rerun = false;
  for (int attempt = 0; attempt < kIpoptAttempts; ++attempt) {
    const IpoptSettings ipopt = restart_settings(first, attempt);
    if (solve(ipopt)) break;
    const NlpSolution& failed = out.solution;
    if (stall_rerun || failed.solved || failed.acceptable ||
        !(failed.smallest_error <= nlp_stall_tolerance_factor * ipopt.tolerance))
      continue;
    stall_rerun = true;
    IpoptSettings retrace = ipopt;
    retrace.stop_at_error = nlp_stall_tolerance_factor * ipopt.tolerance;
    if (solve(retrace)) {
      out.stalled = true;
      break;
    }
  }
  return out;
}

NlpSolution solve_with_ipopt(const SparseNlp& nlp, const std::vector<double>& start,
                             const IpoptSettings& settings) {
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = new Ipopt::IpoptApplication(false);
  app->Options()->SetIntegerValue("print_level", settings.print_level);
  app->Options()->SetStringValue("sb", "yes");
  if (const char* f = std::getenv("POINSOT_IPOPT_LOG")) app->Options()->SetStringValue("output_file", f);
  app->Options()->SetNumericValue("tol", settings.tolerance);
  if (settings.acceptable_tolerance > 0.0)
    app->Options()->SetNumericValue("acceptable_tol", settings.acceptable_tolerance);
  app->Options()->SetIntegerValue("max_iter", settings.max_iterations);
  app->Options()->SetStringValue("hessian_approximation", "exact");
  app->Options()->SetStringValue("mu_strategy", settings.mu_strategy);
  if (settings.mu_init > 0.0) app->Options()->SetNumericValue("mu_init", settings.mu_init);
  if (settings.warm_start)
    for (const char* option : {"bound_push", "bound_frac", "slack_bound_push", "slack_bound_frac"})
      app->Options()->SetNumericValue(option, 1e-9);
  if (settings.bound_multipliers_from_barrier)
    app->Options()->SetStringValue("bound_mult_init_method", "mu-based");
  if (settings.exact_bounds) app->Options()->SetNumericValue("bound_relax_factor", 0.0);
  app->Options()->SetIntegerValue("mumps_scaling", settings.mumps_scaling);
  app->Options()->SetIntegerValue("mumps_pivot_order", kMumpsOrderingQamd);
  app->Options()->SetIntegerValue("mumps_permuting_scaling", kMumpsNoColumnPermutation);
  if (app->Initialize() != Ipopt::Solve_Succeeded) throw ComputationFailed("ipopt: initialisation failed");
  Ipopt::SmartPtr<SparseNlpAdapter> adapter = new SparseNlpAdapter(nlp, start, settings);
  const SingleBlasThread one_blas_thread;  // bit-identical results with a threaded OpenBLAS
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(adapter);
  NlpSolution out;
  const bool stopped = status == Ipopt::User_Requested_Stop && adapter->stopped_at_error();
  out.solved = status == Ipopt::Solve_Succeeded || stopped;
  out.acceptable = status == Ipopt::Solved_To_Acceptable_Level;
  out.return_code = static_cast<int>(status);
  out.status = stopped ? fmt::format(
                             "solved to {} (optimality error), where Ipopt stalled above its "
                             "tolerance {}",
                             settings.stop_at_error, settings.tolerance)
                       : status_words(status);
  if (auto stats = app->Statistics(); Ipopt::IsValid(stats)) out.iterations = stats->IterationCount();
  out.x = adapter->x();
  out.y = adapter->y();
  out.objective = adapter->f();
  out.smallest_error = adapter->smallest_error();
  return out;
}

}  // namespace poinsot::optimal::detail
