// Ipopt behind the SparseNlp interface and the restarts of the direct methods: a two-variable program with a
// known optimum, solved; a warm start on an active bound, which stays there; the restart settings in their
// documented order; solve_with_restarts makes at most
// kIpoptAttempts attempts from the same start, stops at the first accepted one and counts every iteration; an
// attempt that stalls near its tolerance is retraced and stopped where it came within the factor.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../src/optimal/sparse_nlp.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/optimal/direct_collocation.hpp"

namespace poinsot::optimal::detail {
namespace {

/// min (x − 1)² + (y − 2)² subject to x + y = 1, |x|, |y| ≤ 10: the optimum (0, 1), multiplier y_g = 2
/// (∇f + y_g ∇g = 0). With x ≥ x_min > 0 instead, the optimum is on that bound: (x_min, 1 − x_min).
class Projection final : public SparseNlp {
 public:
  explicit Projection(double x_min = -10.0) : x_min_(x_min) {}
  int num_variables() const override { return 2; }
  int num_constraints() const override { return 1; }
  void bounds(std::vector<double>& xl, std::vector<double>& xu, std::vector<double>& gl,
              std::vector<double>& gu) const override {
    xl = {x_min_, -10.0};
    xu.assign(2, 10.0);
    gl.assign(1, 1.0);
    gu.assign(1, 1.0);
  }
  double objective(const double* x) const override {
    return (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 2.0) * (x[1] - 2.0);
  }
  void objective_gradient(const double* x, double* g) const override {
    g[0] = 2.0 * (x[0] - 1.0);
    g[1] = 2.0 * (x[1] - 2.0);
  }
  void constraints(const double* x, double* g) const override { g[0] = x[0] + x[1]; }
  int jacobian_nonzeros() const override { return 2; }
  void jacobian_structure(int* rows, int* cols) const override {
    rows[0] = rows[1] = 0;
    cols[0] = 0;
    cols[1] = 1;
  }
  void jacobian_values(const double*, double* v) const override { v[0] = v[1] = 1.0; }
  int hessian_nonzeros() const override { return 2; }
  void hessian_structure(int* rows, int* cols) const override {
    rows[0] = cols[0] = 0;
    rows[1] = cols[1] = 1;
  }
  void hessian_values(const double*, double sigma, const double*, double* v) const override {
    v[0] = v[1] = 2.0 * sigma;
  }

 private:
  double x_min_;
};

/// The projection with its constraint given twice, the second copy shifted by `gap`: x + y = 1 and
/// x + y = 1 + gap. The constraints' gradients are dependent and the two rows disagree by `gap`: a
/// near-singular KKT system whose rounding Ipopt cannot remove, in miniature. No iterate's constraint
/// violation, hence no scaled optimality error, falls below gap/2; the least-squares point is the projection
/// onto x + y = 1 + gap/2, (gap/4, 1 + gap/4).
class InconsistentProjection final : public SparseNlp {
 public:
  explicit InconsistentProjection(double gap) : gap_(gap) {}
  int num_variables() const override { return 2; }
  int num_constraints() const override { return 2; }
  void bounds(std::vector<double>& xl, std::vector<double>& xu, std::vector<double>& gl,
              std::vector<double>& gu) const override {
    xl.assign(2, -10.0);
    xu.assign(2, 10.0);
    gl = gu = {1.0, 1.0 + gap_};
  }
  double objective(const double* x) const override { return exact_.objective(x); }
  void objective_gradient(const double* x, double* g) const override { exact_.objective_gradient(x, g); }
  void constraints(const double* x, double* g) const override { g[0] = g[1] = x[0] + x[1]; }
  int jacobian_nonzeros() const override { return 4; }
  void jacobian_structure(int* rows, int* cols) const override {
    for (int k = 0; k < 4; ++k) {
      rows[k] = k / 2;
      cols[k] = k % 2;
    }
  }
  void jacobian_values(const double*, double* v) const override { v[0] = v[1] = v[2] = v[3] = 1.0; }
  int hessian_nonzeros() const override { return exact_.hessian_nonzeros(); }
  void hessian_structure(int* rows, int* cols) const override { exact_.hessian_structure(rows, cols); }
  void hessian_values(const double* x, double sigma, const double* y, double* v) const override {
    exact_.hessian_values(x, sigma, y, v);
  }

