// The exact derivatives of the differential-algebraic Hermite–Simpson NLP, for both multibody point models
// (rotation-matrix and minimal coordinates), against central finite differences.
#include "../../src/optimal/hermite_simpson_nlp.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <random>
#include <utility>

#include "../../src/optimal/multibody_minimal_model.hpp"
#include "../../src/optimal/multibody_rotation_model.hpp"
#include "multibody_test_problems.hpp"

namespace poinsot::optimal::detail {
namespace {

Eigen::MatrixXd dense_jacobian(const SparseNlp& nlp, const std::vector<double>& x) {
  const auto nnz = static_cast<std::size_t>(nlp.jacobian_nonzeros());
  std::vector<int> rows(nnz), cols(nnz);
  std::vector<double> values(nnz);
  nlp.jacobian_structure(rows.data(), cols.data());
  nlp.jacobian_values(x.data(), values.data());
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(nlp.num_constraints(), nlp.num_variables());
  for (std::size_t e = 0; e < nnz; ++e)
    J(rows[e], cols[e]) += values[e];  // duplicates add, as in Ipopt
  return J;
}

// ∇(σ f + yᵀ g) at x.
Eigen::VectorXd lagrangian_gradient(const SparseNlp& nlp, const std::vector<double>& x, double sigma,
                                    const Eigen::VectorXd& y) {
  Eigen::VectorXd grad(nlp.num_variables());
  nlp.objective_gradient(x.data(), grad.data());
  return sigma * grad + dense_jacobian(nlp, x).transpose() * y;
}

// Checks ∂g/∂x and the lower triangle of ∇²(σ f + yᵀg) against central differences with step ε = 1e-6. The
// difference quotients of the constraints (at most cubic in a step along one variable for the rotation-matrix
// model, smooth for the minimal one) carry an error of order ε² · |third derivative| + 1e-16 / ε, about 1e-10
// here; the tolerance 1e-6 (relative to the entry's size, at least 1) leaves a wide margin and still catches
// a wrong or missing entry, whose size is of order 1.
void check_derivatives(const SparseNlp& nlp, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> d(-1.0, 1.0);
  std::vector<double> x(static_cast<std::size_t>(nlp.num_variables()));
  for (double& v : x)
    v = d(rng);
  Eigen::VectorXd y(nlp.num_constraints());
  for (Eigen::Index i = 0; i < y.size(); ++i)
    y(i) = d(rng);
  const double sigma = 0.7;
  const double eps = 1e-6;
  const Eigen::MatrixXd J = dense_jacobian(nlp, x);
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(nlp.num_variables(), nlp.num_variables());
  {
    const auto nnz = static_cast<std::size_t>(nlp.hessian_nonzeros());
    std::vector<int> rows(nnz), cols(nnz);
    std::vector<double> values(nnz);
    nlp.hessian_structure(rows.data(), cols.data());
    nlp.hessian_values(x.data(), sigma, y.data(), values.data());
    for (std::size_t e = 0; e < nnz; ++e) {
      ASSERT_GE(rows[e], cols[e]);
      H(rows[e], cols[e]) += values[e];
    }
  }
  Eigen::VectorXd gp(nlp.num_constraints()), gm(nlp.num_constraints());
  double worst_jacobian = 0.0, worst_hessian = 0.0;
  for (int i = 0; i < nlp.num_variables(); ++i) {
    std::vector<double> xp = x, xm = x;
    xp[static_cast<std::size_t>(i)] += eps;
    xm[static_cast<std::size_t>(i)] -= eps;
    nlp.constraints(xp.data(), gp.data());
    nlp.constraints(xm.data(), gm.data());
    const Eigen::VectorXd fd = (gp - gm) / (2.0 * eps);
    for (Eigen::Index r = 0; r < fd.size(); ++r)
      worst_jacobian = std::max(worst_jacobian, std::abs(fd(r) - J(r, i)) / std::max(1.0, std::abs(J(r, i))));
    const Eigen::VectorXd hd =
        (lagrangian_gradient(nlp, xp, sigma, y) - lagrangian_gradient(nlp, xm, sigma, y)) / (2.0 * eps);
    for (int j = i; j < nlp.num_variables(); ++j)  // column i of the lower triangle
      worst_hessian = std::max(worst_hessian, std::abs(hd(j) - H(j, i)) / std::max(1.0, std::abs(H(j, i))));
  }
  EXPECT_LT(worst_jacobian, 1e-6);
  EXPECT_LT(worst_hessian, 1e-6);
  // The objective's gradient: Simpson's rule of Σu², exact by hand.
  Eigen::VectorXd grad(nlp.num_variables());
  nlp.objective_gradient(x.data(), grad.data());
  for (int i = 0; i < nlp.num_variables(); ++i) {
    std::vector<double> xp = x, xm = x;
    xp[static_cast<std::size_t>(i)] += eps;
    xm[static_cast<std::size_t>(i)] -= eps;
    EXPECT_NEAR((nlp.objective(xp.data()) - nlp.objective(xm.data())) / (2.0 * eps), grad(i), 1e-7);
  }
}

// The transcription at the fixed final time T, on N equal intervals or on the given fractions.
HermiteSimpsonNlp at_fixed_time(const CollocationModel& model, int N, double T, const Eigen::VectorXd& y0,
                                const Eigen::MatrixXd& rows, const Eigen::VectorXd& values,
                                std::vector<double> fractions = {}) {
  return HermiteSimpsonNlp(
      model,
      fractions.empty() ? CollocationMesh::uniform(N) : CollocationMesh::from_fractions(std::move(fractions)),
      y0, rows, values, CollocationTime::at(T), CollocationObjective{0.0, 1.0});
}

// The transcription with a free final time T ∈ [0.5, 3] s and the objective T + 0.3 ∫ Σ u² dt.
HermiteSimpsonNlp at_free_time(const CollocationModel& model, CollocationMesh mesh, const Eigen::VectorXd& y0,
                               const Eigen::MatrixXd& rows, const Eigen::VectorXd& values) {
  const auto phases = static_cast<std::size_t>(mesh.phases());
  return HermiteSimpsonNlp(
      model, std::move(mesh), y0, rows, values,
      CollocationTime{0.0, std::vector<double>(phases, 0.5), std::vector<double>(phases, 3.0)},
      CollocationObjective{1.0, 0.3});
}

TEST(HermiteSimpsonNlp, RotationMatrixModelDerivativesAreExact) {
  MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 2);
  p.actuators.push_back({ActuatorKind::body_torque, 1, 5.0});  // a body torque as well
  const MultibodyRotationModel model(p);
  const Eigen::VectorXd y0 = model.state_vector(p.initial_state);
  const Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(3, model.state_size());
  const HermiteSimpsonNlp nlp = at_fixed_time(model, 1, 1.5, y0, rows, Eigen::VectorXd::Zero(3));
  check_derivatives(nlp, 7);
}

TEST(HermiteSimpsonNlp, MinimalModelDerivativesAreExact) {
  const MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 2);
  const MultibodyMinimalModel model(p);
  const Eigen::VectorXd y0 = model.state_vector(p.initial_state);
  const Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(4, 4);
  const HermiteSimpsonNlp nlp = at_fixed_time(model, 2, 1.5, y0, rows, Eigen::VectorXd::Zero(4));
  check_derivatives(nlp, 11);
}

