#pragma once
/// @file model_repair.hpp
/// `poinsot inertia check --repair`: a copy of a robot model (robot_model.hpp) in which only the numbers of
/// the chosen inertia tensors are replaced, in place, in the file's own text; every other byte is kept.
///
/// nearest_valid: each tensor that fails validity.hpp is replaced by the nearest valid tensor in the
/// Frobenius norm (repair_inertia). It is computed in the frame the file writes the tensor in; the norm is
/// invariant under rotation, so it is also the nearest in the link frame. A valid model is returned
/// unchanged, byte for byte.
/// from_geometry: each tensor is replaced by its link geometry's tensor about the geometry's own centre of
/// mass at the link's mass (model_check.hpp, geometry_inertia), re-expressed in the file's inertial frame
/// (J_file = Rᵀ J_link R). The centre of mass is not changed (the distance between the two is reported).
/// Links without inertial data or without usable geometry are left as they are (noted). MJCF diaginertia
/// can hold only a tensor diagonal in its frame: when the replacement is not (off-diagonal entries above
/// 1e-9 of its trace) the link is left unchanged and noted.
/// Numbers are written in the shortest form that reads back to the same double.
#include <string>
#include <vector>

#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/io/robot/robot_model.hpp"

namespace poinsot::io {

enum class RepairMode { nearest_valid, from_geometry };

struct LinkEdit {
  std::string link;
  Mat3 inertia_before = Mat3::Zero();  ///< about the centre of mass, link frame (kg·m²)
  Mat3 inertia_after = Mat3::Zero();   ///< the same after the edit
  double distance = 0.0;               ///< ‖after − before‖_F (kg·m²)
};

struct ModelRepair {
  std::string text;                  ///< the edited model
  std::vector<LinkEdit> edits;       ///< one per link whose tensor was replaced
  std::vector<std::string> skipped;  ///< one line per link that should have been edited and was not
};

/// Edits `model.text` as described in the file comment; `check` is check_model(model, ...) (its repairs and
/// geometry are used). Throws InvalidInput when a tensor to be replaced cannot be located in the text.
ModelRepair repair_model(const RobotModel& model, const ModelCheck& check, RepairMode mode);

/// A one-line-per-link summary of `repair` for the terminal, and the same as a JSON array.
std::string model_repair_text(const ModelRepair& repair);
std::string model_repair_json(const ModelRepair& repair);

}  // namespace poinsot::io
