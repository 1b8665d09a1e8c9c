#pragma once
/// @file reference_trajectory.hpp
/// The trajectory.csv of `poinsot optimize` read back as the reference motion of a slew ensemble
/// (ensemble/slew_tracking.hpp, `[ensemble.slew] reference`).
///
/// Format: UTF-8 text; blank lines and lines starting with `#` are skipped; the first other line is the
/// header, whose first eleven columns are `t,qw,qx,qy,qz,wx,wy,wz,ux,uy,uz` (s; the attitude body → space;
/// rad/s and N·m in the body frame; further columns, such as L, are ignored); then one row of
/// comma-separated numbers per line.
#include <string>
#include <string_view>

#include "poinsot/ensemble/slew_tracking.hpp"

namespace poinsot::io {

/// Parses trajectory text; `source` names it in the messages. Throws InvalidInput (one line naming the
/// source, the line and what was expected) for a missing or different header, a row with too few numbers
/// or a non-number.
ensemble::ReferenceRows parse_reference_trajectory(std::string_view text, std::string_view source);
/// Reads and parses the file at `path`. Throws InvalidInput for an unreadable file or invalid content.
ensemble::ReferenceRows read_reference_trajectory(const std::string& path);

}  // namespace poinsot::io