TEST(HermiteSimpsonNlp, FloatingBaseMinimalModelDerivativesAreExact) {
  // The base's quaternion (of any norm: R(e/|e|)), its angular velocity and the centre of mass eliminated.
  const MultibodyProblem p = testing::offset_reaction_wheel();
  const MultibodyMinimalModel model(p);
  ASSERT_TRUE(model.tree().floating);
  const Eigen::VectorXd y0 = model.state_vector(p.initial_state);
  const Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(3, model.state_size());
  const HermiteSimpsonNlp nlp = at_fixed_time(model, 2, 1.5, y0, rows, Eigen::VectorXd::Zero(3));
  check_derivatives(nlp, 29);
}

TEST(HermiteSimpsonNlp, BallJointMinimalModelDerivativesAreExact) {
  // The falling cat: a floating base and a ball joint (a relative quaternion) with three motors.
  const MultibodyProblem p = testing::falling_cat(0.5, 3.0, 1.0, 2);
  const MultibodyMinimalModel model(p);
  ASSERT_TRUE(model.tree().links[1].ball);
  const Eigen::VectorXd y0 = model.state_vector(p.initial_state);
  const Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(3, model.state_size());
  const HermiteSimpsonNlp nlp = at_fixed_time(model, 2, 1.0, y0, rows, Eigen::VectorXd::Zero(3));
  check_derivatives(nlp, 31);
}

TEST(HermiteSimpsonNlp, FreeFinalTimeDerivativesAreExact) {
  // T is the last variable: its Jacobian column (the defects' f-terms / T) and its Hessian row (the f-terms'
  // second derivatives / T, the objective's 2εŵu) against the same central differences.
  MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 2);
  p.actuators.push_back({ActuatorKind::body_torque, 1, 5.0});
  const MultibodyRotationModel rotation(p);
  const HermiteSimpsonNlp nlp_r =
      at_free_time(rotation, CollocationMesh::uniform(1), rotation.state_vector(p.initial_state),
                   Eigen::MatrixXd::Identity(3, rotation.state_size()), Eigen::VectorXd::Zero(3));
  ASSERT_EQ(nlp_r.num_variables(), nlp_r.time_index() + 1);
  check_derivatives(nlp_r, 13);
  const MultibodyProblem q = testing::two_link_arm(1.0, 0.5, 1.5, 2);
  const MultibodyMinimalModel minimal(q);
  const HermiteSimpsonNlp nlp_m =
      at_free_time(minimal, CollocationMesh::uniform(2), minimal.state_vector(q.initial_state),
                   Eigen::MatrixXd::Identity(4, 4), Eigen::VectorXd::Zero(4));
  check_derivatives(nlp_m, 17);
}

