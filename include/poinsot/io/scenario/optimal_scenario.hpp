#pragma once
/// @file optimal_scenario.hpp
/// Scenario files for `poinsot optimize` (docs/optimal_control.md, "Scenario files"): the body in `[body]`
/// (any form of docs/scenario.md: principal_moments, inertia, poinsot, shape, mesh, composite; J about the
/// centre of mass) and the problem in `[optimal_control]`:
///
///     [optimal_control]
///     objective = "minimum_time"     # or minimum_energy (needs final_time),
///                                    # minimum_time_regularised (needs energy_weight)
///     torque_bound = "per_axis"      # or "norm"
///     torque_max = [50, 50, 50]      # N·m: three bounds per axis, one number for a norm bound
///     rate_max = 0.5                 # rad/s, optional
///     final_time = 10.0              # s, minimum_energy only
///     energy_weight = 1e-4           # s/(N·m)², minimum_time_regularised only
///     mesh_tolerance = 1e-5          # direct method, optional
///     initial_intervals = 10         # direct method, optional (2 … 4000)
///     max_mesh_iterations = 10       # direct method, optional (1 … 100)
///     starts = 4                     # direct method, optional (1 … 64): guesses the first mesh is
///                                    # solved from (CollocationOptions::starts)
///     shooting_nodes = 1             # indirect method, optional (1 … 1000): segments of multiple shooting
///     phased = true                  # optional: the phase-per-arc re-solve of a minimum-time direct
///                                    # solution where it applies (phased_collocation.hpp); false: off
///     phased_intervals_per_arc = 64  # optional (1 … 2000): its uniform intervals on every arc
///     [optimal_control.initial]      # orientation = { ... } as in [initial]; omega_body (rad/s)
///     [optimal_control.final]        # the same, or free_attitude = true (detumbling)
///     [[optimal_control.keep_out]]   # any number (pointing_constraint.hpp): name (optional),
///                                    # boresight_body, direction_space ([x, y, z], any non-zero length),
///                                    # half_angle (rad) or half_angle_deg; [[optimal_control.keep_in]] alike
///     [output]
///     dir = "..."                    # optional, default SCENARIO-optimize
///
/// Throws InvalidInput located at the key for every malformed or invalid value (the problem's own checks,
/// optimal::validate, are applied and located at [optimal_control]).
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "poinsot/inertia/mesh.hpp"
#include "poinsot/optimal/direct_collocation.hpp"
#include "poinsot/optimal/indirect_shooting.hpp"
#include "poinsot/optimal/phased_collocation.hpp"
#include "poinsot/optimal/problem.hpp"

namespace poinsot::io {

struct OptimalScenario {
  std::string name;                         ///< the file's stem
  std::string source;                       ///< the file's path (or "<string>", "<dict>")
  std::string title;                        ///< the file's `title`, or empty
  std::string body_description;             ///< how [body] gave the inertia
  optimal::ReorientationProblem problem;    ///< the validated problem of [optimal_control]
  optimal::CollocationOptions collocation;  ///< the direct method's options
  optimal::ShootingOptions shooting;        ///< the indirect method's options (shooting_nodes from the file)
  /// The phase-per-arc re-solve after the mesh refinement (minimum time, where the switching structure
  /// allows it): on unless the file says `phased = false`; 64 intervals per arc unless it says otherwise
  /// (Betts' t* then meets the indirect one to 1e-11, docs/optimal_control_theory.md section 2b), and at
  /// most 40 Ipopt iterations: from the refined direct solution it converges in 3 to 12 on the benchmark's
  /// random problems, and one that takes more is degenerate (problem 6 of seed 5 of the per_axis family: two
  /// switches of different axes merge, Ipopt enters its restoration phase and fails after 357 iterations
  /// and 400 s of CPU, on an NLP of 512 intervals that it otherwise solves in under a second).
  bool phased = true;
  optimal::PhasedOptions phased_options{.intervals_per_arc = 64, .max_nlp_iterations = 40};
  std::string out_dir;  ///< [output] dir; empty: the default
  /// For drawing (view.html): the body's mass (kg) when the file gives one, and its surface about the centre
  /// of mass (body axes, m) when it gives a shape or a mesh, else null.
  std::optional<double> body_mass;
  std::shared_ptr<const inertia::TriangleMesh> body_surface;
};

/// Parses scenario text; `source` names it in the messages and `base_dir` resolves relative mesh paths.
/// Throws InvalidInput located at the offending key.
OptimalScenario parse_optimal_scenario(std::string_view text, std::string_view source,
                                       std::string_view base_dir);
/// Reads and parses the file at `path` (name = its stem). Throws InvalidInput for an unreadable file or any
/// invalid value.
OptimalScenario load_optimal_scenario(const std::string& path);

}  // namespace poinsot::io
