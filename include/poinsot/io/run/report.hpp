#pragma once
/// @file report.hpp
/// The text report of a run, printed by `poinsot run`: the body (principal moments, symmetry class), the
/// initial invariants and their worst relative error over the run, the events beside their theory (flips of
/// the intermediate axis and the closed-form interval 2K(k)/ω_p; precession and nutation of a top), a few
/// lines on Λ, the cost (steps, wall time, steps per second) and the files written.

#include <string>

#include "poinsot/io/run/run_summary.hpp"

namespace poinsot::io {

/// The report as text (lines ending in '\n'), SI units stated on each line.
std::string format_report(const RunSummary& summary);

}  // namespace poinsot::io