TEST(HermiteSimpsonNlp, UnequalMeshDerivativesAreExact) {
  // Intervals of T Δτ_k with unequal Δτ_k, at fixed and at free final time.
  const MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 3);
  const MultibodyMinimalModel minimal(p);
  const std::vector<double> fractions{0.2, 0.5, 0.3};
  const HermiteSimpsonNlp fixed =
      at_fixed_time(minimal, 3, 1.5, minimal.state_vector(p.initial_state), Eigen::MatrixXd::Identity(4, 4),
                    Eigen::VectorXd::Zero(4), fractions);
  std::vector<double> x(static_cast<std::size_t>(fixed.num_variables()), 0.0);
  EXPECT_DOUBLE_EQ(fixed.point_times(x.data())[3], 1.5 * 0.45);  // the second interval's midpoint
  check_derivatives(fixed, 19);
  const HermiteSimpsonNlp timed =
      at_free_time(minimal, CollocationMesh::from_fractions(fractions), minimal.state_vector(p.initial_state),
                   Eigen::MatrixXd::Identity(4, 4), Eigen::VectorXd::Zero(4));
  check_derivatives(timed, 23);
}

TEST(HermiteSimpsonNlp, PhasedMeshOfCoupledBodiesDerivativesAreExact) {
  // Phases are a property of the mesh, for coupled bodies as for one: two phases of the arm, each with its
  // own duration variable, a duplicated node and the state's continuity rows between them.
  const MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 3);
  const MultibodyMinimalModel minimal(p);
  const HermiteSimpsonNlp nlp = at_free_time(
      minimal, CollocationMesh::from_nodes({0.0, 0.4, 1.0, 0.0, 1.0}, {2, 1}),
      minimal.state_vector(p.initial_state), Eigen::MatrixXd::Identity(4, 4), Eigen::VectorXd::Zero(4));
  EXPECT_EQ(nlp.points(), 2 * 3 + 2);
  EXPECT_EQ(nlp.num_variables(), minimal.point_size() * nlp.points() + 2);
  // Rows: the defects, the path rows of every point, 4 continuity rows, the 4 final rows.
  EXPECT_EQ(nlp.num_constraints(), nlp.path_row(nlp.points()) + 4 + 4);
  check_derivatives(nlp, 37);
}

// The largest number of structural non-zeros in one column and in one row of the triplets (rows, cols).
std::pair<int, int> densest_line(const std::vector<int>& rows, const std::vector<int>& cols) {
  std::map<int, int> per_row, per_col;
  for (std::size_t e = 0; e < rows.size(); ++e) {
    ++per_row[rows[e]];
    ++per_col[cols[e]];
  }
  const auto largest = [](const std::map<int, int>& m) {
    int n = 0;
    for (const auto& [line, count] : m)
      n = std::max(n, count);
    return n;
  };
  return {largest(per_col), largest(per_row)};
}

TEST(HermiteSimpsonNlp, RotationMatrixSparsityGrowsByAFixedBlockPerInterval) {
  // The KKT matrix Ipopt factorises is banded only if no variable or row couples all intervals: at fixed T
  // the Jacobian's and the Hessian's non-zeros must grow by the same count per interval, and their densest
  // column and row must not grow with N (a dense line makes the sparse factorisation fill in). Counted on
  // the arm for N = 4, 8 and 16, exactly (structural counts, no tolerance).
  const MultibodyProblem p = testing::two_link_arm(1.0, 0.5, 1.5, 4);
  const MultibodyRotationModel model(p);
  const Eigen::VectorXd y0 = model.state_vector(p.initial_state);
  const Eigen::MatrixXd rows = Eigen::MatrixXd::Identity(model.state_size(), model.state_size());
  std::vector<int> jacobian, hessian;
  std::vector<std::pair<int, int>> jacobian_lines, hessian_lines;
  for (const int n : {4, 8, 16}) {
    const HermiteSimpsonNlp nlp = at_fixed_time(model, n, 1.5, y0, rows, y0);
    std::vector<int> r(static_cast<std::size_t>(nlp.jacobian_nonzeros())), c(r.size());
    nlp.jacobian_structure(r.data(), c.data());
    jacobian.push_back(nlp.jacobian_nonzeros());
    jacobian_lines.push_back(densest_line(r, c));
    r.resize(static_cast<std::size_t>(nlp.hessian_nonzeros()));
    c.resize(r.size());
    nlp.hessian_structure(r.data(), c.data());
    hessian.push_back(nlp.hessian_nonzeros());
    hessian_lines.push_back(densest_line(r, c));
  }
  EXPECT_EQ(jacobian[2] - jacobian[1], 2 * (jacobian[1] - jacobian[0]));
  EXPECT_EQ(hessian[2] - hessian[1], 2 * (hessian[1] - hessian[0]));
  EXPECT_EQ(jacobian_lines[2], jacobian_lines[0]);
  EXPECT_EQ(hessian_lines[2], hessian_lines[0]);
  // Per interval (a midpoint and a node): 2 × 48 defect rows and the point rows of two points; a few
  // thousand entries, not the 10⁴ of one dense interval block (118 variables × 116 rows per point).
  EXPECT_LT((jacobian[1] - jacobian[0]) / 4, 2 * 118 * 116 / 4);
}

}  // namespace
}  // namespace poinsot::optimal::detail
