#pragma once
// Internal to the io layer: the `orientation` sub-table of a scenario section (docs/scenario.md), read the
// same way for `[initial]` and for the attitudes of `[optimal_control]`.

#include "poinsot/core/types.hpp"
#include "toml_fields.hpp"

namespace poinsot::io::detail {

/// R (body → space) from `parent`'s `orientation = { quaternion | matrix | axis_angle | euler, degrees }`;
/// the identity when absent. Throws InvalidInput located at the key (`[initial.orientation] matrix: ...`).
Mat3 read_orientation(const Source& src, const Section& parent);

}  // namespace poinsot::io::detail
