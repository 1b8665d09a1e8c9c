#pragma once
/// @file summary.hpp
/// summary.json: the machine-readable result of a run (the keys are documented in docs/run.md), written
/// atomically so that a reader never sees half a file.

#include <string>

#include "poinsot/io/run/run_summary.hpp"

namespace poinsot::io {

/// The summary as JSON text (pretty-printed, SI units, a missing theory as null).
std::string summary_json(const RunSummary& summary);

/// Writes `content` to `path` atomically: to a temporary file in the same folder, flushed to disk, then
/// renamed over `path`. Throws ComputationFailed (with the system's reason) when it cannot.
void write_file_atomic(const std::string& path, const std::string& content);

}  // namespace poinsot::io