 private:
  Projection exact_;
  double gap_;
};

TEST(IpoptSolve, SolvesAProgramWithAKnownOptimum) {
  const NlpSolution s = solve_with_ipopt(Projection(), {3.0, -4.0}, IpoptSettings{});
  ASSERT_TRUE(s.solved) << s.status;
  EXPECT_NEAR(s.x[0], 0.0, 1e-9);  // Ipopt's tol 1e-10 on the scaled KKT error of a quadratic program
  EXPECT_NEAR(s.x[1], 1.0, 1e-9);
  EXPECT_NEAR(s.objective, 2.0, 1e-9);
  ASSERT_EQ(s.y.size(), 1u);
  EXPECT_NEAR(std::abs(s.y[0]), 2.0, 1e-8);  // the sign follows Ipopt's Lagrangian convention
}

TEST(IpoptSolve, RestartSettingsAreTheMonotoneBarrierThenTwiceTheIterations) {
  IpoptSettings first;
  first.max_iterations = 40;
  const IpoptSettings a0 = restart_settings(first, 0);
  const IpoptSettings a1 = restart_settings(first, 1);
  const IpoptSettings a2 = restart_settings(first, 2);
  EXPECT_EQ(a0.mu_strategy, "adaptive");
  EXPECT_FALSE(a0.warm_start);
  EXPECT_EQ(a1.mu_strategy, "monotone");
  EXPECT_EQ(a1.mu_init, 1e-4);
  EXPECT_TRUE(a1.warm_start);
  EXPECT_EQ(a1.max_iterations, 40);
  EXPECT_EQ(a2.mu_strategy, "adaptive");
  EXPECT_TRUE(a2.warm_start);
  EXPECT_EQ(a2.max_iterations, 80);
  EXPECT_THROW(restart_settings(first, kIpoptAttempts), InvalidInput);
  EXPECT_THROW(restart_settings(first, -1), InvalidInput);
}

// A cap on the first attempt's iterations (a start at a nearby optimum that has not converged by then is
// stalling) ends that attempt early and leaves the restarts their iterations: the projection from (3, −4)
// needs more than one iteration, so the first attempt, capped at one, fails, and the monotone restart
// solves it with the full limit.
TEST(IpoptSolve, TheFirstAttemptsCapLeavesTheRestartsTheirIterations) {
  IpoptSettings first;
  first.max_iterations = 40;
  first.first_attempt_max_iterations = 1;
  EXPECT_EQ(restart_settings(first, 0).max_iterations, 1);
  EXPECT_EQ(restart_settings(first, 1).max_iterations, 40);
  EXPECT_EQ(restart_settings(first, 2).max_iterations, 80);
  std::vector<int> last_iteration(kIpoptAttempts + 1, 0);  // by run: the attempts and at most one retrace
  const RestartedSolution r = solve_with_restarts(
      Projection(), {3.0, -4.0}, first, [](const NlpSolution& s) { return s.solved; },
      [&](int attempt, int iteration, double, double) {
        last_iteration[static_cast<std::size_t>(attempt)] = iteration;
      });
  ASSERT_TRUE(r.accepted);
  EXPECT_EQ(r.restarts, 1);
  EXPECT_EQ(last_iteration[0], 1);
  EXPECT_GT(last_iteration[1], 1);
}

// A refined mesh's first settings (a warm start with the bound multipliers from the barrier) are not carried
// into the restarts, which are those of a cold first attempt.
TEST(IpoptSolve, RestartsStartTheBoundMultipliersAtIpoptsDefault) {
  IpoptSettings warm;
  warm.warm_start = true;
  warm.mu_init = 1e-6;
  warm.bound_multipliers_from_barrier = true;
  EXPECT_TRUE(restart_settings(warm, 0).bound_multipliers_from_barrier);
  EXPECT_EQ(restart_settings(warm, 0).mu_init, 1e-6);
  const IpoptSettings a1 = restart_settings(warm, 1), a2 = restart_settings(warm, 2);
  EXPECT_FALSE(a1.bound_multipliers_from_barrier);
  EXPECT_EQ(a1.mu_init, 1e-4);
  EXPECT_FALSE(a2.bound_multipliers_from_barrier);
  EXPECT_EQ(a2.mu_init, 0.0);  // Ipopt's own
  EXPECT_TRUE(a2.warm_start);
}

// The projection with x ≥ 1/2 started at its optimum (1/2, 1/2), f = 5/2, on the active bound: Ipopt's
// defaults push the start 1e-2 off the bound and begin the barrier at μ = 0.1, and come back in several
// iterations; the warm start (push 1e-9, μ = 1e-6, the bound multiplier at μ/slack) stays there and needs
// fewer. Both end at the optimum.
TEST(IpoptSolve, AWarmStartOnAnActiveBoundStaysAtTheOptimum) {
  const std::vector<double> optimum{0.5, 0.5};
  const NlpSolution cold = solve_with_ipopt(Projection(0.5), optimum, IpoptSettings{});
  const NlpSolution warm =
      solve_with_ipopt(Projection(0.5), optimum, near_solution_settings(IpoptSettings{}));
  for (const NlpSolution* s : {&cold, &warm}) {
    ASSERT_TRUE(s->solved) << s->status;
    EXPECT_NEAR(s->x[0], 0.5, 1e-8);
    // Ipopt relaxes the bound by 1e-8 (bound_relax_factor), and f' = 4x = 2 along x + y = 1 there.
    EXPECT_NEAR(s->objective, 2.5, 3e-8);
  }
  EXPECT_LT(warm.iterations, cold.iterations);
}

TEST(IpoptSolve, RestartsStopAtTheFirstAcceptedAttemptAndCountEveryIteration) {
  const Projection nlp;
  const std::vector<double> start{3.0, -4.0};
  for (int accept_at = 0; accept_at <= kIpoptAttempts; ++accept_at) {
    int calls = 0, iterations = 0;
    std::vector<int> attempts_seen;
    const RestartedSolution r = solve_with_restarts(
        nlp, start, IpoptSettings{},
        [&](const NlpSolution& s) {
          iterations += s.iterations;
          return calls++ == accept_at;
        },
        [&](int attempt, int, double, double) {
          if (attempts_seen.empty() || attempts_seen.back() != attempt) attempts_seen.push_back(attempt);
        });
    const int made = accept_at < kIpoptAttempts ? accept_at + 1 : kIpoptAttempts;
    EXPECT_EQ(calls, made) << accept_at;
    EXPECT_EQ(r.accepted, accept_at < kIpoptAttempts) << accept_at;
    EXPECT_EQ(r.restarts, made - 1) << accept_at;
    EXPECT_EQ(r.iterations, iterations) << accept_at;
    ASSERT_EQ(static_cast<int>(attempts_seen.size()), made) << accept_at;
    for (int a = 0; a < made; ++a)
      EXPECT_EQ(attempts_seen[static_cast<std::size_t>(a)], a);
    // Every attempt starts from the same point and solves this program.
    EXPECT_TRUE(r.solution.solved);
    EXPECT_NEAR(r.solution.x[1], 1.0, 1e-9);
  }
}

}  // namespace
}  // namespace poinsot::optimal::detail

