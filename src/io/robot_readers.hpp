#pragma once
// Internal to the io layer: the three robot-model readers behind read_robot_model (robot_model.hpp) and the
// helpers they share. Each reader walks the tinyxml2 tree of an XmlSource and fills RobotModel::links.
#include <string>

#include "poinsot/io/robot_model.hpp"
#include "xml_source.hpp"

namespace poinsot::io::detail {

void read_urdf(const XmlSource& xml, const std::string& base_dir, RobotModel& model);
void read_mjcf(const XmlSource& xml, const std::string& base_dir, RobotModel& model);
void read_sdf(const XmlSource& xml, const std::string& base_dir, RobotModel& model);

/// The symmetric J from its entries (kg·m²).
Mat3 tensor_from_entries(double ixx, double iyy, double izz, double ixy, double ixz, double iyz);
/// R = R_z(yaw) R_y(pitch) R_x(roll): the fixed-axis roll-pitch-yaw of URDF and SDF (radians).
Mat3 rotation_from_rpy(const Vec3& roll_pitch_yaw);
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
/// Reads a format's <collision> or <visual> element (the holder of a <geometry>) into a link's geometry;
/// mesh paths resolve against the model's folder (the string).
using ShapeReader = void (*)(const XmlSource&, const tinyxml2::XMLElement&, const std::string&, RobotLink&);

/// A <link> of URDF or SDF, which share its layout: the name (an InvalidInput naming the element's line when
/// it has none), the line, the inertial and the shapes: every <collision>, or every <visual> when the link
/// has no collision shape (collision shapes describe the volume; visual ones only stand in for them).
RobotLink read_link_element(const XmlSource& xml, const tinyxml2::XMLElement& e, const std::string& base_dir,
                            InertialReader read_inertial, ShapeReader read_shape);

}  // namespace poinsot::io::detail
