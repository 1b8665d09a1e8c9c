// The inertia of a scenario's body from a shape or a mesh, through the inertia layer (see scenario_body.hpp).
#include "scenario_body.hpp"

#include <filesystem>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"

namespace poinsot::io::detail {
namespace {

/// The keys each shape takes besides type, mass and density (sizes in m).
const std::map<std::string, std::vector<std::string_view>, std::less<>>& shape_keys() {
  static const std::map<std::string, std::vector<std::string_view>, std::less<>> keys = {
      {"point", {}},
      {"rod", {"length"}},
      {"plate", {"size"}},
      {"box", {"size"}},
      {"sphere", {"radius", "inner_radius", "hollow"}},
      {"cylinder", {"radius", "length", "inner_radius", "hollow"}},
      {"cone", {"radius", "height"}},
      {"ellipsoid", {"size"}},
      {"capsule", {"radius", "length"}},
      {"torus", {"major_radius", "minor_radius"}},
  };
  return keys;
}

/// mass or density, exactly one, > 0.
std::pair<bool, double> mass_or_density(const Section& s) {
  const auto which = s.exactly_one({"mass", "density"}, "the amount of matter");
  const double x = *s.number(which);
  if (!(x > 0.0)) s.fail(which, fmt::format("got {}, expected a number > 0", format_number(x)));
  return {which == "mass", x};
}

template <class F>
auto located(const Section& s, std::string_view key, F&& f) {
  try {
    return f();
  } catch (const InvalidInput& e) {
    s.fail(key, e.what());
  }
}

}  // namespace

BodyInertia body_from_shape(const Source& source, const toml::table& shape, const toml::node* position) {
  const Section probe(source, &shape, "body.shape",
                      {"type", "mass", "density", "size", "radius", "length", "height", "inner_radius",
                       "major_radius", "minor_radius", "hollow"},
                      position);
  probe.require("type", "one of point, rod, plate, box, sphere, cylinder, cone, ellipsoid, capsule, torus");
  const std::string type = *probe.string("type");
  const auto it = shape_keys().find(type);
  if (it == shape_keys().end()) {
    probe.fail("type",
               fmt::format("got \"{}\", expected one of point, rod, plate, box, sphere, cylinder, cone, "
                           "ellipsoid, capsule, torus",
                           type));
  }
  // Keys that this type does not take are errors (with the ones it takes listed).
  std::string valid = "type, mass, density";
  for (const auto& k : it->second)
    valid += fmt::format(", {}", k);
  for (const auto& [key, value] : shape) {
    bool ok = key.str() == "type" || key.str() == "mass" || key.str() == "density";
    for (const auto& k : it->second)
      ok = ok || key.str() == k;
    if (!ok) {
      const auto& at = key.source().begin;
      const std::string where =
          at.line > 0 ? fmt::format("{}:{}:{}: ", source.name, at.line, at.column) : location(source, &value);
      throw InvalidInput(fmt::format("{}[body.shape] key \"{}\" does not apply to a {}; valid keys: {}",
                                     where, key.str(), type, valid));
    }
  }
  const Section& s = probe;
  inertia::ShapeSpec spec;
  spec.kind = type;
  const auto need = [&](std::string_view key, std::string_view what) {
    if (!s.has(key)) s.fail(key, fmt::format("missing; a {} needs {}", type, what));
  };
  if (type == "plate") {
    need("size", "size = [a, b] (m, in the xy-plane)");
    const auto v = *s.numbers("size", 2);
    spec.size = Vec3(v[0], v[1], 0.0);
  } else if (type == "box" || type == "ellipsoid") {
    need("size", type == "box" ? "size = [a, b, c] (m, edge lengths)" : "size = [a, b, c] (m, semi-axes)");
    spec.size = *s.vec3("size");
  }
  for (const auto& k : it->second) {
    if (k == "size" || k == "hollow" || k == "inner_radius") continue;
    need(k, fmt::format("{} (m)", k));
  }
  spec.radius = s.number("radius").value_or(0.0);
  spec.length = s.number("length").value_or(0.0);
  spec.height = s.number("height").value_or(0.0);
  spec.inner_radius = s.number("inner_radius").value_or(0.0);
  spec.major_radius = s.number("major_radius").value_or(0.0);
  spec.minor_radius = s.number("minor_radius").value_or(0.0);
  spec.hollow = s.boolean("hollow").value_or(false);
  const auto [by_mass, amount] = mass_or_density(s);
  const inertia::MassProperties mp = located(s, "type", [&] {
    return by_mass ? inertia::shape_with_mass(spec, amount) : inertia::shape_with_density(spec, amount);
  });
  BodyInertia out;
  out.inertia_com = mp.inertia_com;
  out.mass = mp.mass;
  out.com = mp.com;
  std::string sizes;
  if (s.has("size")) sizes += fmt::format(" size {} m", describe(*s.node("size")));
  for (const char* k : {"radius", "inner_radius", "length", "height", "major_radius", "minor_radius"}) {
    if (s.has(k)) sizes += fmt::format(" {} {} m", k, format_number(*s.number(k)));
  }
  out.description = fmt::format(
      "{}{}{}, mass {} kg (shape of the inertia layer, frame: its centre of mass and "
      "axes)",
      spec.hollow ? "hollow " : "", type, sizes, format_number(mp.mass));
  return out;
}

BodyInertia body_from_mesh(const Source& source, const toml::table& mesh, const toml::node* position,
                           std::string_view base_dir) {
  const Section s(source, &mesh, "body.mesh", {"file", "mass", "density", "shell", "flip_inward"}, position);
  s.require("file", "the path of a closed triangle mesh (STL, OBJ, PLY, OFF), relative to the scenario file");
  std::filesystem::path file(*s.string("file"));
  if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
  const auto [by_mass, amount] = mass_or_density(s);
  const bool shell = s.boolean("shell").value_or(false);
  inertia::MeshOptions options;
  options.flip_inward = s.boolean("flip_inward").value_or(false);
  const inertia::TriangleMesh m = located(s, "file", [&] { return inertia::load_mesh(file.string()); });
  const inertia::MassProperties mp = located(s, "file", [&, by_mass = by_mass, amount = amount] {
    if (shell) {
      return by_mass ? inertia::mesh_shell_mass_properties_with_mass(m, amount)
                     : inertia::mesh_shell_mass_properties(m, amount);
    }
    return by_mass ? inertia::mesh_mass_properties_with_mass(m, amount, options)
                   : inertia::mesh_mass_properties(m, amount, options);
  });
  BodyInertia out;
  out.inertia_com = mp.inertia_com;
  out.mass = mp.mass;
  out.com = mp.com;
  out.description = fmt::format(
      "{}mesh {} ({} triangles), {} {} {}, mass {} kg, centre of mass {} m (mesh frame)",
      shell ? "thin-shell " : "", file.string(), m.triangles.size(), by_mass ? "mass" : "density",
      format_number(amount), by_mass ? "kg" : (shell ? "kg/m²" : "kg/m³"), format_number(mp.mass, 7),
      fmt::format("({}, {}, {})", format_number(mp.com.x(), 7), format_number(mp.com.y(), 7),
                  format_number(mp.com.z(), 7)));
  return out;
}

}  // namespace poinsot::io::detail
