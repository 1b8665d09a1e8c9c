#include "poinsot/inertia/body_file.hpp"

#include <filesystem>
#include <fstream>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>

#include <fmt/format.h>
#include <toml++/toml.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/text_file.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::inertia {
namespace {

const std::set<std::string> kKeys{"shape",  "mesh",           "size",         "radius",       "length",
                                  "height", "inner_radius",   "major_radius", "minor_radius", "hollow",
                                  "mass",   "density",        "position",     "quaternion",   "axis_angle",
                                  "euler",  "euler_sequence", "degrees",      "shell",        "flip_inward"};

/// One [[part]] or [[void]] table being read; `name` is "part 2" etc. for messages.
class Entry {
 public:
  Entry(const toml::table& t, std::string name) : t_(t), name_(std::move(name)) {}

  const std::string& name() const { return name_; }

  std::optional<double> number(const char* key) const {
    const toml::node* n = t_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto v = n->value<double>();
    if (!v) throw InvalidInput(fmt::format("{}: {} must be a number", name_, key));
    require_finite(fmt::format("{}: {}", name_, key), *v);
    return v;
  }
  double number_or(const char* key, double fallback) const { return number(key).value_or(fallback); }

  std::optional<std::vector<double>> numbers(const char* key, std::size_t count) const {
    const toml::node* n = t_.get(key);
    if (n == nullptr) return std::nullopt;
    const toml::array* a = n->as_array();
    if (a == nullptr || a->size() != count) {
      throw InvalidInput(fmt::format("{}: {} must be an array of {} numbers", name_, key, count));
    }
    std::vector<double> out;
    for (const auto& e : *a) {
      const auto v = e.value<double>();
      if (!v) throw InvalidInput(fmt::format("{}: {} must be an array of {} numbers", name_, key, count));
      require_finite(fmt::format("{}: {}", name_, key), *v);
      out.push_back(*v);
    }
    return out;
  }

  std::optional<std::vector<double>> numbers_any(const char* key) const {
    const toml::node* n = t_.get(key);
    if (n == nullptr) return std::nullopt;
    const toml::array* a = n->as_array();
    if (a == nullptr) throw InvalidInput(fmt::format("{}: {} must be an array of numbers", name_, key));
    return numbers(key, a->size());
  }

  std::optional<std::string> text(const char* key) const {
    const toml::node* n = t_.get(key);
    if (n == nullptr) return std::nullopt;
    const auto v = n->value<std::string>();
    if (!v) throw InvalidInput(fmt::format("{}: {} must be a string", name_, key));
    return v;
  }

  bool flag(const char* key) const {
    const toml::node* n = t_.get(key);
    if (n == nullptr) return false;
    const auto v = n->value<bool>();
    if (!v) throw InvalidInput(fmt::format("{}: {} must be true or false", name_, key));
    return *v;
  }

  void check_keys() const {
    for (const auto& [k, v] : t_) {
      if (!kKeys.contains(std::string(k.str()))) {
        throw InvalidInput(
            fmt::format("{}: unknown key \"{}\"; expected shape or mesh, sizes, mass or density, "
                        "position and one orientation (quaternion, axis_angle, euler)",
                        name_, k.str()));
      }
    }
  }

