// The exact derivatives of the Hermite–Simpson NLP against central finite differences.
#include "../../src/optimal/collocation_nlp.hpp"

#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <tuple>

#include "optimal_test_problems.hpp"
#include "poinsot/core/error.hpp"

namespace poinsot::optimal::detail {
namespace {

std::vector<double> random_point(const CollocationNlp& nlp, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> z(nlp.num_variables());
  for (auto& v : z)
    v = d(rng);
  for (int a = 0; a < nlp.phases() && nlp.free_time(); ++a)
    z[nlp.duration_index(a)] = 3.0 + d(rng);
  return z;
}

// Dense ∂g/∂z from the triplets.
Eigen::MatrixXd dense_jacobian(const CollocationNlp& nlp, const std::vector<double>& z) {
  const int nnz = nlp.jacobian_nonzeros();
  std::vector<int> r(nnz), c(nnz);
  std::vector<double> v(nnz);
  nlp.jacobian_structure(r.data(), c.data());
  nlp.jacobian_values(z.data(), v.data());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nlp.num_constraints(), nlp.num_variables());
  for (int i = 0; i < nnz; ++i)
    J(r[i], c[i]) += v[i];
  return J;
}

ReorientationProblem general_problem(TorqueBound bound, Objective objective, bool free_attitude) {
  ReorientationProblem p;
  Mat3 J;
  J << 3.0, 0.2, -0.1, 0.2, 2.5, 0.3, -0.1, 0.3, 2.0;  // a valid non-diagonal inertia
  p.inertia_body = J;
  p.bound = bound;
  p.torque_max = Vec3(1.0, 2.0, 3.0);
  p.attitude_final = Quat(Eigen::AngleAxisd(1.0, Vec3(1, 2, 3).normalized()));
  p.objective = objective;
  if (objective == Objective::minimum_energy) p.final_time = 10.0;
  if (objective == Objective::minimum_time_regularised) p.energy_weight = 0.3;
  p.free_final_attitude = free_attitude;
  return p;
}

// Central differences have error O(δ²·|f'''|) + O(ε/δ): with δ = 1e-6 and O(1) data, about 1e-9.
void expect_derivatives_match_central_differences(const CollocationNlp& nlp) {
  const std::vector<double> z = random_point(nlp, 7);
  const int n = nlp.num_variables(), m = nlp.num_constraints();
  const double delta = 1e-6;

  const Eigen::MatrixXd J = dense_jacobian(nlp, z);
  std::vector<double> grad(n);
  nlp.objective_gradient(z.data(), grad.data());
  for (int j = 0; j < n; ++j) {
    std::vector<double> zp = z, zm = z;
    zp[j] += delta;
    zm[j] -= delta;
    std::vector<double> gp(m), gm(m);
    nlp.constraints(zp.data(), gp.data());
    nlp.constraints(zm.data(), gm.data());
    for (int i = 0; i < m; ++i)
      ASSERT_NEAR(J(i, j), (gp[i] - gm[i]) / (2 * delta), 1e-8) << i << "," << j;
    EXPECT_NEAR(grad[j], (nlp.objective(zp.data()) - nlp.objective(zm.data())) / (2 * delta), 1e-8) << j;
  }

  // ∇²(σ f + yᵀg) by differences of the exact gradient σ∇f + Jᵀy.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  Eigen::VectorXd y(m);
  for (int i = 0; i < m; ++i)
    y[i] = d(rng);
  const double sigma = 0.7;
  const auto lagrangian_gradient = [&](const std::vector<double>& zz) {
    std::vector<double> g(n);
    nlp.objective_gradient(zz.data(), g.data());
    return Eigen::VectorXd(sigma * Eigen::Map<Eigen::VectorXd>(g.data(), n) +
                           dense_jacobian(nlp, zz).transpose() * y);
  };
  const int nnz = nlp.hessian_nonzeros();
  std::vector<int> r(nnz), c(nnz);
  std::vector<double> v(nnz);
  nlp.hessian_structure(r.data(), c.data());
  nlp.hessian_values(z.data(), sigma, y.data(), v.data());
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < nnz; ++i) {
    ASSERT_GE(r[i], c[i]);
    H(r[i], c[i]) += v[i];
    if (r[i] != c[i]) H(c[i], r[i]) += v[i];
  }
  for (int j = 0; j < n; ++j) {
    std::vector<double> zp = z, zm = z;
    zp[j] += delta;
    zm[j] -= delta;
    const Eigen::VectorXd col = (lagrangian_gradient(zp) - lagrangian_gradient(zm)) / (2 * delta);
    for (int i = 0; i < n; ++i)
      ASSERT_NEAR(H(i, j), col[i], 1e-7) << i << "," << j;
  }
}

class CollocationDerivatives : public ::testing::TestWithParam<std::tuple<TorqueBound, Objective, bool>> {};

TEST_P(CollocationDerivatives, JacobianAndHessianMatchCentralDifferences) {
  const auto [bound, objective, free_attitude] = GetParam();
  expect_derivatives_match_central_differences(
      CollocationNlp(general_problem(bound, objective, free_attitude), {0.0, 0.3, 0.55, 1.0}));
}

// Three phases (durations as variables, duplicated nodes, continuity rows, per-phase torque bounds).
TEST(CollocationPhases, JacobianAndHessianMatchCentralDifferences) {
  for (const auto& [bound, objective] :
       {std::pair{TorqueBound::per_axis, Objective::minimum_time_regularised},
        std::pair{TorqueBound::norm, Objective::minimum_time}}) {
    CollocationPhases phases;
    phases.intervals = {2, 1, 2};
    phases.torque_lower = {Vec3(-1, -2, -3), Vec3(1, -2, -3), Vec3(-1, 2, -3)};
    phases.torque_upper = {Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(-1, 2, 3)};
    const CollocationNlp nlp(general_problem(bound, objective, false),
                             {0.0, 0.4, 1.0, 0.0, 1.0, 0.0, 0.5, 1.0}, phases);
    EXPECT_EQ(nlp.phases(), 3);
    EXPECT_EQ(nlp.points(), 2 * 5 + 3);
    expect_derivatives_match_central_differences(nlp);
  }
}

