// `poinsot rotation`: converts one rotation between the forms of the so3 layer (matrix, quaternion,
// axis-angle, rotation vector, Euler angles in a named sequence). Exactly one input form is given.
#include <array>
#include <numbers>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/exp_log.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::cli {
namespace {

struct RotationOptions {
  std::vector<double> quaternion;  // w x y z
  std::vector<double> matrix;      // 9, row-major
  std::vector<double> axis_angle;  // x y z angle
  std::vector<double> rotvec;      // x y z
  std::vector<std::string> euler;  // SEQ a1 a2 a3
  bool degrees = false;
  std::string out_sequence = "ZYX";
};

double parse_number(const std::string& field, const std::string& text) {
  try {
    std::size_t used = 0;
    const double x = std::stod(text, &used);
    if (used == text.size()) return x;
  } catch (const std::exception&) {
  }
  throw InvalidInput(fmt::format("{}: got \"{}\", expected a number", field, text));
}

void run(const RotationOptions& o) {
  const double to_rad = o.degrees ? std::numbers::pi / 180.0 : 1.0;
  const int given = !o.quaternion.empty() + !o.matrix.empty() + !o.axis_angle.empty() + !o.rotvec.empty() +
                    !o.euler.empty();
  if (given != 1) {
    throw InvalidInput(
        fmt::format("rotation: got {} input forms, expected exactly one of --quaternion, --matrix, "
                    "--axis-angle, --rotvec, --euler",
                    given));
  }
  Mat3 R;
  if (!o.quaternion.empty()) {
    R = so3::rotation_from_quaternion(
        Quat(o.quaternion[0], o.quaternion[1], o.quaternion[2], o.quaternion[3]));
  } else if (!o.matrix.empty()) {
    Mat3 m;
    for (int i = 0; i < 9; ++i)
      m(i / 3, i % 3) = o.matrix[static_cast<std::size_t>(i)];
    R = so3::project_to_so3(m);
  } else if (!o.axis_angle.empty()) {
    R = so3::rotation_from_axis_angle(vec3_from_list(o.axis_angle), o.axis_angle[3] * to_rad);
  } else if (!o.rotvec.empty()) {
    R = so3::exp_checked(vec3_from_list(o.rotvec) * to_rad);
  } else {
    const auto seq = so3::EulerSequence::parse(o.euler[0]);
    Vec3 a;
    for (int i = 0; i < 3; ++i)
      a[i] = parse_number("--euler angle", o.euler[static_cast<std::size_t>(i) + 1]) * to_rad;
    R = so3::rotation_from_euler(seq, a);
  }
  const Quat q = so3::quaternion_from_rotation(R);
  const so3::AxisAngle aa = so3::axis_angle_from_rotation(R);
  const auto seq = so3::EulerSequence::parse(o.out_sequence);
  const Vec3 e = so3::euler_from_rotation(seq, R) / to_rad;
  const char* unit = o.degrees ? "deg" : "rad";
  fmt::print("rotation matrix R (body to space):\n");
  for (int i = 0; i < 3; ++i)
    fmt::print("  [{:>22.17g} {:>22.17g} {:>22.17g}]\n", R(i, 0), R(i, 1), R(i, 2));
  fmt::print("quaternion (w, x, y, z):   {}\n", format_quaternion(q));
  fmt::print("axis, angle:               {}, {} {}\n", format_vector(aa.axis), aa.angle / to_rad, unit);
  fmt::print("rotation vector:           {} {}\n", format_vector(so3::log(R) / to_rad), unit);
  fmt::print("euler {} (intrinsic):     {} {}\n", seq.name(), format_vector(e), unit);
}

}  // namespace

void register_rotation(CLI::App& app) {
  auto opts = std::make_shared<RotationOptions>();
  auto* cmd = app.add_subcommand("rotation",
                                 "Convert a rotation between matrix, quaternion, axis-angle, rotation "
                                 "vector and Euler angles");
  cmd->add_option("--quaternion", opts->quaternion, "w x y z (normalised for you)")->expected(4);
  cmd->add_option("--matrix", opts->matrix, "9 entries row by row (projected onto SO(3) if slightly off)")
      ->expected(9);
  cmd->add_option("--axis-angle", opts->axis_angle, "x y z angle")->expected(4);
  cmd->add_option("--rotvec", opts->rotvec, "rotation vector x y z (angle times unit axis)")->expected(3);
  cmd->add_option("--euler", opts->euler, "SEQUENCE a1 a2 a3, intrinsic, e.g. ZXZ 0.1 0.2 0.3")->expected(4);
  cmd->add_flag("--degrees", opts->degrees, "angles in degrees (input and output)");
  cmd->add_option("--sequence", opts->out_sequence, "Euler sequence of the output (default ZYX)");
  cmd->callback([opts] { run(*opts); });
}

}  // namespace poinsot::cli
