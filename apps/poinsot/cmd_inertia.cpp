// `poinsot inertia`: mass properties of shapes, meshes, composite bodies and given tensors, with principal
// axes, symmetry class and validity. Sub-commands: point, rod, plate, box, sphere, cylinder, cone, ellipsoid,
// capsule, torus, mesh, tensor, body. Output: a table, --json (one object), or --format urdf|mjcf|sdf (the
// inertial element of that model format). Everything is computed before anything is printed, so bad input
// leaves stdout empty (main prints the one-line error and exits 2).
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/body_file.hpp"
#include "poinsot/inertia/mass_properties.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/validity.hpp"
#include "poinsot/io/robot/inertia_report.hpp"
#include "poinsot/io/robot/robot_model.hpp"

namespace poinsot::cli {
namespace {

using namespace poinsot::inertia;  // NOLINT: this file is the inertia command

/// Options shared by every sub-command (output) plus those of the shapes and meshes.
struct InertiaOptions {
  // output
  bool json = false;
  std::string format;  // urdf, mjcf, sdf
  std::vector<double> about;
  double symmetry_tolerance = kDefaultSymmetryTolerance;
  // amount of material
  std::optional<double> mass;
  std::optional<double> density;
  // shapes
  ShapeSpec shape;
  std::vector<double> size;
  // mesh and body
  std::string file;
  std::optional<double> shell;
  bool flip_inward = false;
  // tensor
  std::vector<double> entries;
  bool repair = false;
  double validity_tolerance = kDefaultValidityTolerance;
};

using Report = io::InertiaReport;

std::string num(double x) {
  return format_number(x);
}

/// Prints the report in the form the options ask for (io/robot/inertia_report.hpp composes it fully first).
void print_report(const InertiaOptions& o, Report r) {
  if (o.json && !o.format.empty())
    throw InvalidInput("inertia: got --json and --format; expected at most one");
  std::optional<io::RobotFormat> format;
  if (!o.format.empty()) format = io::robot_format_named(o.format, "inertia: --format");
  if (!o.about.empty()) r.about = Vec3(o.about[0], o.about[1], o.about[2]);
  r.symmetry_tolerance = o.symmetry_tolerance;
  std::string out;
  if (format) {
    if (!r.mass)
      throw InvalidInput(
          fmt::format("inertia: --format {} needs the mass; expected --mass M (kg)", o.format));
    io::inertia_report_text(r);  // validates the reference point as the other forms do
    out = io::inertial_element(*format, *r.mass, r.props);
  } else {
    out = o.json ? io::inertia_report_json(r) : io::inertia_report_text(r);
  }
  fmt::print("{}", out);
}

void require_one_amount(const InertiaOptions& o, const std::string& what) {
  if (o.mass.has_value() == o.density.has_value()) {
    throw InvalidInput(fmt::format("{}: expected exactly one of --mass (kg) or --density", what));
  }
}

void run_shape(InertiaOptions o) {
  ShapeSpec s = o.shape;
  if (!o.size.empty()) {
    s.size = Vec3::Zero();
    for (std::size_t i = 0; i < o.size.size(); ++i)
      s.size[static_cast<Eigen::Index>(i)] = o.size[i];
  }
  Report r;
  if (s.kind == "point") {
    if (o.density) throw InvalidInput("point: a point mass has no density; expected --mass (kg)");
    if (!o.mass) throw InvalidInput("point: expected --mass (kg)");
  } else {
    require_one_amount(o, s.kind);
  }
  r.props = o.mass ? shape_with_mass(s, *o.mass) : shape_with_density(s, *o.density);
  r.mass = r.props.mass;
  r.valid = check_inertia(r.props.inertia_com).valid;
  print_report(o, r);
}

void run_mesh(InertiaOptions o) {
  require_one_amount(o, "mesh");
  const TriangleMesh mesh = load_mesh(o.file);
  Report r;
  MeshDiagnostics d;
  if (o.shell) {
    if (!(*o.shell > 0.0) || !std::isfinite(*o.shell)) {
      throw InvalidInput(fmt::format("mesh: --shell {} m; expected a positive thickness", num(*o.shell)));
    }
    r.props = o.mass ? mesh_shell_mass_properties_with_mass(mesh, *o.mass, &d)
                     : mesh_shell_mass_properties(mesh, *o.density * *o.shell, &d);
  } else {
    MeshOptions opt;
    opt.flip_inward = o.flip_inward;
    r.props = o.mass ? mesh_mass_properties_with_mass(mesh, *o.mass, opt, &d)
                     : mesh_mass_properties(mesh, *o.density, opt, &d);
  }
  r.mass = r.props.mass;
  r.diagnostics = d.messages();
  if (d.inward() && o.flip_inward && !o.shell) r.diagnostics.push_back("flipped to outward orientation");
  const InertiaCheck c = check_inertia(r.props.inertia_com);
  r.valid = c.valid;
  if (!c.valid) r.diagnostics.push_back(c.message);
  print_report(o, r);
}

void run_tensor(InertiaOptions o) {
  if (o.density) throw InvalidInput("tensor: --density does not apply; expected --mass (kg) or nothing");
  const std::vector<double>& e = o.entries;
  Mat3 J;
  J << e[0], e[3], e[4], e[3], e[1], e[5], e[4], e[5], e[2];
  if (!J.allFinite()) {
    throw InvalidInput(fmt::format("tensor: entries {}; expected finite numbers (kg·m²)", format_matrix(J)));
  }
  if (o.mass && (!(*o.mass > 0.0) || !std::isfinite(*o.mass))) {
    throw InvalidInput(fmt::format("tensor: --mass {} kg; expected a positive finite mass", num(*o.mass)));
  }
  Report r;
  r.mass = o.mass;
  r.props.mass = o.mass.value_or(0.0);
  const InertiaCheck c = check_inertia(J, o.validity_tolerance, "tensor");
  if (!c.valid && !o.repair) throw InvalidInput(c.message + "; pass --repair for the nearest valid tensor");
  if (!c.valid) {
    const InertiaRepair rep = repair_inertia(J);
    J = rep.inertia;
    r.repair_distance = rep.distance;
    r.diagnostics.push_back(c.message);
    r.diagnostics.push_back(fmt::format("repaired: principal moments {} -> {} kg·m², distance {} kg·m²",
                                        format_vector(rep.moments_before), format_vector(rep.moments_after),
                                        format_number(rep.distance, 6)));
  } else if (o.repair) {
    r.repair_distance = 0.0;
  }
  r.props.inertia_com = J;
  r.valid = true;
  print_report(o, r);
}

void run_body(InertiaOptions o) {
  const BodyFileResult b = load_body_file(o.file);
  Report r;
  r.props = b.body;
  r.mass = b.body.mass;
  r.diagnostics = b.diagnostics;
  const InertiaCheck c = check_inertia(b.body.inertia_com, kDefaultValidityTolerance, "body");
  if (!c.valid) throw InvalidInput(c.message + " (do the voids lie inside the parts?)");
  print_report(o, r);
}

void add_output_options(CLI::App* cmd, const std::shared_ptr<InertiaOptions>& o) {
  cmd->add_flag("--json", o->json, "print one JSON object (SI units)");
  cmd->add_option("--format", o->format, "print the inertial element of a model: urdf, mjcf or sdf");
  cmd->add_option("--about", o->about, "also give J about this point x y z (m), in the input frame")
      ->expected(3);
  cmd->add_option("--symmetry-tolerance", o->symmetry_tolerance,
                  "relative tolerance of the symmetry classification (default 1e-9)");
}

void add_amount_options(CLI::App* cmd, const std::shared_ptr<InertiaOptions>& o,
                        const std::string& density_help) {
  cmd->add_option("--mass", o->mass, "mass (kg)");
  cmd->add_option("--density", o->density, density_help);
}

}  // namespace

void register_inertia(CLI::App& app) {
  auto* inertia = app.add_subcommand("inertia", "Mass properties, principal axes and validity of a body");
  // No sub-command: say which exist (an unknown one is rejected by CLI11 as "not expected: NAME").
  inertia->require_subcommand(0, 1);
  inertia->callback([inertia] {
    if (inertia->get_subcommands().empty()) {
      throw InvalidInput(
          "inertia: no sub-command; expected one of point, rod, plate, box, sphere, cylinder, cone, "
          "ellipsoid, "
          "capsule, torus, mesh, tensor, body, check");
    }
  });

  struct ShapeDef {
    const char* name;
    const char* help;
  };
  const std::vector<ShapeDef> shapes{
      {"point", "point mass (--mass)"},
      {"rod", "thin rod along z (--length)"},
      {"plate", "rectangular plate in the xy-plane (--size A B)"},
      {"box", "box (--size X Y Z)"},
      {"sphere", "sphere (--radius; --inner-radius or --hollow for a shell)"},
      {"cylinder", "cylinder along z (--radius --length; --inner-radius or --hollow for a tube)"},
      {"cone", "cone along z, base at z = -h/4 (--radius --height)"},
      {"ellipsoid", "ellipsoid (--semi-axes A B C)"},
      {"capsule", "capsule along z (--radius, --length of the cylinder)"},
      {"torus", "solid torus about z (--major-radius --minor-radius)"}};
  for (const auto& def : shapes) {
    auto o = std::make_shared<InertiaOptions>();
    o->shape.kind = def.name;
    const std::string kind = def.name;
    auto* cmd = inertia->add_subcommand(def.name, def.help);
    add_output_options(cmd, o);
    const std::string unit = kind == "rod"     ? "kg/m"
                             : kind == "plate" ? "kg/m²"
                                               : "kg/m³ (kg/m² with --hollow)";
    add_amount_options(cmd, o, "density (" + unit + ")");
    if (kind == "plate")
      cmd->add_option("--size", o->size, "side lengths A (x) B (y), m")->expected(2)->required();
    if (kind == "box") cmd->add_option("--size", o->size, "side lengths X Y Z, m")->expected(3)->required();
    if (kind == "ellipsoid")
      cmd->add_option("--semi-axes", o->size, "semi-axes A B C, m")->expected(3)->required();
    if (kind == "sphere" || kind == "cylinder" || kind == "cone" || kind == "capsule") {
      cmd->add_option("--radius", o->shape.radius, "radius, m")->required();
    }
    if (kind == "rod" || kind == "cylinder" || kind == "capsule") {
      cmd->add_option("--length", o->shape.length, "length, m")->required();
    }
    if (kind == "cone") cmd->add_option("--height", o->shape.height, "height, m")->required();
    if (kind == "sphere" || kind == "cylinder") {
      auto* inner = cmd->add_option("--inner-radius", o->shape.inner_radius, "inner radius (thick shell), m");
      cmd->add_flag("--hollow", o->shape.hollow, "thin shell (a surface)")->excludes(inner);
    }
    if (kind == "torus") {
      cmd->add_option("--major-radius", o->shape.major_radius, "axis to tube centre, m")->required();
      cmd->add_option("--minor-radius", o->shape.minor_radius, "tube radius, m")->required();
    }
    cmd->callback([o] { run_shape(*o); });
  }

  {
    auto o = std::make_shared<InertiaOptions>();
    auto* cmd =
        inertia->add_subcommand("mesh", "closed triangle mesh (STL, OBJ, PLY, OFF) of uniform density");
    cmd->add_option("file", o->file, "mesh file")->required();
    add_output_options(cmd, o);
    add_amount_options(cmd, o, "density (kg/m³)");
    cmd->add_option("--shell", o->shell, "thin surface of this thickness (m) instead of a solid");
    cmd->add_flag("--flip-inward", o->flip_inward, "flip an inward-oriented mesh instead of rejecting it");
    cmd->callback([o] { run_mesh(*o); });
  }
  {
    auto o = std::make_shared<InertiaOptions>();
    auto* cmd =
        inertia->add_subcommand("tensor", "check and diagonalise J = [Ixx Ixy Ixz; . Iyy Iyz; . . Izz]");
    cmd->add_option("entries", o->entries, "Ixx Iyy Izz Ixy Ixz Iyz (kg·m², entries of J)")
        ->expected(6)
        ->required();
    add_output_options(cmd, o);
    cmd->add_option("--mass", o->mass, "mass (kg), for --about and --format");
    cmd->add_option("--density", o->density, "not applicable");
    cmd->add_flag("--repair", o->repair, "replace an invalid tensor by the nearest valid one");
    cmd->add_option("--validity-tolerance", o->validity_tolerance,
                    "relative tolerance (times the trace) of the validity test (default 1e-10)");
    cmd->callback([o] { run_tensor(*o); });
  }
  {
    auto o = std::make_shared<InertiaOptions>();
    auto* cmd =
        inertia->add_subcommand("body", "composite of shapes, meshes and voids with poses (TOML file)");
    cmd->add_option("file", o->file, "body file (.toml), see docs/inertia.md")->required();
    add_output_options(cmd, o);
    cmd->callback([o] { run_body(*o); });
  }
  register_inertia_check(*inertia);
}

}  // namespace poinsot::cli
