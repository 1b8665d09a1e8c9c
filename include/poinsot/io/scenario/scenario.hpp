#pragma once
/// @file scenario.hpp
/// Scenario files: a rotating body described in TOML (body, initial state, torque, integrator, output), read
/// with toml++ into a validated Scenario. Every key is documented in docs/scenario.md; examples/*.toml are
/// commented examples.
///
/// Every problem with the file is an InvalidInput whose one-line message starts with `FILE:LINE:COLUMN:` (the
/// place in the file), names the key as `[section] key`, the value received and what was expected: a TOML
/// syntax error, an unknown key (with the valid keys listed), a missing or doubly given required key (exactly
/// one way to give the inertia, the initial angular velocity, the orientation), a wrong type, a value out of
/// range (t_end <= 0, dt <= 0, non-finite numbers), an invalid inertia (the inertia layer's message), the
/// method `exact` with a torque. Units are SI throughout: kg, m, s, rad, kg·m², N·m.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/integrator.hpp"
#include "poinsot/dynamics/methods.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/simulation.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"
#include "poinsot/inertia/mesh.hpp"

namespace poinsot::io {

/// A validated scenario: everything `poinsot run` needs.
struct Scenario {
  std::string name;              ///< the file's stem ("tennis_racket"), or "scenario" for text
  std::string source;            ///< the file's path, or the name given to parse_scenario
  std::string title;             ///< optional one-line description (top-level key `title`)
  dynamics::RigidBody body;      ///< inertia about the rotation point, optional pivot
  std::string body_description;  ///< how the inertia was given, for the report ("principal moments ...")
  dynamics::State initial;       ///< t = 0, R body → space, ω body frame (rad/s)
  std::string torque_type;       ///< "none", "gravity", "body", "space"
  std::shared_ptr<const dynamics::TorqueModel> torque;  ///< never null
  Vec3 gravity_space = Vec3::Zero();                    ///< m/s², space frame; zero unless gravity
  std::string method;                      ///< a name of the method registry (dynamics/methods.hpp)
  dynamics::IntegratorOptions integrator;  ///< dt (s), rtol, atol
  dynamics::SimulationOptions simulation;  ///< t_end (s), sample_dt (s)
  std::string out_dir;  ///< [output] dir; empty: the CLI uses a folder named after the scenario
  /// The body's surface about its centre of mass (body axes, m) when the file gives a shape or a mesh, for
  /// drawing (view.html); null otherwise.
  std::shared_ptr<const inertia::TriangleMesh> body_surface;
};

/// Parses and validates scenario text. `source` names it in messages (a path, or "<string>"); a relative mesh
/// file is looked up in `base_dir` (the scenario file's folder; the current folder when empty).
/// Throws InvalidInput (one line, `SOURCE:LINE:COLUMN: ...`) on any problem.
Scenario parse_scenario(std::string_view text, std::string_view source = "<string>",
                        std::string_view base_dir = "");

/// Reads and validates a scenario file. Throws InvalidInput if it cannot be read or is invalid.
Scenario load_scenario(const std::string& path);

/// Command-line overrides of the common keys (`--method`, `--dt`, `--t-end`, `--sample-dt`, `--out`), the one
/// mapping behind `poinsot run`, `poinsot lambda` and Python's `Scenario.with_overrides`; an unset field
/// leaves the file's value. Validated like the file's values (the messages name the option, e.g. `--dt`).
struct ScenarioOverrides {
  std::string method;               ///< empty: unset
  std::optional<double> dt;         ///< s
  std::optional<double> t_end;      ///< s
  std::optional<double> sample_dt;  ///< s
  std::string out_dir;              ///< empty: unset
};

/// Applies overrides to a scenario and re-checks the rules they touch (range, `exact` with a torque).
/// The multibody overload is in multibody_scenario.hpp; both are defined in overrides.cpp.
void apply_overrides(Scenario& scenario, const ScenarioOverrides& overrides);

/// Throws InvalidInput unless `method` names an integrator that can run this scenario (`what` names the
/// source of the value, e.g. "[integrator] method" or "--method").
void check_method(const Scenario& scenario, std::string_view method, std::string_view what);

}  // namespace poinsot::io
