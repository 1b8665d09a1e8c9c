// check_model of model_check.hpp: the validity verdict and plausibility warnings of each link.
#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/robot/model_check.hpp"

namespace poinsot::io {
namespace {

void check_options(const ModelCheckOptions& o) {
  if (!std::isfinite(o.density_min) || !(o.density_min > 0.0) || !std::isfinite(o.density_max) ||
      !(o.density_max >= o.density_min)) {
    throw InvalidInput(fmt::format("check: density range [{}, {}] kg/m³; expected 0 < min <= max, finite",
                                   format_number(o.density_min), format_number(o.density_max)));
  }
  if (!std::isfinite(o.ratio_limit) || !(o.ratio_limit > 1.0))
    throw InvalidInput(
        fmt::format("check: ratio limit {}; expected a finite number > 1", format_number(o.ratio_limit)));
}

void plausibility(const RobotLink& link, const ModelCheckOptions& o, LinkCheck& c) {
  if (link.mass == 0.0) {
    c.warnings.push_back("mass 0 kg: expected a positive mass (a zero mass with a tensor is not a body)");
    return;
  }
  if (link.mass < 0.0) {
    c.warnings.push_back(
        fmt::format("mass {} kg is negative; expected a positive mass", format_number(link.mass)));
    return;
  }
  c.geometry = geometry_inertia(link, link.mass, o, c.notes);
  if (!c.geometry) {
    c.notes.push_back(
        "no usable collision or visual geometry: plausibility against the geometry not checked");
    return;
  }
  const GeometryInertia& g = *c.geometry;
  c.implied_density = link.mass / g.volume;
  if (*c.implied_density < o.density_min || *c.implied_density > o.density_max) {
    c.warnings.push_back(
        fmt::format("implied density {} kg/m³ (mass {} kg / {} volume {} m³) is outside [{}, {}] kg/m³",
                    format_number(*c.implied_density, 4), format_number(link.mass), g.source,
                    format_number(g.volume, 6), format_number(o.density_min), format_number(o.density_max)));
  }
  const double trace = link.inertia_link.trace();
  const double trace_geometry = g.props.inertia_com.trace();
  c.trace_ratio = trace / trace_geometry;
  if (*c.trace_ratio > o.ratio_limit || *c.trace_ratio < 1.0 / o.ratio_limit) {
    c.warnings.push_back(fmt::format(
        "inertia trace {} kg·m² is {} times the {} geometry's {} kg·m² at this mass (more than {}× apart: "
        "units or frame?)",
        format_number(trace, 6), format_number(*c.trace_ratio, 4), g.source, format_number(trace_geometry, 6),
        format_number(o.ratio_limit)));
  }
  const double margin = 1e-9 * (g.box_max - g.box_min).norm();
  const Vec3& x = link.com_link;
  if ((x.array() < g.box_min.array() - margin).any() || (x.array() > g.box_max.array() + margin).any()) {
    c.warnings.push_back(
        fmt::format("centre of mass {} m is outside the {} geometry's bounding box {} to {} m",
                    format_vector(x), g.source, format_vector(g.box_min), format_vector(g.box_max)));
  }
}

}  // namespace

ModelCheck check_model(const RobotModel& model, const ModelCheckOptions& options) {
  check_options(options);
  if (model.links.empty())
    throw InvalidInput(fmt::format("{}: no link or body; expected a robot model with links", model.source));
  ModelCheck out;
  out.format = model.format;
  out.source = model.source;
  out.options = options;
  for (const RobotLink& link : model.links) {
    LinkCheck c;
    c.name = link.name;
    c.line = model.lines.line_in_file(link.line);
    c.file = model.lines.file(link.line);
    c.has_inertial = link.has_inertial;
    c.notes = link.notes;
    if (!link.has_inertial) {
      c.notes.push_back("no inertial element: nothing to check");
      out.links.push_back(std::move(c));
      continue;
    }
    c.mass = link.mass;
    c.com_link = link.com_link;
    c.inertia_link = link.inertia_link;
    c.principal = inertia::principal_axes(link.inertia_link);
    c.validity = inertia::check_inertia(link.inertia_link, options.validity_tolerance,
                                        "link " + link.name + " inertia");
    if (!c.validity.valid) {
      c.repair = inertia::repair_inertia(link.inertia_link);
      ++out.invalid;
    }
    plausibility(link, options, c);
    out.warnings += c.warnings.size();
    out.links.push_back(std::move(c));
  }
  return out;
}

}  // namespace poinsot::io
