// The Λ lines of the report (src/io/run/run_lambda.cpp).
#include "../../../src/io/run/run_lambda.hpp"

#include <gtest/gtest.h>

#include <string>

namespace poinsot::io::detail {
namespace {

std::string joined(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines)
    out += l + "\n";
  return out;
}

TEST(RunLambda, AxisymmetricBodyShowsTheClosedForm) {
  const auto body = dynamics::RigidBody::from_principal_moments(Vec3(2, 2, 3));
  dynamics::State s;
  s.omega_body = Vec3(0.3, 0.0, 1.0);
  const analysis::LambdaTracker tr(body, nullptr, s);
  const std::string text = joined(lambda_lines(tr.properties()));
  EXPECT_NE(text.find("closed form (axisymmetric, A = 2, C = 3 kg·m²)"), std::string::npos) << text;
  EXPECT_NE(text.find("constant by the paper's theorem"), std::string::npos) << text;
  // tr Λ = −2T: T = ½(2·0.09 + 3) = 1.59 J, so the eigenvalues sum to −3.18 J.
  const Vec3 ev = tr.properties().eigenvalues_initial;
  EXPECT_NEAR(ev.sum(), -3.18, 1e-14);
}

TEST(RunLambda, AsymmetricBodySaysTheTheoremDoesNotApply) {
  const auto body = dynamics::RigidBody::from_principal_moments(Vec3(1, 2, 3));
  dynamics::State s;
  s.omega_body = Vec3(0.3, 1.0, 0.2);
  const analysis::LambdaTracker tr(body, nullptr, s);
  const std::string text = joined(lambda_lines(tr.properties()));
  EXPECT_NE(text.find("the theorem needs an axisymmetric body"), std::string::npos) << text;
  EXPECT_EQ(text.find("closed form"), std::string::npos) << text;
  EXPECT_NE(text.find("∫σ dv = −R Λ Rᵀ"), std::string::npos);
}

}  // namespace
}  // namespace poinsot::io::detail
