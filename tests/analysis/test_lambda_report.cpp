#include "poinsot/analysis/lambda_report.hpp"

#include <cmath>

#include "errata_cases.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot_test.hpp"

namespace poinsot::analysis {
namespace {
using dynamics::RigidBody;
using dynamics::State;
using test::kEps;

State initial_state(const Vec3& w) {
  State s;
  s.omega_body = w;
  return s;
}

LambdaAnalysisOptions opts(const std::string& method, double dt, double t_end, double sample_dt = 0.1) {
  LambdaAnalysisOptions o;
  o.method = method;
  o.integrator.dt = dt;
  o.t_end = t_end;
  o.sample_dt = sample_dt;
  return o;
}

using errata::kOmegaB;
using errata::kOmegaC;
const RigidBody kProlate =
    RigidBody::from_principal_moments(Vec3(2.0, 2.0, 1.0));  // docs/conventions.md case b
const RigidBody kOblate =
    RigidBody::from_principal_moments(Vec3(1.0, 1.0, 1.8));  // docs/conventions.md case c

TEST(LambdaReport, ExactSolutionKeepsTheEigenvaluesToRoundOff) {
  for (const auto& [body, w] : {std::pair{kProlate, kOmegaB}, std::pair{kOblate, kOmegaC}}) {
    const LambdaReport r = analyse_lambda(body, initial_state(w), opts("exact", 0.0, 20.0));
    ASSERT_TRUE(r.properties.closed_form.has_value());
    const double scale = r.properties.lambda_scale;
    // The exact solution's ω(t) is accurate to a few ulp of |ω|; Λ is quadratic in ω.
    EXPECT_LE(r.properties.closed_form->max_deviation, 1e-13 * scale);
    EXPECT_LE(r.properties.eigenvalue_max_variation, 1e-13 * scale);
    EXPECT_LE(r.properties.closed_form->eigenvector_residual_max, 1e-13 * scale);
    // EᵀΛE constant (Property 3): this also fails if the trajectory does not precess at (C/A − 1)μ.
    EXPECT_LE(r.properties.closed_form->constant_matrix_deviation_max, 1e-13 * scale);
    EXPECT_GT((r.properties.lambda_final - r.properties.lambda_initial).norm(), 0.1 * scale);
    EXPECT_LE(r.properties.max_eigenvalue_max, 1e-14 * scale);
    EXPECT_EQ(r.properties.samples, 201);
    EXPECT_EQ(r.method, "exact");
  }
}

TEST(LambdaReport, RandomAxisymmetricBodiesExactAndRk4) {
  // Constant to round-off with exact, to the method's error with rk4 (dt = 1e-2 s, |ω| ≤ √3 rad/s, 5 s:
  // global error ~ (ω dt)⁴ · ω t ~ 1e-8).
  for (int i = 0; i < 10; ++i) {
    const double A = test::uniform(0.5, 3.0);
    const double C = test::uniform(0.1, 2.0 * A);
    const Mat3 Q = test::random_rotation();
    const RigidBody body = RigidBody::from_inertia(Q * Vec3(A, A, C).asDiagonal() * Q.transpose());
    State s0 = initial_state(test::random_vector(1.0));
    s0.R_space_body = test::random_rotation();
    const LambdaReport exact = analyse_lambda(body, s0, opts("exact", 0.0, 5.0));
    const LambdaReport rk4 = analyse_lambda(body, s0, opts("rk4", 1e-2, 5.0));
    ASSERT_TRUE(exact.properties.closed_form.has_value());
    ASSERT_TRUE(rk4.properties.closed_form.has_value());
    const double scale = std::max(1e-3, exact.properties.lambda_scale);
    EXPECT_LE(exact.properties.closed_form->max_deviation, 1e-12 * scale);
    EXPECT_LE(rk4.properties.closed_form->max_deviation, 1e-7 * scale);
    EXPECT_LE(exact.properties.closed_form->constant_matrix_deviation_max, 1e-12 * scale);
    EXPECT_LE(rk4.properties.closed_form->constant_matrix_deviation_max, 1e-7 * scale);
  }
}

TEST(LambdaReport, RattleMultipliersConvergeAtOrderTwo) {
  // Λ from rattle's last_multiplier (midpoint of the step) against (j(ω)² + j(ω̇))K at that midpoint: the
  // deviation must fall by 4 when the step halves. Asymmetric and axisymmetric bodies.
  for (const auto& [body, w] :
       {std::pair{RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0)), Vec3(1.0, 0.5, 0.3)},
        std::pair{kOblate, kOmegaC}}) {
    double previous = 0.0;
    for (const double dt : {0.02, 0.01, 0.005}) {
      const LambdaReport r = analyse_lambda(body, initial_state(w), opts("rattle", dt, 2.0));
      ASSERT_TRUE(r.properties.has_integrator_multiplier);
      const double dev = r.properties.integrator_multiplier_deviation_max;
      EXPECT_LE(r.properties.integrator_multiplier_symmetry_error_max, 1e-12 * r.properties.lambda_scale);
      if (previous > 0.0) {
        const double order = std::log2(previous / dev);
        EXPECT_NEAR(order, 2.0, 0.15) << "dt = " << dt << ", deviation " << dev;
      }
      previous = dev;
    }
    EXPECT_LE(previous, 1e-3 * body.principal_moments()[2] * w.squaredNorm());
  }
}

