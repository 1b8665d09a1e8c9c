#pragma once
/// @file top_prediction.hpp
/// Which top a body and its load make, and what the theory predicts for it: the one place where a run, an
/// ensemble or a report decides "is this a heavy top, about which axis".
///
/// Two kinds are recognised:
///  - a **heavy top**: a body held at a pivot away from its centre of mass, under uniform gravity g ≠ 0. Its
///    figure axis is e = d/|d| (body frame, d the pivot-to-centre-of-mass vector) and it precesses about the
///    upward vertical −g/|g| (space frame);
///  - a **free symmetric top**: a torque-free body without pivot whose principal moments make it prolate or
///    oblate. Its figure axis is the principal axis of the distinct moment and it precesses about
///    L_space/|L|.
///
/// Predictions, with I3 = eᵀJe and I1 = (tr J − I3)/2 about the rotation point (kg·m²) and ω3 = ω·e (rad/s):
///  - heavy top: the fast-top precession rate M g l/(I3 ω3) and nutation frequency I3|ω3|/I1 of the notes,
///    the sleeping-top criterion ω3² > 4 I1 M g l/I3² (top_theory.hpp), and, when J is symmetric about e and
///    the axis is tilted, the exact mean precession rate, nutation frequency and tilt range of Goldstein's
///    quadrature (top_motion());
///  - free symmetric top: the figure axis turns about L at |L|/I1 (docs/exact.md).
#include <optional>
#include <string_view>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"

namespace poinsot::dynamics {

enum class TopKind { heavy, free_symmetric };

/// "heavy top" or "free symmetric top" (the words of reports and summary.json).
std::string_view to_string(TopKind kind);

/// True when `body` under gravity (`gravity_torque`, acceleration `gravity_space` in m/s², space frame) is a
/// heavy top: it has a pivot away from its centre of mass and g ≠ 0.
bool is_heavy_top(const RigidBody& body, bool gravity_torque, const Vec3& gravity_space);

/// What the theory predicts for a top (SI units; see the file comment).
struct TopPrediction {
  TopKind kind = TopKind::heavy;
  Vec3 axis_body = Vec3::Zero();        ///< the figure axis e, body frame (unit)
  Vec3 direction_space = Vec3::Zero();  ///< precession about: −g/|g| or L_space/|L| (unit)
  double spin = 0.0;                    ///< ω3 = ω·e at the initial state (rad/s)
  double moment_axial = 0.0;            ///< I3 = eᵀJe about the rotation point (kg·m²)
  double moment_transverse = 0.0;       ///< I1 = (tr J − I3)/2 about the rotation point (kg·m²)
  /// Heavy top: M g l/(I3 ω3) (when ω3 ≠ 0); free symmetric top: |L|/I1 (rad/s).
  std::optional<double> precession_rate_theory;
  std::optional<double> precession_rate_exact;      ///< heavy symmetric tilted top: Ω̄ = Δφ/T_nut (rad/s)
  std::optional<double> nutation_frequency_theory;  ///< heavy symmetric tilted top: 2π/T_nut (rad/s)
  std::optional<double> nutation_frequency_fast_top;  ///< heavy top: I3|ω3|/I1 (when ω3 ≠ 0, rad/s)
  std::optional<double> theta_min_theory, theta_max_theory;  ///< heavy symmetric tilted top: tilt range (rad)
  std::optional<bool> sleeping;  ///< heavy top: the sleeping-top criterion ω3² > 4 I1 M g l/I3²
};

/// The top that `body` under `torque` (gravity `gravity_space`, m/s², space frame) makes from state `s0`,
/// with its predictions; std::nullopt when it is neither kind (or a free symmetric top with L = 0). Throws
/// nothing for a valid body and state.
std::optional<TopPrediction> predict_top(const RigidBody& body, const TorqueModel& torque,
                                         const Vec3& gravity_space, const State& s0);

}  // namespace poinsot::dynamics
