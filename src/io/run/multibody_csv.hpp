#pragma once
// Internal to the io layer: the CSV layouts of multibody results, shared by `poinsot run` on a multibody
// scenario (multibody_run.hpp) and `poinsot optimize` on one (multibody_optimal_run.hpp). Numbers with 17
// significant digits (an exact round trip).

#include <string>

#include "poinsot/multibody/model.hpp"
#include "poinsot/multibody/multipliers.hpp"
#include "poinsot/multibody/state.hpp"

namespace poinsot::io::detail {

/// trajectory.csv's header: t, then per body NAME.x .y .z (centre of mass, m), NAME.qw .qx .qy .qz (body →
/// space), NAME.vx .vy .vz (m/s), NAME.wx .wy .wz (ω, body frame, rad/s).
void append_trajectory_header(std::string& out, const multibody::System& system);
/// One trajectory row of `state`, in the header's columns.
void append_trajectory_row(std::string& out, const multibody::State& state);

/// reactions.csv rows at time t (s): per joint, the reaction force (N) and couple (N·m) on body a at the
/// joint point, space frame; with `header` the column line first.
std::string reactions_csv(const multibody::System& system, const multibody::Multipliers& multipliers,
                          double t, bool header = true);
/// multipliers.csv rows at the state's time: per body, the centre of mass (m) and Λ (J, body frame, row by
/// row); with `header` the column line first.
std::string multipliers_csv(const multibody::System& system, const multibody::State& state,
                            const multibody::Multipliers& multipliers, bool header = true);

}  // namespace poinsot::io::detail
