// Bindings of the inertia layer as poinsot.inertia: mass properties from shapes, meshes and tensors, their
// principal axes and symmetry class, validity checks and the explicit repair. Docstrings from the headers.
#include <pybind11/stl.h>

#include <optional>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "docstrings.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/inertia/body_file.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/validity.hpp"
#include "poinsot/io/robot/inertia_report.hpp"
#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/io/robot/model_repair.hpp"
#include "poinsot/io/robot/robot_model.hpp"
#include "poinsot/io/run/summary.hpp"

namespace poinsot::python {

using inertia::MassProperties;
using inertia::TriangleMesh;

namespace {

py::dict diagnostics_dict(const inertia::MeshDiagnostics& d) {
  py::dict out;
  out["triangles"] = d.triangles;
  out["vertices"] = d.vertices;
  out["open_edges"] = d.open_edges;
  out["inconsistent_edges"] = d.inconsistent_edges;
  out["non_manifold_edges"] = d.non_manifold_edges;
  out["degenerate_triangles"] = d.degenerate_triangles;
  out["shells"] = d.shells;
  out["signed_volume"] = d.signed_volume;
  out["area"] = d.area;
  out["watertight"] = d.watertight();
  out["consistent"] = d.consistent();
  out["inward"] = d.inward();
  out["messages"] = d.messages();
  return out;
}

TriangleMesh make_mesh(const py::handle& vertices, const py::handle& triangles) {
  auto v = to_float_array(vertices, "vertices", {-1, 3});
  py::array t_raw = py::module_::import("numpy").attr("asarray")(triangles);
  const char kind = t_raw.dtype().kind();
  if (kind != 'i' && kind != 'u')
    throw py::type_error("triangles: expected integer vertex indices, got dtype " +
                         std::string(py::str(t_raw.dtype())));
  auto t = to_float_array(t_raw, "triangles", {-1, 3});  // checks the shape; indices are exact in float64
  TriangleMesh mesh;
  const double* pv = v.data();
  for (py::ssize_t i = 0; i < v.shape(0); ++i)
    mesh.vertices.emplace_back(pv[3 * i], pv[3 * i + 1], pv[3 * i + 2]);
  const double* pt = t.data();
  for (py::ssize_t i = 0; i < t.shape(0); ++i)
    mesh.triangles.push_back({static_cast<std::int32_t>(pt[3 * i]), static_cast<std::int32_t>(pt[3 * i + 1]),
                              static_cast<std::int32_t>(pt[3 * i + 2])});
  return mesh;
}

void with_mass_or_density(const char* what, const std::optional<double>& mass,
                          const std::optional<double>& density) {
  if (mass.has_value() == density.has_value())
    throw py::value_error(std::string(what) + ": give exactly one of mass (kg) and density, got " +
                          (mass ? "both" : "neither"));
}

/// The robot-model check's options from the Python arguments.
io::ModelCheckOptions check_options(double density_min, double density_max, double ratio_limit,
                                    double validity_tolerance) {
  io::ModelCheckOptions o;
  o.density_min = density_min;
  o.density_max = density_max;
  o.ratio_limit = ratio_limit;
  o.validity_tolerance = validity_tolerance;
  return o;
}

/// MassProperties, and what combines, moves and re-expresses mass properties.
void bind_mass_properties(py::module_& m) {
  py::class_<MassProperties>(m, "MassProperties", POINSOT_DOC(inertia_MassProperties))
      .def(py::init([](double mass, ArrayLike com, ArrayLike J) {
             MassProperties p;
             p.mass = mass;
             p.com = to_vec3(com, "center_of_mass");
             p.inertia_com = to_mat3(J, "inertia_com");
             return p;
           }),
           py::arg("mass"), py::arg("center_of_mass"), py::arg("inertia_com"),
           "Mass properties from mass (kg), centre of mass (m) and J about it (kg·m²), all in one frame.")
      .def_readonly("mass", &MassProperties::mass, POINSOT_DOC(inertia_MassProperties_mass))
      .def_property_readonly(
          "center_of_mass", [](const MassProperties& p) { return from_vec3(p.com); },
          POINSOT_DOC(inertia_MassProperties_com))
      .def_property_readonly(
          "inertia_com", [](const MassProperties& p) { return from_mat3(p.inertia_com); },
          POINSOT_DOC(inertia_MassProperties_inertia_com))
      .def_property_readonly(
          "poinsot_com", [](const MassProperties& p) { return from_mat3(p.poinsot_com()); },
          POINSOT_DOC(inertia_MassProperties_poinsot_com))
      .def_property_readonly(
          "principal_moments",
          [](const MassProperties& p) { return from_vec3(inertia::principal_axes(p.inertia_com).moments); },
          "Principal moments of inertia_com, ascending (kg·m²); see poinsot.inertia.principal_axes.")
      .def_property_readonly(
          "principal_axes",
          [](const MassProperties& p) { return from_mat3(inertia::principal_axes(p.inertia_com).axes); },
          "Columns: the principal axes of inertia_com, a proper rotation (det = +1), with the sign rule of "
          "poinsot.inertia.principal_axes.")
      .def_property_readonly(
          "symmetry",
          [](const MassProperties& p) {
            return inertia::to_string(inertia::principal_axes(p.inertia_com).symmetry);
          },
          "\"asymmetric\", \"prolate\", \"oblate\" or \"spherical\" (relative tolerance 1e-9).")
      .def(
          "inertia_about",
          [](const MassProperties& p, ArrayLike point) {
            return from_mat3(p.inertia_about(to_vec3(point, "point")));
          },
          py::arg("point"), POINSOT_DOC(inertia_MassProperties_inertia_about))
      .def(
          "placed",
          [](const MassProperties& p, ArrayLike R, ArrayLike pos) {
            return p.placed(to_mat3(R, "R_P_F"), to_vec3(pos, "position_P"));
          },
          py::arg("R_P_F"), py::arg("position_P"), POINSOT_DOC(inertia_MassProperties_placed))
      .def(
          "to_rigid_body",
          [](const MassProperties& p) { return dynamics::RigidBody::from_inertia(p.inertia_com); },
          "A free poinsot.RigidBody whose body frame is this frame, with J = inertia_com (about the centre "
          "of mass).")
      .def("__add__", &inertia::combine, POINSOT_DOC(inertia_combine))
      .def("__sub__", &inertia::subtract, POINSOT_DOC(inertia_subtract))
      .def("__repr__", [](const MassProperties& p) {
        return "MassProperties(mass=" + format_number(p.mass) +
               " kg, center_of_mass=" + format_vector(p.com) +
               " m, inertia_com=" + format_matrix(p.inertia_com) + " kg·m²)";
      });

  m.def(
      "from_inertia_about",
      [](double mass, ArrayLike com, ArrayLike J, ArrayLike point) {
        return inertia::from_inertia_about(mass, to_vec3(com, "com"), to_mat3(J, "J_point"),
                                           to_vec3(point, "point"));
      },
      py::arg("mass"), py::arg("com"), py::arg("J_point"), py::arg("point"),
      POINSOT_DOC(inertia_from_inertia_about));
  m.def("combine", &inertia::combine, py::arg("a"), py::arg("b"), POINSOT_DOC(inertia_combine));
  m.def("subtract", &inertia::subtract, py::arg("whole"), py::arg("removed"), POINSOT_DOC(inertia_subtract));
  m.def(
      "poinsot_from_inertia",
      [](ArrayLike J) { return from_mat3(inertia::poinsot_from_inertia(to_mat3(J, "J"))); }, py::arg("J"),
      POINSOT_DOC(inertia_poinsot_from_inertia));
  m.def(
      "inertia_from_poinsot",
      [](ArrayLike K) { return from_mat3(inertia::inertia_from_poinsot(to_mat3(K, "K"))); }, py::arg("K"),
      POINSOT_DOC(inertia_inertia_from_poinsot));
  m.def(
      "shift_from_com",
      [](ArrayLike J, double mass, ArrayLike com, ArrayLike point) {
        return from_mat3(
            inertia::shift_from_com(to_mat3(J, "J_com"), mass, to_vec3(com, "com"), to_vec3(point, "point")));
      },
      py::arg("J_com"), py::arg("mass"), py::arg("com"), py::arg("point"),
      POINSOT_DOC(inertia_shift_from_com));
  m.def(
      "shift_to_com",
      [](ArrayLike J, double mass, ArrayLike com, ArrayLike point) {
        return from_mat3(
            inertia::shift_to_com(to_mat3(J, "J_point"), mass, to_vec3(com, "com"), to_vec3(point, "point")));
      },
      py::arg("J_point"), py::arg("mass"), py::arg("com"), py::arg("point"),
      POINSOT_DOC(inertia_shift_to_com));
  m.def(
      "reexpress",
      [](ArrayLike T, ArrayLike R) {
        return from_mat3(inertia::reexpress(to_mat3(T, "tensor_F"), to_mat3(R, "R_B_F")));
      },
      py::arg("tensor_F"), py::arg("R_B_F"), POINSOT_DOC(inertia_reexpress));
}

/// Principal axes, symmetry class, validity checks and the explicit repair.
void bind_principal_axes_and_validity(py::module_& m) {
  m.def(
      "principal_axes",
      [](ArrayLike J, double rel_tol) {
        const auto pa = inertia::principal_axes(to_mat3(J, "J"), rel_tol);
        return py::make_tuple(from_vec3(pa.moments), from_mat3(pa.axes), inertia::to_string(pa.symmetry));
      },
      py::arg("J"), py::arg("rel_tol") = inertia::kDefaultSymmetryTolerance,
      (std::string(POINSOT_DOC(inertia_principal_axes)) +
       "\n\nReturns (moments (3,), axes (3, 3) with the axes as columns, symmetry).\n\n" +
       POINSOT_DOC(file_inertia_principal_axes))
          .c_str());
  m.def(
      "classify",
      [](ArrayLike moments, double rel_tol) {
        return inertia::to_string(inertia::classify(to_vec3(moments, "moments_ascending"), rel_tol));
      },
      py::arg("moments_ascending"), py::arg("rel_tol") = inertia::kDefaultSymmetryTolerance,
      POINSOT_DOC(inertia_classify));
  m.def(
      "check_inertia",
      [](ArrayLike J, double rel_tol, const std::string& what) {
        const auto c = inertia::check_inertia(to_mat3(J, "J"), rel_tol, what);
        py::dict out;
        out["valid"] = c.valid;
        out["condition"] = c.condition;
        out["amount"] = c.amount;
        out["message"] = c.message;
        out["moments"] = from_vec3(c.moments);
        return out;
      },
      py::arg("J"), py::arg("rel_tol") = inertia::kDefaultValidityTolerance, py::arg("what") = "inertia",
      (std::string(POINSOT_DOC(inertia_check_inertia)) +
       "\n\nReturns a dict: valid, condition, amount (kg·m²), message, moments (ascending, kg·m²).")
          .c_str());
  m.def(
      "require_valid_inertia",
      [](ArrayLike J, const std::string& what, double rel_tol) {
        inertia::require_valid_inertia(to_mat3(J, "J"), what, rel_tol);
      },
      py::arg("J"), py::arg("what") = "inertia", py::arg("rel_tol") = inertia::kDefaultValidityTolerance,
      POINSOT_DOC(inertia_require_valid_inertia));
  m.def(
      "repair_inertia",
      [](ArrayLike J) {
        const auto r = inertia::repair_inertia(to_mat3(J, "J"));
        py::dict out;
        out["inertia"] = from_mat3(r.inertia);
        out["moments_before"] = from_vec3(r.moments_before);
        out["moments_after"] = from_vec3(r.moments_after);
        out["distance"] = r.distance;
        return out;
      },
      py::arg("J"),
      (std::string(POINSOT_DOC(inertia_repair_inertia)) +
       "\n\nReturns a dict: inertia (3, 3), moments_before, moments_after (ascending, kg·m²), distance "
       "(kg·m²).\n\n" +
       POINSOT_DOC(file_inertia_validity))
          .c_str());
}

/// The closed-form shapes, each from a mass (kg); shape() by name, also from a density.
void bind_shapes(py::module_& m) {
  m.def("point_mass", &inertia::point_mass, py::arg("mass"));
  m.def("rod", &inertia::rod, py::arg("mass"), py::arg("length"));
  m.def("plate", &inertia::plate, py::arg("mass"), py::arg("size_x"), py::arg("size_y"));
  m.def(
      "box", [](double mass, ArrayLike size) { return inertia::box(mass, to_vec3(size, "size")); },
      py::arg("mass"), py::arg("size"));
  m.def("solid_sphere", &inertia::solid_sphere, py::arg("mass"), py::arg("radius"));
  m.def("hollow_sphere", &inertia::hollow_sphere, py::arg("mass"), py::arg("radius"), py::arg("inner_radius"),
        POINSOT_DOC(inertia_hollow_sphere));
  m.def("spherical_shell", &inertia::spherical_shell, py::arg("mass"), py::arg("radius"),
        POINSOT_DOC(inertia_spherical_shell));
  m.def("cylinder", &inertia::cylinder, py::arg("mass"), py::arg("radius"), py::arg("length"),
        py::arg("inner_radius") = 0.0, POINSOT_DOC(inertia_cylinder));
  m.def("cylindrical_shell", &inertia::cylindrical_shell, py::arg("mass"), py::arg("radius"),
        py::arg("length"), POINSOT_DOC(inertia_cylindrical_shell));
  m.def("cone", &inertia::cone, py::arg("mass"), py::arg("radius"), py::arg("height"));
  m.def(
      "ellipsoid", [](double mass, ArrayLike a) { return inertia::ellipsoid(mass, to_vec3(a, "semi_axes")); },
      py::arg("mass"), py::arg("semi_axes"));
  m.def("capsule", &inertia::capsule, py::arg("mass"), py::arg("radius"), py::arg("length"));
  m.def("torus", &inertia::torus, py::arg("mass"), py::arg("major_radius"), py::arg("minor_radius"));
  m.attr("_doc_shapes") = POINSOT_DOC(file_inertia_shapes);
  m.def(
      "shape",
      [](const std::string& kind, std::optional<double> mass, std::optional<double> density, py::object size,
         double radius, double length, double height, double inner_radius, double major_radius,
         double minor_radius, bool hollow) {
        with_mass_or_density("shape", mass, density);
        inertia::ShapeSpec spec;
        spec.kind = kind;
        if (!size.is_none()) {
          py::array a = py::module_::import("numpy").attr("asarray")(size);
          if (a.ndim() == 1 && a.shape(0) == 2) {
            auto v = to_float_array(a, "size", {2});
            spec.size = Vec3(v.data()[0], v.data()[1], 0.0);
          } else {
            spec.size = to_vec3(a, "size");
          }
        }
        spec.radius = radius;
        spec.length = length;
        spec.height = height;
        spec.inner_radius = inner_radius;
        spec.major_radius = major_radius;
        spec.minor_radius = minor_radius;
        spec.hollow = hollow;
        return mass ? inertia::shape_with_mass(spec, *mass) : inertia::shape_with_density(spec, *density);
      },
      py::arg("kind"), py::kw_only(), py::arg("mass") = py::none(), py::arg("density") = py::none(),
      py::arg("size") = py::none(), py::arg("radius") = 0.0, py::arg("length") = 0.0, py::arg("height") = 0.0,
      py::arg("inner_radius") = 0.0, py::arg("major_radius") = 0.0, py::arg("minor_radius") = 0.0,
      py::arg("hollow") = false,
      (std::string("A shape by name with a mass (kg) or a density, sizes in m.\n\n") +
       POINSOT_DOC(inertia_ShapeSpec) + "\n\n" + POINSOT_DOC(file_inertia_shapes))
          .c_str());
}

/// Triangle meshes: construction, files, mass properties.
void bind_meshes(py::module_& m) {
  py::class_<TriangleMesh>(m, "TriangleMesh", POINSOT_DOC(inertia_TriangleMesh))
      .def(py::init([](ArrayLike v, ArrayLike t) { return make_mesh(v.obj, t.obj); }), py::arg("vertices"),
           py::arg("triangles"), "A mesh from vertices (n, 3) in m and triangles (m, 3) of vertex indices.")
      .def_property_readonly(
          "vertices",
          [](const TriangleMesh& mesh) {
            std::vector<double> buf;
            buf.reserve(3 * mesh.vertices.size());
            for (const auto& v : mesh.vertices)
              buf.insert(buf.end(), {v[0], v[1], v[2]});
            return array_from_buffer(std::move(buf), {static_cast<py::ssize_t>(mesh.vertices.size()), 3});
          })
      .def_property_readonly("triangles",
                             [](const TriangleMesh& mesh) {
                               py::array_t<std::int32_t> a({static_cast<py::ssize_t>(mesh.triangles.size()),
                                                            static_cast<py::ssize_t>(3)});
                               auto* p = a.mutable_data();
                               for (const auto& t : mesh.triangles) {
                                 *p++ = t[0];
                                 *p++ = t[1];
                                 *p++ = t[2];
                               }
                               return a;
                             })
      .def("__repr__", [](const TriangleMesh& mesh) {
        return "TriangleMesh(vertices=" + std::to_string(mesh.vertices.size()) +
               ", triangles=" + std::to_string(mesh.triangles.size()) + ")";
      });
}

/// Composite bodies from a body file (the format of `poinsot inertia body FILE.toml`).
void bind_body_files(py::module_& m) {
  const auto body_result = [](const inertia::BodyFileResult& r) {
    py::dict d;
    d["body"] = r.body;
    d["diagnostics"] = r.diagnostics;
    d["parts"] = r.parts;
    d["voids"] = r.voids;
    return d;
  };
  m.def(
      "load_body_file",
      [body_result](const std::string& path) { return body_result(inertia::load_body_file(path)); },
      py::arg("path"),
      (std::string(POINSOT_DOC(inertia_load_body_file)) +
       "\n\nReturns a dict: body (MassProperties, body frame), diagnostics (list of str), parts, voids.\n\n" +
       POINSOT_DOC(file_inertia_body_file))
          .c_str());
  m.def(
      "parse_body",
      [body_result](const std::string& text, const std::string& base_dir) {
        return body_result(inertia::parse_body(text, base_dir));
      },
      py::arg("toml_text"), py::arg("base_dir") = ".",
      (std::string(POINSOT_DOC(inertia_parse_body)) + "\n\nReturns the dict of load_body_file.").c_str());
  m.def(
      "load_mesh", [](const std::string& path) { return inertia::load_mesh(path); }, py::arg("path"),
      (std::string(POINSOT_DOC(inertia_load_mesh)) + "\n\n" + POINSOT_DOC(file_inertia_mesh_io)).c_str());
  m.def("write_binary_stl", &inertia::write_binary_stl, py::arg("mesh"), py::arg("path"),
        POINSOT_DOC(inertia_write_binary_stl));
  m.def(
      "diagnose", [](const TriangleMesh& mesh) { return diagnostics_dict(inertia::diagnose(mesh)); },
      py::arg("mesh"), POINSOT_DOC(inertia_diagnose));
  m.def(
      "mesh",
      [](const py::object& source, std::optional<double> mass, std::optional<double> density,
         std::optional<double> areal_density, bool shell, bool flip_inward) {
        TriangleMesh mesh = py::isinstance<TriangleMesh>(source) ? source.cast<TriangleMesh>()
                                                                 : inertia::load_mesh(py::str(source));
        inertia::MeshOptions options;
        options.flip_inward = flip_inward;
        if (shell) {
          if (mass.has_value() == areal_density.has_value())
            throw py::value_error("mesh: a shell needs exactly one of mass (kg) and areal_density (kg/m²)");
          return mass ? inertia::mesh_shell_mass_properties_with_mass(mesh, *mass)
                      : inertia::mesh_shell_mass_properties(mesh, *areal_density);
        }
        with_mass_or_density("mesh", mass, density);
        return mass ? inertia::mesh_mass_properties_with_mass(mesh, *mass, options)
                    : inertia::mesh_mass_properties(mesh, *density, options);
      },
      py::arg("source"), py::kw_only(), py::arg("mass") = py::none(), py::arg("density") = py::none(),
      py::arg("areal_density") = py::none(), py::arg("shell") = false, py::arg("flip_inward") = false,
      (std::string(
           "Mass properties of a mesh (a file path or a TriangleMesh): the enclosed solid with a mass "
           "(kg) or a density (kg/m³), or with shell=True the surface with a mass or an areal_density "
           "(kg/m²).\n\n") +
       POINSOT_DOC(inertia_mesh_mass_properties) + "\n\n" + POINSOT_DOC(file_inertia_mesh))
          .c_str());
}

/// Robot models (URDF, MJCF, SDF), checked and repaired: the report is io::model_check_json, parsed, so
/// that the command line and Python share one serialisation.
void bind_robot_model_checks(py::module_& m) {
  m.def(
      "check_model",
      [](const std::string& path, double density_min, double density_max, double ratio_limit,
         double validity_tolerance) {
        const auto model = io::load_robot_model(path);
        const auto check =
            io::check_model(model, check_options(density_min, density_max, ratio_limit, validity_tolerance));
        return py::module_::import("json").attr("loads")(io::model_check_json(check));
      },
      py::arg("path"), py::kw_only(), py::arg("density_min") = 50.0, py::arg("density_max") = 25000.0,
      py::arg("ratio_limit") = 10.0, py::arg("validity_tolerance") = inertia::kDefaultValidityTolerance,
      (std::string(POINSOT_DOC(io_check_model)) +
       "\n\nReads the model file `path` (robot_model.hpp) and returns the report as a dict (the keys of "
       "model_check_json).\n\n" +
       POINSOT_DOC(file_io_robot_model_check))
          .c_str());
}

/// The report of `poinsot inertia --json` and the inertial elements of `--format`, from
/// io/robot/inertia_report.hpp.
void bind_inertia_report(py::module_& m) {
  m.def(
      "report",
      [](const MassProperties& props, const py::object& about, double symmetry_tolerance) {
        io::InertiaReport r;
        r.mass = props.mass > 0.0 ? std::optional<double>(props.mass) : std::nullopt;
        r.props = props;
        const inertia::InertiaCheck c = inertia::check_inertia(props.inertia_com);
        r.valid = c.valid;
        if (!c.valid) r.diagnostics.push_back(c.message);
        if (!about.is_none()) r.about = to_vec3(about, "about");
        r.symmetry_tolerance = symmetry_tolerance;
        return py::module_::import("json").attr("loads")(io::inertia_report_json(r));
      },
      py::arg("props"), py::kw_only(), py::arg("about") = py::none(),
      py::arg("symmetry_tolerance") = inertia::kDefaultSymmetryTolerance,
      (std::string(
           "The mass properties `props` as the dict of `poinsot inertia --json` (valid and diagnostics "
           "from check_inertia; mass null when props.mass is 0).\n\n") +
       POINSOT_DOC(io_inertia_report_json))
          .c_str());
  m.def(
      "inertial_element",
      [](const MassProperties& props, const std::string& format) {
        return io::inertial_element(io::robot_format_named(format, "inertial_element: format"), props.mass,
                                    props);
      },
      py::arg("props"), py::arg("format"),
      (std::string("The inertial element of `props` (its own mass) in `format`, \"urdf\", \"mjcf\" or "
                   "\"sdf\", as `poinsot inertia --format` prints it.\n\n") +
       POINSOT_DOC(io_inertial_element))
          .c_str());
  m.def(
      "repair_model",
      [](const std::string& path, const std::string& out, bool from_geometry) {
        const auto model = io::load_robot_model(path);
        const auto check =
            io::check_model(model, check_options(50.0, 25000.0, 10.0, inertia::kDefaultValidityTolerance));
        const auto repair = io::repair_model(
            model, check, from_geometry ? io::RepairMode::from_geometry : io::RepairMode::nearest_valid);
        io::write_file_atomic(out, repair.text);
        return py::module_::import("json").attr("loads")(io::model_repair_json(repair));
      },
      py::arg("path"), py::arg("out"), py::kw_only(), py::arg("from_geometry") = false,
      (std::string(POINSOT_DOC(io_repair_model)) +
       "\n\nWrites the repaired copy of the model file `path` to `out` (atomically) and returns a dict: "
       "edits "
       "(link, inertia_before, inertia_after, distance) and skipped.\n\n" +
       POINSOT_DOC(file_io_robot_model_repair))
          .c_str());
}

}  // namespace

void bind_inertia(py::module_& parent) {
  auto m = parent.def_submodule("inertia", POINSOT_DOC(file_inertia_mass_properties));
  bind_mass_properties(m);
  bind_principal_axes_and_validity(m);
  bind_shapes(m);
  bind_meshes(m);
  bind_body_files(m);
  bind_robot_model_checks(m);
  bind_inertia_report(m);
}

}  // namespace poinsot::python