// Keep-out and keep-in rows (qᵀAq, exact gradient 2Aq and Hessian 2A) on one phase and on three.
TEST(CollocationPointing, JacobianAndHessianMatchCentralDifferences) {
  ReorientationProblem p = general_problem(TorqueBound::norm, Objective::minimum_time, false);
  const int base_rows = CollocationNlp(p, {0.0, 0.3, 0.55, 1.0}).num_constraints();
  p.pointing.push_back({"sun", PointingKind::keep_out, Vec3(1, 0, 0), Vec3(0.6, 0.8, 0.0), 0.5});
  p.pointing.push_back({"earth", PointingKind::keep_in, Vec3(0, 0.6, -0.8), Vec3(0, 0, -1), 1.2});
  const CollocationNlp one(p, {0.0, 0.3, 0.55, 1.0});
  EXPECT_EQ(one.num_constraints(), base_rows + 2 * (one.points() - 1));
  expect_derivatives_match_central_differences(one);
  CollocationPhases phases;
  phases.intervals = {2, 1};
  phases.torque_lower = {Vec3::Constant(-1), Vec3::Constant(-1)};
  phases.torque_upper = {Vec3::Constant(1), Vec3::Constant(1)};
  const CollocationNlp two(p, {0.0, 0.4, 1.0, 0.0, 1.0}, phases);
  EXPECT_EQ(two.pointing_row(two.interval_first_point(2), 0), -1);  // the second phase's first point
  expect_derivatives_match_central_differences(two);
}

// Reaction wheels (skewed axes, a bias momentum and a spinning start, so L ≠ 0 and the gyroscopic term
// ω × Rᵀ(q) L is cubic): the dynamics' Jacobian and z-dependent Hessian, and the momentum-bound rows
// h_k = qᵀN_k q − g_kᵀω; on one phase and on two.
TEST(CollocationWheels, JacobianAndHessianMatchCentralDifferences) {
  for (const Objective objective : {Objective::minimum_energy, Objective::minimum_time_regularised}) {
    ReorientationProblem p = general_problem(TorqueBound::per_axis, objective, false);
    ReactionWheels w;
    w.axes_body.col(0) = Vec3(1.0, 0.2, -0.1).normalized();
    w.axes_body.col(1) = Vec3(0.1, 1.0, 0.3).normalized();
    w.axes_body.col(2) = Vec3(-0.2, 0.1, 1.0).normalized();
    w.spin_inertia = Vec3(0.1, 0.2, 0.15);
    w.momentum_initial = Vec3(0.4, -0.3, 0.8);
    w.momentum_max = Vec3(5.0, std::numeric_limits<double>::infinity(), 4.0);
    p.wheels = w;
    p.omega_initial = Vec3(0.2, -0.1, 0.3);
    const int without =
        CollocationNlp(general_problem(TorqueBound::per_axis, objective, false), {0.0, 0.3, 0.55, 1.0})
            .num_constraints();
    const CollocationNlp one(p, {0.0, 0.3, 0.55, 1.0});
    EXPECT_EQ(one.num_constraints(), without + 3 * (one.points() - 1));
    EXPECT_GE(one.momentum_row(1, 2), 0);
    EXPECT_EQ(one.momentum_row(0, 0), -1);
    expect_derivatives_match_central_differences(one);
  }
  ReorientationProblem p = general_problem(TorqueBound::per_axis, Objective::minimum_time, false);
  ReactionWheels w;
  w.spin_inertia = Vec3(0.1, 0.2, 0.15);
  w.momentum_initial = Vec3(0.4, -0.3, 0.8);
  w.momentum_max = Vec3::Constant(3.0);
  p.wheels = w;
  CollocationPhases phases;
  phases.intervals = {2, 1};
  phases.torque_lower = {Vec3::Constant(-1), Vec3::Constant(-1)};
  phases.torque_upper = {Vec3::Constant(1), Vec3::Constant(1)};
  expect_derivatives_match_central_differences(CollocationNlp(p, {0.0, 0.4, 1.0, 0.0, 1.0}, phases));
}

TEST(CollocationPhases, RefusesInconsistentPhases) {
  CollocationPhases phases;
  phases.intervals = {2, 1};
  phases.torque_lower = phases.torque_upper = {Vec3::Zero(), Vec3::Zero()};
  const auto p = general_problem(TorqueBound::per_axis, Objective::minimum_time, false);
  EXPECT_THROW(CollocationNlp(p, {0.0, 0.5, 1.0, 0.0}, phases), InvalidInput);
  EXPECT_THROW(CollocationNlp(general_problem(TorqueBound::per_axis, Objective::minimum_energy, false),
                              {0.0, 0.5, 1.0, 0.0, 1.0}, phases),
               InvalidInput);
}

INSTANTIATE_TEST_SUITE_P(AllObjectives, CollocationDerivatives,
                         ::testing::Values(std::tuple{TorqueBound::per_axis, Objective::minimum_time, false},
                                           std::tuple{TorqueBound::norm, Objective::minimum_energy, false},
                                           std::tuple{TorqueBound::per_axis,
                                                      Objective::minimum_time_regularised, false},
                                           std::tuple{TorqueBound::norm, Objective::minimum_time, true}));

}  // namespace
}  // namespace poinsot::optimal::detail
