#pragma once
// Internal to the io layer: the three robot-model readers behind read_robot_model (robot_model.hpp) and the
// helpers they share. Each reader walks the tinyxml2 tree of an XmlSource and fills RobotModel::links.
#include <optional>
#include <string>
#include <string_view>

#include "poinsot/io/robot/robot_model.hpp"
#include "xml_source.hpp"

namespace poinsot::io::detail {

void read_urdf(const XmlSource& xml, const std::string& base_dir, RobotModel& model);
void read_mjcf(const XmlSource& xml, const std::string& base_dir, RobotModel& model);
void read_sdf(const XmlSource& xml, const std::string& base_dir, RobotModel& model);

/// The symmetric J from its entries (kg·m²).
Mat3 tensor_from_entries(double ixx, double iyy, double izz, double ixy, double ixz, double iyz);
/// R = R_z(yaw) R_y(pitch) R_x(roll): the fixed-axis roll-pitch-yaw of URDF and SDF (radians). Throws
/// InvalidInput `WHERE: got (r, p, y), expected angles (rad) whose rotation is finite` when the angles are
/// not finite or so large that the rotation is not (`where` locates the attribute: "FILE:LINE: <origin>
/// rpy").
Mat3 rotation_from_rpy(const Vec3& roll_pitch_yaw, std::string_view where);
/// A mesh reference as a file path: relative paths against `base_dir`; `package://P/rest` and
/// `model://P/rest` as `base_dir/rest` or `base_dir/../rest` when one exists; `file://` stripped. Empty
/// when it cannot be resolved to an existing file.
std::string resolve_mesh_path(const std::string& uri, const std::string& base_dir);
/// Sets link.inertia_link = R J_file Rᵀ from link.R_link_inertial and link.inertia_file.
void finish_inertial(RobotLink& link);
/// Sets link.value_spans to `spans` when every one was located; leaves them empty otherwise (the tensor then
/// cannot be edited in place).
void set_spans(RobotLink& link, const std::vector<std::optional<TextSpan>>& spans);

/// Reads a format's <inertial> element into a link.
using InertialReader = void (*)(const XmlSource&, const tinyxml2::XMLElement&, RobotLink&);
/// How a format writes a <geometry>'s shape: URDF in attributes (`<box size="x y z"/>`), SDF in child
/// elements (`<box><size>x y z</size></box>`). Each function throws InvalidInput naming the element's line
/// and the missing or malformed field.
struct ShapeSyntax {
  /// One length (m) of `shape` named `name` (a radius, a length).
  double (*length)(const XmlSource&, const tinyxml2::XMLElement& shape, const char* name);
  /// Three lengths (m) of `shape` named `name` (a box's size, an ellipsoid's radii).
  Vec3 (*lengths)(const XmlSource&, const tinyxml2::XMLElement& shape, const char* name);
  /// A <mesh>'s file reference as written.
  std::string (*mesh_uri)(const XmlSource&, const tinyxml2::XMLElement& mesh);
  /// A <mesh>'s scale factors per axis, when given.
  std::optional<Vec3> (*mesh_scale)(const XmlSource&, const tinyxml2::XMLElement& mesh);
  /// Whether the format has an <ellipsoid> (SDF does, URDF does not).
  bool has_ellipsoid = false;
};

/// Reads the pose of a <collision> or <visual> element into g (R_link_geometry, position_link); returns
/// false, with a note in the link, when the shape is to be skipped.
using GeometryPoseReader = bool (*)(const XmlSource&, const tinyxml2::XMLElement& holder, LinkGeometry& g,
                                    RobotLink& link);

/// The shape of a <collision> or <visual> element (the holder of a <geometry>) of URDF or SDF, appended to
/// link.geometry: box, sphere, cylinder, capsule, ellipsoid (where the format has it) and mesh (the path
/// resolved against `base_dir`). A missing shape, an unresolved mesh or an unknown geometry is skipped with a
/// note in link.notes; a malformed field throws InvalidInput.
void read_link_shape(const XmlSource& xml, const tinyxml2::XMLElement& holder, const std::string& base_dir,
                     GeometryPoseReader read_pose, const ShapeSyntax& syntax, RobotLink& link);

/// A <link> of URDF or SDF, which share its layout: the name (an InvalidInput naming the element's line when
/// it has none), the line, the inertial and the shapes: every <collision>, or every <visual> when the link
/// has no collision shape (collision shapes describe the volume; visual ones only stand in for them).
RobotLink read_link_element(const XmlSource& xml, const tinyxml2::XMLElement& e, const std::string& base_dir,
                            InertialReader read_inertial, GeometryPoseReader read_pose,
                            const ShapeSyntax& syntax);

}  // namespace poinsot::io::detail
