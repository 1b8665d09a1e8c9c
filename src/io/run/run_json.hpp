#pragma once
// Internal to io/run: the JSON values that only the run serialisers write (summary.json of each kind of run,
// the Λ report), beside the shared forms of io/json_values.hpp.
#include <string>

#include "io/json_values.hpp"

namespace poinsot::analysis {
struct LambdaProperties;
}

namespace poinsot::io::detail {

/// The `status` of a run: "failed", "interrupted" or "completed".
inline const char* run_status(const std::string& failure, bool interrupted) {
  return !failure.empty() ? "failed" : (interrupted ? "interrupted" : "completed");
}

/// The properties of Λ along a run (the object of io::lambda_properties_json; lambda_json.cpp).
json lambda_properties_value(const analysis::LambdaProperties& properties);

}  // namespace poinsot::io::detail
