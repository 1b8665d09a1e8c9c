#pragma once
/// @file robot_model.hpp
/// The inertial data of a robot description file — URDF, MJCF (MuJoCo) or SDF (Gazebo) — per link (body), as
/// the file states it, converted to one convention: mass m (kg), centre of mass c (m) and the inertia tensor
/// J about c (kg·m², J_xy = −∫ρxy as in mass_properties.hpp), both in the link's own frame.
///
/// Conventions of the formats (each checked against a hand-computed case in
/// tests/io/robot/test_robot_model.cpp):
///  * URDF `<link><inertial><origin xyz rpy/><mass value/><inertia ixx ixy ixz iyy iyz izz/>`: the tensor is
///    given in the frame of `origin`, at c = xyz, with R = R_z(yaw) R_y(pitch) R_x(roll) (fixed-axis roll,
///    pitch, yaw); J_link = R J_file Rᵀ.
///  * MJCF `<body><inertial pos mass diaginertia|fullinertia quat/>`: the tensor is given in the frame of
///    `quat` (w x y z, normalised; identity when absent), at c = pos: J_body = R D Rᵀ with D =
///    diag(diaginertia), or with D the symmetric matrix of fullinertia = (M11 M22 M33 M12 M13 M23). Other
///    orientation attributes (axisangle, euler, xyaxes, zaxis) are refused, since their meaning depends on
///    compiler settings.
///  * SDF `<link><inertial><pose>x y z roll pitch yaw</pose><mass/><inertia><ixx/>...</inertia>`: as URDF,
///    the pose (relative to the link) placing the inertial frame; `degrees="true"` and
///    `rotation_format="quat_xyzw"` (x y z qx qy qz qw) are understood; `relative_to` other than the link is
///    refused.
/// Geometry (for the plausibility checks of model_check.hpp): the link's collision shapes, or its visual ones
/// when it has none, with their pose in the link frame: boxes, spheres, cylinders (along z), capsules and
/// ellipsoids (MJCF, SDF), and meshes (a file path resolved relative to the model's folder; `package://` and
/// `model://` URIs are resolved only when the file exists under the model's folder, else noted).
#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "poinsot/core/types.hpp"
#include "poinsot/inertia/shapes.hpp"

namespace poinsot::io {

enum class RobotFormat { urdf, mjcf, sdf };
/// "urdf", "mjcf" or "sdf".
std::string to_string(RobotFormat f);

/// One collision (or visual) shape of a link.
struct LinkGeometry {
  std::string element;             ///< "collision", "visual" or "geom" (MJCF)
  inertia::ShapeSpec shape;        ///< kind box, sphere, cylinder, capsule, ellipsoid (sizes in m), or "mesh"
  std::string mesh_path;           ///< the mesh file (kind "mesh")
  Vec3 mesh_scale = Vec3::Ones();  ///< per-axis scale of the mesh's coordinates
  Mat3 R_link_geometry = Mat3::Identity();  ///< orientation of the shape's frame in the link frame
  Vec3 position_link = Vec3::Zero();        ///< origin of the shape's frame in the link frame (m)
  double density = 1000.0;                  ///< MJCF: the geom's density, kg/m³ (MuJoCo's default 1000)
  std::optional<double> mass;  ///< MJCF: the geom's mass when it writes one (kg; replaces density × volume)
};

/// How the file writes the tensor, for in-place edits.
enum class TensorLayout {
  urdf_attributes,  ///< six attributes ixx ixy ixz iyy iyz izz
  sdf_elements,     ///< six elements ixx ixy ixz iyy iyz izz
  mjcf_full,        ///< one attribute of six numbers M11 M22 M33 M12 M13 M23
  mjcf_diag,        ///< one attribute of three numbers
};

/// Byte range [begin, end) of the model's text.
struct ValueSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
};

struct RobotLink {
  std::string name;
  int line = 0;                  ///< line of the link (body) element
  bool has_inertial = false;     ///< false: the file gives no inertial data (the other fields are zero)
  double mass = 0.0;             ///< kg, as written (may be <= 0: reported, not refused)
  Vec3 com_link = Vec3::Zero();  ///< m
  Mat3 R_link_inertial = Mat3::Identity();  ///< orientation of the frame the tensor is written in
  Mat3 inertia_file = Mat3::Zero();         ///< J as written, in that frame (kg·m², symmetric)
  Mat3 inertia_link = Mat3::Zero();         ///< R J_file Rᵀ: about c, link axes (kg·m²)
  TensorLayout layout = TensorLayout::urdf_attributes;
  /// Where the tensor's numbers are written: six spans (URDF, SDF: ixx ixy ixz iyy iyz izz) or one (MJCF).
  /// Empty when a value cannot be edited in place (its text is not a single plain value).
  std::vector<ValueSpan> value_spans;
  std::vector<LinkGeometry> geometry;
  std::vector<std::string> notes;  ///< what the reader skipped, one line each
};

/// Where each line of a model's text comes from. An MJCF `<include file="F"/>` is replaced by the children of
/// F's top-level element, so a line of the text may be a line of F (MuJoCo's rule: F relative to the main
/// file's folder, included at most once, includes nested).
struct SourceLines {
  std::vector<std::string> files;  ///< files[0]: the model's source; then the included files as opened
  /// Per line of the text (index line − 1): (index in files, line there). Empty: the text is files[0] itself.
  std::vector<std::pair<int, int>> origin;
  /// "FILE:LINE" of line `line` (1-based) of the text.
  std::string location(int line) const;
  /// "line N" for a line of the model's own file, "line N of FILE" for one of an included file.
  std::string label(int line) const;
  /// The file of line `line`: "" for the model's own, else the included file's path.
  std::string file(int line) const;
  /// Its line number in that file.
  int line_in_file(int line) const;
};

struct RobotModel {
  RobotFormat format = RobotFormat::urdf;
  std::string source;  ///< path, or "<string>"
  std::string text;    ///< the file's bytes, unchanged (MJCF: with its <include> elements replaced)
  SourceLines lines;   ///< where the lines of `text` come from
  std::vector<RobotLink> links;
};

/// Default limit on the size of a model file (bytes); `poinsot inertia check --max-file-bytes` raises it.
inline constexpr std::size_t kDefaultMaxModelBytes = std::size_t{64} << 20;

/// Reads a model from its text; the format is the root element: <robot> (URDF), <mujoco> (MJCF) or <sdf>.
/// `source` names the text in messages; relative mesh paths and MJCF <include> files are resolved against
/// `base_dir`. Throws InvalidInput for an <include> whose file cannot be read (or is larger than
/// `max_include_bytes`), is not well-formed XML, or is included twice; otherwise
/// InvalidInput (one line, `SOURCE:LINE: <element> ...`) for malformed XML, an unknown root, a missing or
/// malformed number, a non-finite value, or an orientation the reader does not understand.
RobotModel read_robot_model(std::string text, const std::string& source, const std::string& base_dir = ".",
                            std::size_t max_include_bytes = kDefaultMaxModelBytes);

/// Reads the file `path` (at most `max_bytes`, and so each file it includes). Throws InvalidInput as
/// read_robot_model, and when the file cannot be read or is larger than the limit.
RobotModel load_robot_model(const std::string& path, std::size_t max_bytes = kDefaultMaxModelBytes);

}  // namespace poinsot::io
