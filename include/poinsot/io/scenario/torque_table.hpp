#pragma once
/// @file torque_table.hpp
/// Torque tables: the `[torque] type = "table"` of scenario files, e.g. the control.csv of `poinsot
/// optimize`, so that `poinsot run` replays an optimal control with any integrator
/// (dynamics/tabulated_torque.hpp defines the interpolation: linear or local cubics between rows, a jump at
/// two rows with one time, 0 outside the table).
///
/// Format: UTF-8 text; blank lines and lines starting with `#` (such as control.csv's `# status: ...`) are
/// skipped; the first other line is the header, whose first four columns are `t,ux,uy,uz` (s, N·m, body
/// frame; further columns are ignored); then one row of comma-separated numbers per line.
#include <memory>
#include <string>
#include <string_view>

#include "poinsot/dynamics/tabulated_torque.hpp"

namespace poinsot::io {

/// Parses table text; `source` names it in the messages. Throws InvalidInput (one line naming the source,
/// the line and what was expected) for a missing or different header, a row with too few numbers or a
/// non-number, and for what TabulatedTorque rejects.
std::shared_ptr<const dynamics::TabulatedTorque> parse_torque_table(
    std::string_view text, std::string_view source,
    dynamics::TableInterpolation interpolation = dynamics::TableInterpolation::linear);
/// Reads and parses the file at `path`. Throws InvalidInput for an unreadable file or invalid content.
std::shared_ptr<const dynamics::TabulatedTorque> read_torque_table(
    const std::string& path,
    dynamics::TableInterpolation interpolation = dynamics::TableInterpolation::linear);

}  // namespace poinsot::io
