// repair_model of model_repair.hpp: in-place edits of the inertia numbers of a robot model's text.
#include "poinsot/io/robot/model_repair.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::io {
namespace {

struct Edit {
  ValueSpan span;
  std::string value;
};

/// The replacement texts of `J_file` for the spans of `link` (see TensorLayout), or nothing when the layout
/// cannot hold it (diaginertia of a non-diagonal tensor).
std::optional<std::vector<Edit>> edits_for(const RobotLink& link, const Mat3& J) {
  const auto n = [](double x) { return format_number(x); };
  const auto& s = link.value_spans;
  switch (link.layout) {
    case TensorLayout::urdf_attributes:
    case TensorLayout::sdf_elements:
      // ixx ixy ixz iyy iyz izz
      return std::vector<Edit>{{s[0], n(J(0, 0))}, {s[1], n(J(0, 1))}, {s[2], n(J(0, 2))},
                               {s[3], n(J(1, 1))}, {s[4], n(J(1, 2))}, {s[5], n(J(2, 2))}};
    case TensorLayout::mjcf_full:
      return std::vector<Edit>{{s[0], fmt::format("{} {} {} {} {} {}", n(J(0, 0)), n(J(1, 1)), n(J(2, 2)),
                                                  n(J(0, 1)), n(J(0, 2)), n(J(1, 2)))}};
    case TensorLayout::mjcf_diag: {
      const double off = std::max({std::abs(J(0, 1)), std::abs(J(0, 2)), std::abs(J(1, 2))});
      if (off > 1e-9 * std::abs(J.trace())) return std::nullopt;
      return std::vector<Edit>{{s[0], fmt::format("{} {} {}", n(J(0, 0)), n(J(1, 1)), n(J(2, 2)))}};
    }
  }
  return std::nullopt;
}

}  // namespace

ModelRepair repair_model(const RobotModel& model, const ModelCheck& check, RepairMode mode) {
  ModelRepair out;
  std::vector<Edit> edits;
  for (std::size_t k = 0; k < model.links.size() && k < check.links.size(); ++k) {
    const RobotLink& link = model.links[k];
    const LinkCheck& c = check.links[k];
    if (!link.has_inertial) continue;
    Mat3 J_file;
    if (mode == RepairMode::nearest_valid) {
      if (c.validity.valid) continue;
      // Nearest in the file's frame (the same tensor as the link-frame repair, rotated; computed here so
      // that a diagonal tensor stays exactly diagonal).
      J_file = inertia::repair_inertia(link.inertia_file).inertia;
    } else {
      if (!c.geometry) {
        out.skipped.push_back(fmt::format("link {}: no usable geometry; tensor kept", link.name));
        continue;
      }
      if (!c.geometry->props.inertia_com.allFinite()) {
        out.skipped.push_back(
            fmt::format("link {}: the geometry's tensor is not finite; tensor kept", link.name));
        continue;
      }
      J_file = inertia::reexpress(c.geometry->props.inertia_com, link.R_link_inertial.transpose());
    }
    if (link.value_spans.empty()) {
      throw InvalidInput(
          fmt::format("{}: link {}: the inertia values are not plain text in the file; cannot "
                      "edit them in place",
                      model.lines.location(link.line), link.name));
    }
    auto e = edits_for(link, J_file);
    if (!e) {
      out.skipped.push_back(fmt::format(
          "link {}: diaginertia cannot hold the replacement, which is not diagonal in the inertial "
          "frame; tensor kept",
          link.name));
      continue;
    }
    edits.insert(edits.end(), e->begin(), e->end());
    LinkEdit le;
    le.link = link.name;
    le.inertia_before = link.inertia_link;
    le.inertia_after = inertia::reexpress(J_file, link.R_link_inertial);
    le.distance = (le.inertia_after - le.inertia_before).norm();
    out.edits.push_back(std::move(le));
  }
  // Apply from the end so that earlier offsets stay valid.
  std::sort(edits.begin(), edits.end(),
            [](const Edit& a, const Edit& b) { return a.span.begin > b.span.begin; });
  out.text = model.text;
  for (const Edit& e : edits)
    out.text.replace(e.span.begin, e.span.end - e.span.begin, e.value);
  return out;
}

std::string model_repair_text(const ModelRepair& repair) {
  std::string out;
  for (const LinkEdit& e : repair.edits) {
    out += fmt::format("repaired link {}: distance {} kg·m² (Frobenius)\n", e.link,
                       format_number(e.distance, 6));
  }
  for (const std::string& s : repair.skipped)
    out += "not repaired: " + s + "\n";
  if (repair.edits.empty() && repair.skipped.empty()) out += "nothing to repair: the file is unchanged\n";
  return out;
}

std::string model_repair_json(const ModelRepair& repair) {
  nlohmann::ordered_json edits = nlohmann::ordered_json::array();
  const auto mat = [](const Mat3& m) {
    return nlohmann::ordered_json::array(
        {{m(0, 0), m(0, 1), m(0, 2)}, {m(1, 0), m(1, 1), m(1, 2)}, {m(2, 0), m(2, 1), m(2, 2)}});
  };
  for (const LinkEdit& e : repair.edits) {
    edits.push_back({{"link", e.link},
                     {"inertia_before", mat(e.inertia_before)},
                     {"inertia_after", mat(e.inertia_after)},
                     {"distance", e.distance}});
  }
  nlohmann::ordered_json j;
  j["edits"] = std::move(edits);
  j["skipped"] = repair.skipped;
  return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

}  // namespace poinsot::io