TEST(LambdaReport, GeneralBodyReportsVariationNotClosedForm) {
  const RigidBody body = RigidBody::from_principal_moments(Vec3(2.0, 3.0, 4.0));
  const LambdaReport r = analyse_lambda(body, initial_state(Vec3(1.0, 0.5, 0.3)), opts("dop853", 0.1, 3.0));
  EXPECT_FALSE(r.properties.closed_form.has_value());
  EXPECT_NEAR(r.properties.eigenvalues_final[0], -2.3779, 5e-5);  // docs/conventions.md C3
  EXPECT_NEAR(r.properties.eigenvalues_final[1], -0.6791, 5e-5);
  EXPECT_NEAR(r.properties.eigenvalues_final[2], -0.0530, 5e-5);
  EXPECT_GE(r.properties.eigenvalue_max_variation, 0.1);
  const std::string text = format_lambda_report(r);
  EXPECT_NE(text.find("not constant"), std::string::npos);
}

TEST(LambdaReport, HeavyTopWithGravity) {
  // A top on a pivot under gravity: Λ's skew part is the torque, tr Λ = −2T still; no closed form.
  const RigidBody top =
      RigidBody::from_principal_moments(Vec3(0.5, 0.5, 0.8)).with_pivot(1.0, Vec3(0, 0, 0.1));
  LambdaAnalysisOptions o = opts("rattle", 1e-3, 1.0);
  o.torque = dynamics::TorqueModel::gravity(top, Vec3(0, 0, -9.81));
  State s0 = initial_state(Vec3(0.1, 0.0, 30.0));
  s0.R_space_body = Eigen::AngleAxisd(0.5, Vec3::UnitX()).toRotationMatrix();
  const LambdaReport r = analyse_lambda(top, s0, o);
  EXPECT_FALSE(r.properties.torque_free);
  EXPECT_FALSE(r.properties.closed_form.has_value());
  EXPECT_LE(r.properties.symmetry_error_max, 1e-12 * r.properties.lambda_scale);
  EXPECT_LE(r.properties.trace_plus_2T_max, 1e-12 * r.properties.lambda_scale);
  // rattle's multipliers (torque kicks included) still converge to (j(ω)² + j(ω̇))K at order 2, and their
  // skew part to j(τ).
  double previous = 0.0, previous_sym = 0.0;
  for (const double dt : {0.004, 0.002, 0.001}) {
    o.integrator.dt = dt;
    o.sample_dt = 0.02;
    const LambdaReport q = analyse_lambda(top, s0, o);
    const double dev = q.properties.integrator_multiplier_deviation_max;
    const double sym = q.properties.integrator_multiplier_symmetry_error_max;
    if (previous > 0.0) {
      EXPECT_NEAR(std::log2(previous / dev), 2.0, 0.15) << "dt = " << dt;
      EXPECT_NEAR(std::log2(previous_sym / sym), 2.0, 0.15) << "dt = " << dt;
    }
    previous = dev;
    previous_sym = sym;
  }
}

TEST(LambdaReport, LaminaRuns) {
  const RigidBody lamina = RigidBody::from_principal_moments(Vec3(1.0, 2.0, 3.0));
  for (const char* method : {"rk4", "rattle", "exact"}) {
    const LambdaReport r =
        analyse_lambda(lamina, initial_state(Vec3(0.4, 1.0, -0.6)), opts(method, 1e-2, 3.0));
    EXPECT_TRUE(r.properties.lambda_final.allFinite()) << method;
    EXPECT_LE(r.properties.max_eigenvalue_max, 1e-13 * r.properties.lambda_scale) << method;
  }
}

TEST(LambdaReport, BadInputIsRejected) {
  EXPECT_THROW(analyse_lambda(kProlate, initial_state(kOmegaB), opts("euler", 1e-2, 1.0)), InvalidInput);
  EXPECT_THROW(analyse_lambda(kProlate, initial_state(kOmegaB), opts("rk4", 1e-2, -1.0)), InvalidInput);
  LambdaAnalysisOptions o = opts("exact", 0.0, 1.0);
  o.torque = dynamics::TorqueModel::constant_body(Vec3(1, 0, 0));
  EXPECT_THROW(analyse_lambda(kProlate, initial_state(kOmegaB), o), InvalidInput);
}

}  // namespace
}  // namespace poinsot::analysis
