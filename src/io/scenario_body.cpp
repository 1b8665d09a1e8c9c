// The inertia of a scenario's body from a shape or a mesh (see scenario_body.hpp).
#include "scenario_body.hpp"

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::io::detail {

BodyInertia body_from_shape(const Source& source, const toml::table& /*shape*/, const toml::node* position) {
  throw InvalidInput(
      fmt::format("{}[body] shape: the inertia layer's shapes are not in this build yet; "
                  "expected principal_moments or inertia",
                  location(source, position)));
}

BodyInertia body_from_mesh(const Source& source, const toml::table& /*mesh*/, const toml::node* position,
                           std::string_view /*base_dir*/) {
  throw InvalidInput(
      fmt::format("{}[body] mesh: the inertia layer's mesh reader is not in this build yet; "
                  "expected principal_moments or inertia",
                  location(source, position)));
}

}  // namespace poinsot::io::detail