namespace poinsot::optimal::detail {
namespace {

// An attempt that stalls within nlp_stall_tolerance_factor of its tolerance is run again, once and at once,
// and stopped at the first iterate that meets the factor; one that stalls farther away is not, and the
// restarts go on.
TEST(IpoptSolve, AnAttemptThatStallsNearItsToleranceIsRetracedToTheFirstIterateWithinTheFactor) {
  IpoptSettings first;
  first.tolerance = 1e-10;
  first.acceptable_tolerance = first.tolerance;  // as the direct methods set it: no acceptable level below
  first.max_iterations = 60;
  const auto solved = [](const NlpSolution& s) { return s.solved || s.acceptable; };
  {
    // A gap of 1e-9: the error stays above 1e-10 but comes below 100 × 1e-10.
    const double gap = 1e-9;
    const InconsistentProjection nlp(gap);
    const NlpSolution alone = solve_with_ipopt(nlp, {3.0, -4.0}, first);
    ASSERT_FALSE(alone.solved || alone.acceptable) << alone.status;
    ASSERT_GT(alone.smallest_error, first.tolerance);
    ASSERT_LE(alone.smallest_error, nlp_stall_tolerance_factor * first.tolerance);
    const RestartedSolution r = solve_with_restarts(nlp, {3.0, -4.0}, first, solved);
    EXPECT_TRUE(r.accepted);
    EXPECT_TRUE(r.stalled);
    EXPECT_EQ(r.restarts, 1);  // the first settings, then their rerun, stopped where it met the factor
    EXPECT_TRUE(r.solution.solved) << r.solution.status;
    EXPECT_LE(r.solution.smallest_error, nlp_stall_tolerance_factor * first.tolerance);
    EXPECT_LT(r.solution.iterations, alone.iterations);  // the same path, stopped earlier
    EXPECT_NEAR(r.solution.x[0], gap / 4.0, 1e-8);       // the least-squares point, to 100 × 1e-10
    EXPECT_NEAR(r.solution.x[1], 1.0 + gap / 4.0, 1e-8);
  }
  {
    // A gap of 1e-6: no iterate comes within the factor; the three attempts fail, none retraced.
    const InconsistentProjection nlp(1e-6);
    const RestartedSolution r = solve_with_restarts(nlp, {3.0, -4.0}, first, solved);
    EXPECT_FALSE(r.accepted);
    EXPECT_FALSE(r.stalled);
    EXPECT_EQ(r.restarts, kIpoptAttempts - 1);
    EXPECT_GT(r.solution.smallest_error, nlp_stall_tolerance_factor * first.tolerance);
  }
}

}  // namespace
}  // namespace poinsot::optimal::detail
