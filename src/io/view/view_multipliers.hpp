#pragma once
/// @file view_multipliers.hpp
/// The Lagrange multipliers of a multibody run at every frame of its page (view_page.hpp): the joint
/// reactions and each body's Λ, recomputed exactly at the frame's state (multibody::exact_multipliers) since
/// the run's files hold them at the final time only (reactions.csv, multipliers.csv). Internal to the io
/// layer.

#include <string>
#include <vector>

#include "poinsot/multibody/model.hpp"
#include "view_data.hpp"

namespace poinsot::io {

/// Numbers per frame: 6 per joint and 6 per body.
struct FrameMultipliers {
  /// Per frame, per joint: the reaction force on body a at the joint point (N) and the couple on body a
  /// (N·m), space frame: Fx, Fy, Fz, Cx, Cy, Cz.
  std::vector<double> reactions;
  /// Per frame, per body: the symmetric part of Λ (J, body frame): xx, yy, zz, xy, xz, yz. The constraint
  /// stress integrated over the body is ∫σ dv = −R Λ Rᵀ (space frame, N·m; docs/lambda.md).
  std::vector<double> lambda;
};

/// The multipliers at every frame of `f` (a multibody trajectory.csv read from `path`, with the columns
/// NAME.x … NAME.wz of every body of `system`, in its order), each number rounded to kViewDrawDigits
/// significant digits (rounded_for_drawing). The frame's state is the row: x, the rotation of the quaternion,
/// v and ω. Throws InvalidInput when a column is missing.
FrameMultipliers frame_multipliers(const multibody::System& system, const CsvFrames& f,
                                   const std::string& path);

}  // namespace poinsot::io
