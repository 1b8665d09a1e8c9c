// The one JSON form of the Λ report (io/run/lambda_json.hpp): the report holds every key of the properties
// with the same values, the values are the structs' (doubles round-trip exactly), a non-finite number is
// null, and summary.json's `lambda` is the same object.
#include "poinsot/io/run/lambda_json.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "poinsot/io/run/run.hpp"
#include "poinsot/io/run/summary.hpp"
#include "poinsot/io/scenario/scenario.hpp"

namespace poinsot::io {
namespace {

using nlohmann::json;

/// An axisymmetric free body (A = 1, C = 1.6) over 1 s with rattle: closed form and integrator multiplier.
analysis::LambdaReport axisymmetric_report() {
  analysis::LambdaAnalysisOptions o;
  o.method = "rattle";
  o.t_end = 1.0;
  o.sample_dt = 0.1;
  dynamics::State s0;
  s0.omega_body = Vec3(0.4, -0.3, 2.0);
  return analysis::analyse_lambda(dynamics::RigidBody::from_principal_moments(Vec3(1.0, 1.0, 1.6)), s0, o);
}

TEST(LambdaJson, ReportHoldsEveryPropertyWithTheStructsValues) {
  const analysis::LambdaReport r = axisymmetric_report();
  const json report = json::parse(lambda_report_json(r));
  const json props = json::parse(lambda_properties_json(r.properties));
  for (const auto& [key, value] : props.items())
    EXPECT_EQ(report.at(key), value) << key;
  EXPECT_EQ(report["method"], "rattle");
  EXPECT_EQ(report["steps"], r.steps);
  EXPECT_EQ(report["samples"], 11);
  EXPECT_EQ(report["t_end"], 1.0);
  const Mat3& L = r.properties.lambda_final;
  EXPECT_EQ(report["lambda_final"][1][2].get<double>(), L(1, 2));  // row by row, exact round trip
  const analysis::AxisymmetricCheck& c = *r.properties.closed_form;
  EXPECT_EQ(report["closed_form"]["Delta"].get<double>(), c.Delta);
  EXPECT_EQ(report["closed_form"]["special_cases"], json::parse(special_cases_json(c.special_cases)));
  EXPECT_EQ(report["stress_initial"], json::parse(stress_summary_json(r.properties.stress_initial.integral)));
  EXPECT_TRUE(report["mean_stress_initial"].is_null());  // no volume
  EXPECT_TRUE(report["integrator_multiplier"].is_object());
  EXPECT_EQ(report["invariant_errors"]["orthogonality_max"].get<double>(),
            r.invariant_errors.orthogonality_max);
  EXPECT_FALSE(report.contains("wall_time_s"));  // the text is deterministic
}

TEST(LambdaJson, NonFiniteNumbersAreNull) {
  analysis::LambdaProperties p;
  p.lambda_scale = std::nan("");
  p.von_mises_max = INFINITY;
  const json j = json::parse(lambda_properties_json(p));
  EXPECT_TRUE(j["lambda_scale"].is_null());
  EXPECT_TRUE(j["von_mises_max"].is_null());
  EXPECT_TRUE(j["closed_form"].is_null());
  EXPECT_TRUE(j["integrator_multiplier"].is_null());
}

TEST(LambdaJson, RunSummaryLambdaIsTheSameObject) {
  const Scenario sc = parse_scenario(R"(
[body]
principal_moments = [1.0, 1.0, 1.6]
[initial]
omega_body = [0.4, -0.3, 2.0]
[output]
t_end = 1.0
sample_dt = 0.1
)");
  const RunSummary s = run_scenario(sc, {});
  const json lam = json::parse(summary_json(s))["lambda"];
  const json props = json::parse(lambda_properties_json(*s.lambda));
  for (const auto& [key, value] : props.items())
    EXPECT_EQ(lam.at(key), value) << key;
  EXPECT_EQ(lam["lambda_initial_body"], props["lambda_initial"]);
  EXPECT_TRUE(lam["closed_form"].is_object());
}

}  // namespace
}  // namespace poinsot::io
