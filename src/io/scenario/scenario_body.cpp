// The inertia of a scenario's body: explicit tensors, or a shape, a mesh or a composite body file through the
// inertia layer (see scenario_body.hpp).
#include "scenario_body.hpp"

#include <algorithm>
#include <filesystem>
#include <map>
#include <vector>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/body_file.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"

namespace poinsot::io::detail {
namespace {

/// The keys each shape takes besides type, mass and density (sizes in m; axis "x", "y" or "z").
const std::map<std::string, std::vector<std::string_view>, std::less<>>& shape_keys() {
  static const std::map<std::string, std::vector<std::string_view>, std::less<>> keys = {
      {"point", {}},
      {"rod", {"length", "radius", "axis"}},
      {"plate", {"size"}},
      {"box", {"size"}},
      {"sphere", {"radius", "inner_radius", "hollow"}},
      {"cylinder", {"radius", "length", "inner_radius", "hollow", "axis"}},
      {"cone", {"radius", "height", "axis"}},
      {"ellipsoid", {"size"}},
      {"capsule", {"radius", "length", "axis"}},
      {"torus", {"major_radius", "minor_radius", "axis"}},
  };
  return keys;
}

/// The amount of matter of a shape or mesh table: its `mass` or `density` (exactly one, > 0), or else the
/// body's `mass`. Returns (given as a mass, value).
std::pair<bool, double> amount_of_matter(const Section& table, const Section& body) {
  if (!table.has("mass") && !table.has("density") && body.has("mass")) {
    const double m = *body.number("mass");
    if (!(m > 0.0)) body.fail("mass", fmt::format("got {} kg, expected a number > 0", format_number(m)));
    return {true, m};
  }
  if (!table.has("mass") && !table.has("density")) {
    table.fail("mass", fmt::format("missing; expected mass (kg) or density in the table, or {} (the amount "
                                   "of matter)",
                                   body.label("mass")));
  }
  const auto which = table.exactly_one({"mass", "density"}, "the amount of matter");
  const double x = *table.number(which);
  if (!(x > 0.0)) table.fail(which, fmt::format("got {}, expected a number > 0", format_number(x)));
  return {which == "mass", x};
}

/// A mass given twice: in the table (or its file) and as the body's `mass`.
void refuse_body_mass(const Section& body, std::string_view how, double mass) {
  if (!body.has("mass")) return;
  body.fail("mass", fmt::format("got {} kg, but the {} already gives the mass ({} kg); remove {}",
                                format_number(body.number("mass").value_or(0.0)), how, format_number(mass),
                                body.label("mass")));
}

/// The rotation that lays a shape's symmetry axis (its z) along the body axis `axis`, as a cyclic permutation
/// of the axes (det +1): z → x takes x → y, y → z; z → y takes x → z, y → x.
Mat3 axis_rotation(char axis) {
  Mat3 R = Mat3::Zero();
  const int k = axis == 'x' ? 0 : axis == 'y' ? 1 : 2;
  for (int i = 0; i < 3; ++i)
    R((i + k + 1) % 3, i) = 1.0;  // shape axis i → body axis (i + k + 1) mod 3; z (i = 2) → k
  return R;
}

std::string format_point(const Vec3& p) {
  return fmt::format("({}, {}, {})", format_number(p.x(), 7), format_number(p.y(), 7),
                     format_number(p.z(), 7));
}

/// The drawn surface of a shape (shapes.hpp frame, turned by `axes`: shape axis i → body axis), about its
/// centre of mass; null for the shapes without a solid to draw (point, rod, thin shells). A plate is a box
/// of no thickness.
std::shared_ptr<const inertia::TriangleMesh> shape_surface(const inertia::ShapeSpec& spec, const Mat3& axes) {
  inertia::TriangleMesh m;
  if (spec.kind == "plate") {
    m = inertia::box_mesh(Vec3(spec.size.x(), spec.size.y(), 0.0));
  } else if (spec.kind == "point" || spec.kind == "rod" || spec.hollow) {
    return nullptr;
  } else {
    m = inertia::tessellate(spec, inertia::kDrawnSurfaceSegments);
  }
  for (Vec3& v : m.vertices)
    v = axes * v;
  return std::make_shared<const inertia::TriangleMesh>(std::move(m));
}

BodyInertia from_shape(const Source& source, const Section& body, char default_axis) {
  const std::string name = body.name() + ".shape";
  const toml::table* shape = body.table("shape");
  const Section probe(source, shape, name,
                      {"type", "mass", "density", "size", "radius", "length", "height", "inner_radius",
                       "major_radius", "minor_radius", "hollow", "axis"},
                      body.node("shape"));
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
  for (const auto& [key, value] : *shape) {
    bool ok = key.str() == "type" || key.str() == "mass" || key.str() == "density";
    for (const auto& k : it->second)
      ok = ok || key.str() == k;
    if (!ok) {
      const auto& at = key.source().begin;
      const std::string where =
          at.line > 0 ? fmt::format("{}:{}:{}: ", source.name, at.line, at.column) : location(source, &value);
      throw InvalidInput(fmt::format("{}[{}] key \"{}\" does not apply to a {}; valid keys: {}", where, name,
                                     key.str(), type, valid));
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
    if (k == "size" || k == "hollow" || k == "inner_radius" || k == "axis" ||
        (type == "rod" && k == "radius"))
      continue;
    need(k, fmt::format("{} (m)", k));
  }
  spec.radius = s.number("radius").value_or(0.0);
  spec.length = s.number("length").value_or(0.0);
  spec.height = s.number("height").value_or(0.0);
  spec.inner_radius = s.number("inner_radius").value_or(0.0);
  spec.major_radius = s.number("major_radius").value_or(0.0);
  spec.minor_radius = s.number("minor_radius").value_or(0.0);
  spec.hollow = s.boolean("hollow").value_or(false);
  if (type == "rod" && s.has("radius")) spec.kind = "cylinder";  // a rod of finite radius: a solid cylinder
  char axis = default_axis;
  if (const auto a = s.string("axis")) {
    if (*a != "x" && *a != "y" && *a != "z")
      s.fail("axis", fmt::format("got \"{}\", expected \"x\", \"y\" or \"z\" (the body axis of the {}'s "
                                 "symmetry axis)",
                                 *a, type));
    axis = (*a)[0];
  }
  const auto [by_mass, amount] = amount_of_matter(s, body);
  inertia::MassProperties mp = located(s, "type", [&, by_mass = by_mass, amount = amount] {
    return by_mass ? inertia::shape_with_mass(spec, amount) : inertia::shape_with_density(spec, amount);
  });
  const bool has_axis = std::find(it->second.begin(), it->second.end(), "axis") != it->second.end();
  if (has_axis && axis != 'z') mp = mp.placed(axis_rotation(axis), Vec3::Zero());
  if (s.has("mass") || s.has("density")) refuse_body_mass(body, "shape", mp.mass);
  BodyInertia out;
  out.inertia_com = mp.inertia_com;
  out.mass = mp.mass;
  out.com = mp.com;
  out.surface = shape_surface(spec, has_axis && axis != 'z' ? axis_rotation(axis) : Mat3::Identity());
  std::string sizes;
  if (s.has("size")) sizes += fmt::format(" size {} m", describe(*s.node("size")));
  for (const char* k : {"radius", "inner_radius", "length", "height", "major_radius", "minor_radius"}) {
    if (s.has(k)) sizes += fmt::format(" {} {} m", k, format_number(*s.number(k)));
  }
  out.description =
      fmt::format("{}{}{}{}, mass {} kg (shape of the inertia layer, frame: its centre of mass and axes)",
                  spec.hollow ? "hollow " : "", type, sizes, has_axis ? fmt::format(" along {}", axis) : "",
                  format_number(mp.mass));
  return out;
}

BodyInertia from_mesh(const Source& source, const Section& body, std::string_view base_dir) {
  const Section s(source, body.table("mesh"), body.name() + ".mesh",
                  {"file", "mass", "density", "shell", "flip_inward"}, body.node("mesh"));
  s.require("file", "the path of a closed triangle mesh (STL, OBJ, PLY, OFF), relative to the scenario file");
  std::filesystem::path file(*s.string("file"));
  if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
  const auto [by_mass, amount] = amount_of_matter(s, body);
  const bool shell = s.boolean("shell").value_or(false);
  inertia::MeshOptions options;
  options.flip_inward = s.boolean("flip_inward").value_or(false);
  inertia::TriangleMesh m = located(s, "file", [&] { return inertia::load_mesh(file.string()); });
  const inertia::MassProperties mp = located(s, "file", [&, by_mass = by_mass, amount = amount] {
    if (shell) {
      return by_mass ? inertia::mesh_shell_mass_properties_with_mass(m, amount)
                     : inertia::mesh_shell_mass_properties(m, amount);
    }
    return by_mass ? inertia::mesh_mass_properties_with_mass(m, amount, options)
                   : inertia::mesh_mass_properties(m, amount, options);
  });
  if (s.has("mass") || s.has("density")) refuse_body_mass(body, "mesh", mp.mass);
  BodyInertia out;
  out.inertia_com = mp.inertia_com;
  out.mass = mp.mass;
  out.com = mp.com;
  const std::size_t triangles = m.triangles.size();
  for (Vec3& v : m.vertices)  // the mesh itself becomes the surface (no copy of a large mesh)
    v -= mp.com;
  out.surface = std::make_shared<const inertia::TriangleMesh>(std::move(m));
  out.description =
      fmt::format("{}mesh {} ({} triangles), {} {} {}, mass {} kg, centre of mass {} m (mesh frame)",
                  shell ? "thin-shell " : "", file.string(), triangles, by_mass ? "mass" : "density",
                  format_number(amount), by_mass ? "kg" : (shell ? "kg/m²" : "kg/m³"),
                  format_number(mp.mass, 7), format_point(mp.com));
  return out;
}

BodyInertia from_composite(const Source& source, const Section& body, std::string_view base_dir) {
  const Section s(source, body.table("composite"), body.name() + ".composite", {"file"},
                  body.node("composite"));
  s.require("file",
            "the path of a composite body file (TOML with [[part]] and [[void]] entries, "
            "docs/inertia.md), relative to the scenario file");
  std::filesystem::path file(*s.string("file"));
  if (file.is_relative() && !base_dir.empty()) file = std::filesystem::path(base_dir) / file;
  const inertia::BodyFileResult r =
      located(s, "file", [&] { return inertia::load_body_file(file.string()); });
  refuse_body_mass(body, "composite", r.body.mass);
  BodyInertia out;
  out.inertia_com = r.body.inertia_com;
  out.mass = r.body.mass;
  out.com = r.body.com;
  out.description =
      fmt::format("composite {} ({} parts, {} voids), mass {} kg, centre of mass {} m (file frame)",
                  file.string(), r.parts, r.voids, format_number(r.body.mass, 7), format_point(r.body.com));
  for (const auto& d : r.diagnostics)
    out.description += "; " + d;
  return out;
}

/// `inertia` or `poinsot`: [a, b, c] (the diagonal) or three rows of three numbers.
Mat3 tensor(const Section& body, std::string_view key) {
  const toml::node* n = body.node(key);
  const toml::array* a = n->as_array();
  if (a != nullptr && a->size() == 3 && !(*a)[0].is_array()) return body.vec3(key)->asDiagonal();
  return *body.mat3(key);
}

}  // namespace

BodyInertia read_body_inertia(const Source& source, const Section& body, std::string_view base_dir,
                              char default_axis) {
  const std::string_view how =
      body.exactly_one({"principal_moments", "inertia", "poinsot", "shape", "mesh", "composite"},
                       "the inertia (one way to give it)");
  BodyInertia out;
  if (how == "shape") {
    out = from_shape(source, body, default_axis);
  } else if (how == "mesh") {
    out = from_mesh(source, body, base_dir);
  } else if (how == "composite") {
    out = from_composite(source, body, base_dir);
  } else {
    out.mass = body.number("mass");
    if (how == "principal_moments") {
      const Vec3 m = *body.vec3(how);
      out.inertia_com = m.asDiagonal();
      out.description = fmt::format("principal moments {} kg·m²", format_vector(m));
    } else if (how == "inertia") {
      out.inertia_com = tensor(body, how);
      out.description =
          fmt::format("inertia tensor {} kg·m² about the centre of mass", format_matrix(out.inertia_com));
    } else {
      out.poinsot_com = tensor(body, how);
      out.inertia_com = inertia::inertia_from_poinsot(out.poinsot_com);
      out.description =
          fmt::format("Poinsot tensor {} kg·m² about the centre of mass", format_matrix(out.poinsot_com));
    }
  }
  out.how = std::string(how);
  if (how != "poinsot") out.poinsot_com = inertia::poinsot_from_inertia(out.inertia_com);
  return out;
}

}  // namespace poinsot::io::detail
