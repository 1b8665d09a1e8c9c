#pragma once
// Internal to the io layer: MJCF frame orientations as MuJoCo's XML reference defines them — `quat` (w x y z,
// normalised), `axisangle` (x y z angle), `euler` (three angles about the axes of <compiler eulerseq>,
// default "xyz": lower-case letters rotate with the frame, upper-case ones are fixed), `xyaxes` (the frame's
// x and y axes, y orthogonalised against x), `zaxis` (the smallest rotation taking (0, 0, 1) to the axis) —
// with the angles in the unit of <compiler angle> (degrees unless "radian").
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <tinyxml2.h>

#include "poinsot/core/types.hpp"
#include "xml_source.hpp"

namespace poinsot::io::detail {

/// The settings of <compiler> that orientations depend on.
struct MjcfCompiler {
  double angle_unit =
      0.017453292519943295;  ///< rad per unit of the file's angles (MuJoCo's default: degrees)
  std::string eulerseq = "xyz";
  std::string inertiafromgeom = "auto";  ///< "auto", "true" or "false"
};

/// Reads every <compiler> of the model. Throws InvalidInput for an `angle` other than radian or degree.
MjcfCompiler read_mjcf_compiler(const XmlSource& xml);

/// The value of an orientation attribute as exactly `count` numbers, or nothing when absent, and the element
/// that writes it (for messages).
using MjcfNumbers = std::function<std::optional<std::vector<double>>(const char* name, std::size_t count)>;

/// The orientation an element writes, read through `numbers` (its own attributes, or with its default
/// class's: MjcfAttributes::numbers); identity when none. `e` names the element in messages. Throws
/// InvalidInput for a zero quaternion or axis, for an eulerseq that mixes rotating and fixed axes, and for
/// numbers whose rotation is not finite (`FILE:LINE: <body>: its orientation is not a finite rotation; ...`).
Mat3 mjcf_orientation(const XmlSource& xml, const tinyxml2::XMLElement& e, const MjcfCompiler& compiler,
                      const MjcfNumbers& numbers);
/// The same, from the element's own attributes.
Mat3 mjcf_orientation(const XmlSource& xml, const tinyxml2::XMLElement& e, const MjcfCompiler& compiler);

}  // namespace poinsot::io::detail
