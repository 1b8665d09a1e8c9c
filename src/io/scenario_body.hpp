#pragma once
// Internal to the io layer: the inertia of a scenario's body given by a shape or a mesh (the inertia layer),
// read from the `[body] shape = {...}` and `[body] mesh = {...}` tables.

#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"
#include "toml_fields.hpp"

namespace poinsot::io::detail {

/// Mass properties of a shape or a mesh, in the body frame of the scenario.
struct BodyInertia {
  Mat3 inertia_com = Mat3::Identity();  ///< J about the centre of mass, body frame (kg·m²)
  double mass = 0.0;                    ///< kg
  Vec3 com = Vec3::Zero();              ///< centre of mass in the shape's or mesh's frame (m)
  std::string description;              ///< for the report, e.g. "box 0.3 × 0.1 × 0.02 m, 0.4 kg"
};

/// `[body] shape = { type = "...", ... }`. Throws InvalidInput (located) for an unknown type, a missing or
/// unknown key, or a value the inertia layer refuses (its message).
BodyInertia body_from_shape(const Source& source, const toml::table& shape, const toml::node* position);

/// `[body] mesh = { file = "...", density = ... | mass = ... }`; a relative file is taken from `base_dir`.
BodyInertia body_from_mesh(const Source& source, const toml::table& mesh, const toml::node* position,
                           std::string_view base_dir);

}  // namespace poinsot::io::detail