 private:
  const toml::table& t_;
  std::string name_;
};

Mat3 orientation(const Entry& e) {
  const double unit = e.flag("degrees") ? std::numbers::pi / 180.0 : 1.0;
  const auto q = e.numbers("quaternion", 4);
  const auto aa = e.numbers("axis_angle", 4);
  const auto eu = e.numbers("euler", 3);
  const int given = int{q.has_value()} + int{aa.has_value()} + int{eu.has_value()};
  if (given > 1) {
    throw InvalidInput(
        fmt::format("{}: got {} orientations, expected at most one of quaternion, axis_angle, "
                    "euler",
                    e.name(), given));
  }
  if (q) return so3::rotation_from_quaternion(Quat((*q)[0], (*q)[1], (*q)[2], (*q)[3]));
  if (aa) return so3::rotation_from_axis_angle(Vec3((*aa)[0], (*aa)[1], (*aa)[2]), (*aa)[3] * unit);
  if (eu) {
    const auto seq = so3::EulerSequence::parse(e.text("euler_sequence").value_or("ZYX"));
    return so3::rotation_from_euler(seq, Vec3((*eu)[0], (*eu)[1], (*eu)[2]) * unit);
  }
  return Mat3::Identity();
}

/// `size` has 3 entries (box, ellipsoid) or 2 (plate).
Vec3 size_of(const Entry& e) {
  const auto v = e.numbers_any("size");
  if (!v) return Vec3::Zero();
  if (v->size() == 2) return Vec3((*v)[0], (*v)[1], 0.0);
  if (v->size() == 3) return Vec3((*v)[0], (*v)[1], (*v)[2]);
  throw InvalidInput(fmt::format("{}: size must be an array of 2 (plate) or 3 numbers", e.name()));
}

MassProperties evaluate(const Entry& e, const std::string& base_dir, std::vector<std::string>& diagnostics) {
  e.check_keys();
  const auto shape = e.text("shape");
  const auto mesh = e.text("mesh");
  if (shape.has_value() == mesh.has_value()) {
    throw InvalidInput(
        fmt::format("{}: expected exactly one of shape = \"...\" or mesh = \"FILE\"", e.name()));
  }
  const auto mass = e.number("mass");
  const auto density = e.number("density");
  if (mass.has_value() == density.has_value()) {
    throw InvalidInput(fmt::format("{}: expected exactly one of mass (kg) or density", e.name()));
  }
  MassProperties local;
  if (shape) {
    ShapeSpec s;
    s.kind = *shape;
    s.size = size_of(e);
    s.radius = e.number_or("radius", 0.0);
    s.length = e.number_or("length", 0.0);
    s.height = e.number_or("height", 0.0);
    s.inner_radius = e.number_or("inner_radius", 0.0);
    s.major_radius = e.number_or("major_radius", 0.0);
    s.minor_radius = e.number_or("minor_radius", 0.0);
    s.hollow = e.flag("hollow");
    try {
      local = mass ? shape_with_mass(s, *mass) : shape_with_density(s, *density);
    } catch (const InvalidInput& err) {
      throw InvalidInput(fmt::format("{}: {}", e.name(), err.what()));
    }
  } else {
    const std::filesystem::path p = std::filesystem::path(*mesh).is_absolute()
                                        ? std::filesystem::path(*mesh)
                                        : std::filesystem::path(base_dir) / *mesh;
    MeshDiagnostics d;
    try {
      const TriangleMesh m = load_mesh(p.string());
      const auto shell = e.number("shell");
      MeshOptions opt;
      opt.flip_inward = e.flag("flip_inward");
      if (shell) {
        require_positive("shell thickness", *shell, "m");
        local = mass ? mesh_shell_mass_properties_with_mass(m, *mass, &d)
                     : mesh_shell_mass_properties(m, *density * *shell, &d);
      } else {
        local = mass ? mesh_mass_properties_with_mass(m, *mass, opt, &d)
                     : mesh_mass_properties(m, *density, opt, &d);
      }
    } catch (const InvalidInput& err) {
      throw InvalidInput(fmt::format("{}: {}", e.name(), err.what()));
    }
    for (const auto& msg : d.messages())
      diagnostics.push_back(fmt::format("{} ({}): {}", e.name(), *mesh, msg));
  }
  const auto pos = e.numbers("position", 3);
  const Vec3 position = pos ? Vec3((*pos)[0], (*pos)[1], (*pos)[2]) : Vec3::Zero();
  return local.placed(orientation(e), position);
}

}  // namespace

BodyFileResult parse_body(const std::string& toml_text, const std::string& base_dir) {
  toml::table root;
  try {
    root = toml::parse(toml_text);
  } catch (const toml::parse_error& err) {
    // toml++ quotes the offending text, which may span lines: Error keeps the message on one line.
    throw InvalidInput(fmt::format("body: TOML error at line {}: {}", err.source().begin.line,
                                   std::string(err.description())));
  }
  for (const auto& [k, v] : root) {
    if (k.str() != "part" && k.str() != "void") {
      throw InvalidInput(
          fmt::format("body: unknown table \"{}\"; expected [[part]] and [[void]] entries", k.str()));
    }
  }
  BodyFileResult out;
  std::optional<MassProperties> total;
  for (const char* kind : {"part", "void"}) {
    const toml::node* n = root.get(kind);
    if (n == nullptr) continue;
    const toml::array* arr = n->as_array();
    if (arr == nullptr) throw InvalidInput(fmt::format("body: {} must be written [[{}]]", kind, kind));
    std::size_t i = 0;
    for (const auto& item : *arr) {
      ++i;
      const toml::table* t = item.as_table();
      if (t == nullptr) throw InvalidInput(fmt::format("body: {} {} must be a table", kind, i));
      const Entry e(*t, fmt::format("{} {}", kind, i));
      const MassProperties mp = evaluate(e, base_dir, out.diagnostics);
      if (std::string(kind) == "part") {
        total = total ? combine(*total, mp) : mp;
        ++out.parts;
      } else {
        if (!total) throw InvalidInput("body: a void needs at least one [[part]] to be removed from");
        try {
          total = subtract(*total, mp);
        } catch (const InvalidInput& err) {
          throw InvalidInput(fmt::format("void {}: {}", i, err.what()));
        }
        ++out.voids;
      }
    }
  }
  if (!total) throw InvalidInput("body: no [[part]] entries; expected at least one part");
  out.body = *total;
  return out;
}

BodyFileResult load_body_file(const std::string& path) {
  const std::string text = read_file_limited(path, "body", default_max_file_bytes());
  const std::string base = std::filesystem::path(path).parent_path().string();
  return parse_body(text, base.empty() ? "." : base);
}

}  // namespace poinsot::inertia
