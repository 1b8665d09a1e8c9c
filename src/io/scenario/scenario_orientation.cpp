// The orientation sub-table of scenario sections (see scenario_orientation.hpp).
#include "scenario_orientation.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/format.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::io::detail {

Mat3 read_orientation(const Source& src, const Section& parent) {
  const toml::table* t = parent.table("orientation");
  if (t == nullptr) return Mat3::Identity();
  const Section o(src, t, parent.name() + ".orientation",
                  {"quaternion", "matrix", "axis_angle", "euler", "degrees"}, parent.node("orientation"));
  const auto how = o.exactly_one({"quaternion", "matrix", "axis_angle", "euler"}, "orientation");
  const double unit = o.boolean("degrees").value_or(false) ? std::numbers::pi / 180.0 : 1.0;
  if (how == "quaternion") {
    const auto q = *o.numbers(how, 4);
    const double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    if (!(n > 1e-12)) o.fail(how, "got a zero quaternion, expected [w, x, y, z] with a non-zero norm");
    return so3::rotation_from_quaternion(Quat(q[0] / n, q[1] / n, q[2] / n, q[3] / n));
  }
  if (how == "matrix") {
    const Mat3 m = *o.mat3(how);
    if (!so3::is_rotation(m, so3::kRotationInputTolerance)) {
      o.fail(how,
             fmt::format("got {} with ‖RᵀR − I‖ = {} and det = {}; expected a rotation matrix "
                         "(orthogonal to {}, det = +1)",
                         format_matrix(m), format_number(so3::orthogonality_error(m), 3),
                         format_number(m.determinant(), 6), format_number(so3::kRotationInputTolerance)));
    }
    return so3::project_to_so3(m);
  }
  const toml::table* sub = o.table(how);
  if (how == "axis_angle") {
    const Section a(src, sub, o.name() + ".axis_angle", {"axis", "angle"}, o.node(how));
    a.require("axis", "[x, y, z] (any non-zero length)");
    a.require("angle", "a number (rad, or degrees with degrees = true)");
    const Vec3 axis = *a.vec3("axis");
    const double angle = *a.number("angle") * unit;
    if (!(axis.norm() > 0.0)) a.fail("axis", "got (0, 0, 0), expected a non-zero vector");
    return located(a, "axis", [&] { return so3::rotation_from_axis_angle(axis.normalized(), angle); });
  }
  const Section e(src, sub, o.name() + ".euler", {"sequence", "angles"}, o.node(how));
  e.require("sequence", "a sequence name such as \"ZXZ\" or \"ZYX\" (intrinsic)");
  e.require("angles", "[a1, a2, a3] (rad, or degrees with degrees = true)");
  const std::string seq_name = *e.string("sequence");
  const Vec3 angles = *e.vec3("angles") * unit;
  const auto seq = located(e, "sequence", [&] { return so3::EulerSequence::parse(seq_name); });
  return so3::rotation_from_euler(seq, angles);
}

}  // namespace poinsot::io::detail
