// model_check_json and model_check_text of model_check.hpp: the one serialisation of a model check.
#include <fmt/format.h>

#include "io/json_values.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/io/robot/model_check.hpp"

namespace poinsot::io {
namespace {

using detail::json;

std::string matrix_rows(const Mat3& m) {
  std::string s;
  for (int i = 0; i < 3; ++i)
    s += fmt::format("    [{:>14.7g} {:>14.7g} {:>14.7g}]\n", m(i, 0), m(i, 1), m(i, 2));
  return s;
}

}  // namespace

std::string model_check_json(const ModelCheck& check) {
  json j;
  j["format"] = to_string(check.format);
  j["source"] = check.source;
  j["options"] = {{"density_min", check.options.density_min},
                  {"density_max", check.options.density_max},
                  {"ratio_limit", check.options.ratio_limit},
                  {"validity_tolerance", check.options.validity_tolerance}};
  j["invalid"] = check.invalid;
  j["warnings"] = check.warnings;
  json links = json::array();
  for (const LinkCheck& c : check.links) {
    json l;
    l["name"] = c.name;
    l["line"] = c.line;
    if (!c.file.empty()) l["file"] = c.file;
    l["has_inertial"] = c.has_inertial;
    if (c.has_inertial) {
      l["mass"] = c.mass;
      l["center_of_mass"] = detail::vec(c.com_link);
      l["inertia_com"] = detail::mat(c.inertia_link);
      l["principal_moments"] = detail::vec(c.principal.moments);
      l["principal_axes"] = detail::mat(c.principal.axes);
      l["valid"] = c.validity.valid;
      l["condition"] = c.validity.condition;
      l["amount"] = c.validity.amount;
      l["message"] = c.validity.message;
      l["repair"] = c.repair ? json{{"inertia", detail::mat(c.repair->inertia)},
                                    {"moments_before", detail::vec(c.repair->moments_before)},
                                    {"moments_after", detail::vec(c.repair->moments_after)},
                                    {"distance", c.repair->distance}}
                             : json(nullptr);
      l["geometry"] = c.geometry ? json{{"source", c.geometry->source},
                                        {"volume", c.geometry->volume},
                                        {"mass", c.geometry->props.mass},
                                        {"center_of_mass", detail::vec(c.geometry->props.com)},
                                        {"inertia_com", detail::mat(c.geometry->props.inertia_com)},
                                        {"box_min", detail::vec(c.geometry->box_min)},
                                        {"box_max", detail::vec(c.geometry->box_max)}}
                                 : json(nullptr);
      l["implied_density"] = detail::opt(c.implied_density);
      l["trace_ratio"] = detail::opt(c.trace_ratio);
    }
    l["warnings"] = c.warnings;
    l["notes"] = c.notes;
    links.push_back(std::move(l));
  }
  j["links"] = std::move(links);
  return j.dump(-1, ' ', false, nlohmann::ordered_json::error_handler_t::replace);
}

std::string model_check_text(const ModelCheck& check) {
  std::string out = fmt::format("{} ({}): {} links, {} invalid, {} warnings\n", check.source,
                                to_string(check.format), check.links.size(), check.invalid, check.warnings);
  for (const LinkCheck& c : check.links) {
    out += fmt::format("\nlink {} (line {}{})\n", c.name, c.line, c.file.empty() ? "" : " of " + c.file);
    if (c.has_inertial) {
      out += fmt::format("  mass:              {} kg\n", format_number(c.mass));
      out += fmt::format("  centre of mass:    {} m (link frame)\n", format_vector(c.com_link));
      out += "  inertia J about the centre of mass (kg·m², link frame):\n" + matrix_rows(c.inertia_link);
      out += fmt::format("  principal moments: {} kg·m²\n", format_vector(c.principal.moments));
      out += "  principal axes (columns):\n" + matrix_rows(c.principal.axes);
      out += fmt::format("  valid:             {}\n", c.validity.valid ? "yes" : "no: " + c.validity.message);
      if (c.repair) {
        out += fmt::format("  nearest valid:     moments {} kg·m², distance {} kg·m² (Frobenius)\n",
                           format_vector(c.repair->moments_after), format_number(c.repair->distance, 6));
        out += matrix_rows(c.repair->inertia);
      }
      if (c.implied_density)
        out += fmt::format("  implied density:   {} kg/m³ ({} geometry)\n",
                           format_number(*c.implied_density, 6), c.geometry->source);
    }
    for (const std::string& w : c.warnings)
      out += "  warning: " + w + "\n";
    for (const std::string& n : c.notes)
      out += "  note: " + n + "\n";
  }
  return out;
}

}  // namespace poinsot::io
