#pragma once
// The JSON form of analysis::LambdaReport, shared by `poinsot lambda --json` and any other command that
// reports Λ (e.g. `poinsot run`). Keys are stable and documented in docs/lambda.md; values in SI units (J,
// N·m, Pa, s, rad/s). Defined in cmd_lambda.cpp.
#include <nlohmann/json.hpp>

#include "poinsot/analysis/lambda_report.hpp"

namespace poinsot::cli {

nlohmann::ordered_json lambda_report_json(const analysis::LambdaReport& report);

}  // namespace poinsot::cli
