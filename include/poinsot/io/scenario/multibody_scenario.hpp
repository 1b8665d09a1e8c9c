#pragma once
/// @file multibody_scenario.hpp
/// Multibody scenario files (TOML, a `[[bodies]]` array) read into a validated multibody::Scenario, which
/// multibody::run_scenario runs. The format is documented in docs/multibody.md (section "Scenario files"),
/// with examples in examples/multibody/. Units SI throughout: kg, m, s, rad, kg·m², N, N·m.
///
///     title          optional one-line description
///     [simulation]   dt (s), duration (s), output_every (steps), gravity = [x, y, z] (m/s²), order (2 or 4:
///                    RATTLE or its fourth-order composition)
///     [[bodies]]     name; the inertia exactly as a single-body scenario's [body] gives it (one code path,
///                    docs/scenario.md): principal_moments / inertia (J, [Jxx, Jyy, Jzz] or 3×3) / poinsot
///                    (K) with mass (kg), or shape = { type, sizes, mass | density, axis }, or
///                    mesh = { file, mass | density, shell, flip_inward }, or composite = { file } (a body
///                    file of the inertia layer); files relative to the scenario's folder. In multibody files
///                    the symmetry axis of a rod, cylinder, cone, capsule or torus defaults to body x.
///                    position (m): where the origin of the body's frame is, rotation ({ axis, angle } rad,
///                    or a 3×3 matrix) or quaternion = [w, x, y, z]: its orientation, velocity (m/s, of the
///                    centre of mass), omega_body (rad/s, body frame)
///     [[joints]]     name, type = "ball"|"hinge"|"weld", body_a, point_a, body_b (default "world"), point_b
///                    (default: where point_a is at t = 0), axis_a, axis_b (hinge; axis_b defaults to axis_a
///                    carried by the initial rotations)
///     [[springs]]    name, body_a, point_a, body_b, point_b, stiffness (N/m), damping (N·s/m), rest_length
///     (m)
///     [[forces]]     body, force (N, space), point (m)
///     [[torques]]    body, torque (N·m), frame = "space"|"body"
///
/// The body frame is the frame its inertia was given in: a shape's own frame (origin at its centre of mass),
/// a mesh's or composite's file frame (whose origin need not be the centre of mass c), or, for an explicit
/// tensor, a frame at the centre of mass. Every point of a body (joint points, spring ends, force points) is
/// given in that frame, as a user of the mesh reads them off the mesh; the model (multibody/model.hpp) gets
/// them relative to the centre of mass (p − c), and the body's centre of mass starts at position + R c.
/// An omitted point of a body (point_a, a spring's end, a force's point) is its centre of mass, as in the
/// files written before meshes; an omitted point_b of a joint is where point_a is at t = 0. Points on the
/// world are in the space frame (an omitted one is the origin).
///
/// Initial velocities are projected onto the joint constraints (least kinetic-energy change), so a scenario
/// may give only the velocities it cares about.
///
/// Every problem is an InvalidInput with a one-line message `FILE:LINE:COLUMN: [bodies[2]] mass: got -1 kg,
/// expected a number > 0`: the file and place, the entry, the key, the value received and what was expected.

#include <string>
#include <string_view>

#include "poinsot/io/scenario/scenario.hpp"
#include "poinsot/multibody/scenario.hpp"

namespace poinsot::io {

/// Parses and validates a multibody scenario. `source` names it in messages (a path, or "<string>"); relative
/// mesh and composite files are looked up in `base_dir` (the scenario file's folder; the current folder when
/// empty). Throws InvalidInput (one line, located) on any problem.
multibody::Scenario parse_multibody_scenario(std::string_view text, std::string_view source = "<string>",
                                             std::string_view base_dir = "");

/// Reads and validates a multibody scenario file (relative files from its folder).
multibody::Scenario load_multibody_scenario(const std::string& path);

/// The command line's overrides on a multibody scenario: `method` "rattle" (keeps the file's order) or "rk4"
/// (order 4), `dt` (s), `t_end` → duration (s), `sample_dt` → output_every = max(1, round(sample_dt/dt))
/// steps; out_dir is not part of a multibody scenario and is left to the caller. Throws InvalidInput naming
/// the option (`--method`, `--dt`, ...), the value and what was expected.
void apply_overrides(multibody::Scenario& scenario, const ScenarioOverrides& overrides);

}  // namespace poinsot::io
