// A robot file as a multibody scenario (see robot_system.hpp): the links' mass properties, the kinematic
// tree of robot_kinematics.hpp posed at the initial joint coordinates, and the joints of the multibody layer.
#include "poinsot/io/robot/robot_system.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "poinsot/inertia/mesh_io.hpp"
#include "poinsot/inertia/shapes.hpp"
#include "poinsot/inertia/tessellation.hpp"
#include "poinsot/io/robot/model_check.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/quaternion.hpp"
#include "robot_kinematics.hpp"
#include "robot_system_builder.hpp"

namespace poinsot::io {
namespace {

using detail::LinkInertia;
using detail::LinkPlace;
using detail::RigidPose;
using detail::RobotDof;
using detail::RobotJointKind;
using detail::RobotJointSpec;
using detail::RobotTree;
using detail::Twist;
using multibody::kWorld;

LinkInertia link_inertia(const RobotModel& model, const RobotTree& tree, std::size_t k,
                         RobotInertiaSource source) {
  const RobotLink& link = model.links[k];
  LinkInertia out;
  const bool from_geoms = k < tree.inertia_from_geoms.size() && tree.inertia_from_geoms[k];
  if (from_geoms) {
    for (const std::string& note : link.notes) {
      if (note.find("skipped") != std::string::npos) {
        throw InvalidInput(
            fmt::format("{}; the body's inertia comes from its geoms, so each is needed "
                        "(give the body an <inertial>)",
                        note));
      }
    }
    bool any = false;
    for (const LinkGeometry& g : link.geometry) {
      if (g.shape.kind == "mesh") {
        throw InvalidInput(
            fmt::format("{}: <body name=\"{}\">: inertia from a mesh geom: MuJoCo re-centres meshes on "
                        "their centre of "
                        "mass, which is not reproduced; expected an <inertial> for this body",
                        model.lines.location(link.line), link.name));
      }
      const double mass = g.mass ? *g.mass : g.density * inertia::shape_measure(g.shape);
      if (!(mass > 0.0)) continue;
      const inertia::MassProperties part =
          inertia::shape_with_mass(g.shape, mass).placed(g.R_link_geometry, g.position_link);
      out.props = any ? inertia::combine(out.props, part) : part;
      any = true;
    }
    out.how = "from its geoms (uniform density, MuJoCo's rule)";
    return out;
  }
  if (!link.has_inertial) {
    if (model.format == RobotFormat::sdf) {
      out.props.mass = 1.0;
      out.props.inertia_com = Mat3::Identity();
      out.how = "SDF's default inertial (1 kg, J = I kg·m²): the link has no <inertial>";
    }
    return out;  // URDF: no mass
  }
  out.props.mass = link.mass;
  out.props.com = link.com_link;
  out.props.inertia_com = link.inertia_link;
  out.how = "from its <inertial>";
  if (source == RobotInertiaSource::geometry && link.mass > 0.0) {
    std::vector<std::string> notes;
    if (const auto g = geometry_inertia(link, link.mass, ModelCheckOptions{}, notes)) {
      out.props.inertia_com = g->props.inertia_com;
      out.how = "tensor from its geometry at the file's mass, about the file's centre of mass";
    } else {
      out.how = "from its <inertial> (it has no geometry)";
    }
  }
  return out;
}

/// Number of values a joint name takes: (positions, velocities).
std::pair<std::size_t, std::size_t> value_counts(const std::vector<const RobotDof*>& dofs) {
  std::size_t p = 0, v = 0;
  for (const RobotDof* d : dofs) {
    p += d->kind == RobotDof::Kind::ball ? 4 : 1;
    v += d->kind == RobotDof::Kind::ball ? 3 : 1;
  }
  return {p, v};
}

/// The elementary motion of `d` at coordinate(s) `q` (child frame).
RigidPose dof_motion(const RobotDof& d, const double* q) {
  RigidPose m;
  switch (d.kind) {
    case RobotDof::Kind::hinge:
      m.R = so3::rotation_from_axis_angle(d.axis_child, q[0]);
      m.p = d.anchor_child - m.R * d.anchor_child;
      break;
    case RobotDof::Kind::slide:
      m.p = d.axis_child * q[0];
      break;
    case RobotDof::Kind::ball:
      m.R = so3::rotation_from_quaternion(Quat(q[0], q[1], q[2], q[3]));
      m.p = d.anchor_child - m.R * d.anchor_child;
      break;
  }
  return m;
}

}  // namespace

namespace detail {

/// Parents before children; a cycle of joints is a kinematic loop.
void RobotSystemBuilder::sort_links() {
  const std::size_t n = model.links.size();
  std::vector<int> state(n, 0);  // 0 new, 1 on the path, 2 done
  for (std::size_t start = 0; start < n; ++start) {
    std::vector<int> path;
    int k = static_cast<int>(start);
    while (k >= 0 && state[static_cast<std::size_t>(k)] == 0) {
      state[static_cast<std::size_t>(k)] = 1;
      path.push_back(k);
      const RobotJointSpec* j = spec_of(static_cast<std::size_t>(k));
      k = j == nullptr ? -1 : j->parent;
    }
    if (k >= 0 && state[static_cast<std::size_t>(k)] == 1) {
      const RobotJointSpec& j = *spec_of(static_cast<std::size_t>(path.back()));
      throw InvalidInput(
          fmt::format("{}: its parents lead back to link \"{}\": a kinematic loop; expected "
                      "a tree (close loops with MJCF <equality>)",
                      where(j), model.links[static_cast<std::size_t>(k)].name));
    }
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      state[static_cast<std::size_t>(*it)] = 2;
      order.push_back(*it);
    }
  }
}

void RobotSystemBuilder::read_coordinates() {
  for (const RobotJointSpec& j : tree.joints)
    for (const RobotDof& d : j.dofs)
      dofs_by_name[d.name].push_back(&d);
  const auto expected = [&](const std::string& name, std::size_t count, bool velocity) {
    const RobotDof& d = *dofs_by_name.at(name).front();
    if (d.kind == RobotDof::Kind::ball) {
      return velocity ? std::string("[wx, wy, wz] (rad/s, the child's frame) for a ball joint")
                      : std::string("[w, x, y, z] (a unit quaternion) for a ball joint");
    }
    if (count == 2) return std::string("[a, b] (rad, about axis then axis2) for a universal joint");
    return fmt::format(
        "a number ({}) for a {} joint",
        d.kind == RobotDof::Kind::slide ? (velocity ? "m/s" : "m") : (velocity ? "rad/s" : "rad"),
        d.kind == RobotDof::Kind::slide ? "prismatic" : "hinge");
  };
  for (const auto* given : {&options.positions, &options.velocities}) {
    const bool velocity = given == &options.velocities;
    const char* key = velocity ? "velocities" : "positions";
    for (const auto& [name, values] : *given) {
      const auto it = dofs_by_name.find(name);
      if (it == dofs_by_name.end()) {
        std::string names;
        for (const auto& [n, d] : dofs_by_name)
          names += (names.empty() ? "\"" : ", \"") + n + "\"";
        throw InvalidInput(fmt::format("{}.{}: no moving joint of that name in {}; expected one of {}", key,
                                       name, model.source, names.empty() ? "(none)" : names));
      }
      const auto [np, nv] = value_counts(it->second);
      const std::size_t count = velocity ? nv : np;
      if (values.size() != count) {
        throw InvalidInput(fmt::format("{}.{}: got {} value(s), expected {}", key, name, values.size(),
                                       expected(name, count, velocity)));
      }
      std::size_t offset = 0;
      for (const RobotDof* d : it->second) {
        const std::size_t m =
            velocity ? (d->kind == RobotDof::Kind::ball ? 3 : 1) : (d->kind == RobotDof::Kind::ball ? 4 : 1);
        std::vector<double> v(values.begin() + static_cast<std::ptrdiff_t>(offset),
                              values.begin() + static_cast<std::ptrdiff_t>(offset + m));
        offset += m;
        if (!velocity && d->kind == RobotDof::Kind::ball) {
          const double norm = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2] + v[3] * v[3]);
          if (!(norm > 1e-12))
            throw InvalidInput(
                fmt::format("{}.{}: got a zero quaternion, expected [w, x, y, z] with a "
                            "non-zero norm",
                            key, name));
          for (double& x : v)
            x /= norm;
        }
        // A position is kept as the displacement from the file's pose (q − reference).
        if (!velocity && d->kind != RobotDof::Kind::ball) v[0] -= d->reference;
        (velocity ? qd : q)[d] = std::move(v);
      }
    }
  }
}

/// Poses (at the initial and at the file's coordinates) and twists of every link.
void RobotSystemBuilder::pose_links() {
  const std::size_t n = model.links.size();
  pose.assign(n, {});
  pose0.assign(n, {});
  twist.assign(n, {});
  for (const int k : order) {
    const std::size_t u = static_cast<std::size_t>(k);
    const RobotJointSpec* j = spec_of(u);
    if (j == nullptr) {  // a URDF root: at the origin of space
      pose[u] = pose0[u] = RigidPose{};
      if (options.floating_base) set_base(u);
      continue;
    }
    const RigidPose parent = j->parent < 0 ? RigidPose{} : pose[static_cast<std::size_t>(j->parent)];
    const RigidPose parent0 = j->parent < 0 ? RigidPose{} : pose0[static_cast<std::size_t>(j->parent)];
    const Twist parent_twist = j->parent < 0 ? Twist{} : twist[static_cast<std::size_t>(j->parent)];
    pose0[u] = parent0 * j->parent_child;
    if (j->kind == RobotJointKind::free) {
      pose[u] = parent * j->parent_child;
      if (model.format != RobotFormat::urdf) set_base(u);  // a URDF floating joint: at rest
      continue;
    }
    RigidPose f = parent * j->parent_child;
    Twist t = parent_twist;
    for (const RobotDof& d : j->dofs) {
      const double* qv = coordinate(d, false);
      const double* wv = coordinate(d, true);
      const RigidPose after = f * dof_motion(d, qv);
      const Vec3 anchor = f * d.anchor_child;
      switch (d.kind) {
        case RobotDof::Kind::hinge: {
          const Vec3 w = (f.R * d.axis_child) * wv[0];
          t.omega += w;
          t.v0 -= w.cross(anchor);
          break;
        }
        case RobotDof::Kind::slide:
          t.v0 += (f.R * d.axis_child) * wv[0];
          break;
        case RobotDof::Kind::ball: {
          const Vec3 w = after.R * Vec3(wv[0], wv[1], wv[2]);
          t.omega += w;
          t.v0 -= w.cross(anchor);
          break;
        }
      }
      f = after;
    }
    pose[u] = f;
    twist[u] = t;
  }
}

/// The floating base: the URDF root with floating_base, or a free body of MJCF or SDF.
void RobotSystemBuilder::set_base(std::size_t u) {
  ++floating_bases;
  if (options.base_position) pose[u].p = *options.base_position;
  if (options.base_rotation) pose[u].R = *options.base_rotation;
  Twist t;
  t.omega = pose[u].R * options.base_omega_body.value_or(Vec3::Zero());
  t.v0 = options.base_velocity.value_or(Vec3::Zero()) - t.omega.cross(pose[u].p);
  twist[u] = t;
}

/// Bodies: every link with mass, except those fixed to the world; links without mass attached by a fixed
/// joint become frames of their parent's body (or of the world).
void RobotSystemBuilder::place_links() {
  const std::size_t n = model.links.size();
  place.assign(n, {});
  inertia.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    inertia[k] = link_inertia(model, tree, k, options.inertia);
  for (const int k : order) {
    const std::size_t u = static_cast<std::size_t>(k);
    const RobotJointSpec* j = spec_of(u);
    const bool root = j == nullptr;
    const bool moves = root ? options.floating_base : j->kind != RobotJointKind::fixed;
    const bool massive = inertia[u].props.mass > 0.0;
    if (!moves && !massive) {  // a frame of its parent (or of the world)
      if (root || j->parent < 0) {
        place[u] = {kWorld, pose0[u], false};
      } else {
        const LinkPlace& p = place[static_cast<std::size_t>(j->parent)];
        place[u] = {p.body, p.in_body * j->parent_child, false};
      }
      continue;
    }
    if (root && !moves) {  // a URDF root fixed to the world: the world itself when it has no mass
      place[u] = {kWorld, RigidPose{}, false};
      if (!massive) continue;
    }
    if (!massive) {
      throw InvalidInput(fmt::format("{}: mass {} kg on a link that moves ({}); expected a mass > 0",
                                     where_link(u), format_number(inertia[u].props.mass),
                                     root ? "the floating base" : j->element));
    }
    add_body(u);
  }
}

void RobotSystemBuilder::add_body(std::size_t u) {
  const RobotLink& link = model.links[u];
  const LinkInertia& li = inertia[u];
  try {
    sc.system.add_body(link.name, li.props.mass, inertia::poinsot_from_inertia(li.props.inertia_com));
  } catch (const InvalidInput& e) {
    throw InvalidInput(fmt::format("{}: {}", where_link(u), e.what()));
  }
  place[u] = {sc.system.body_count() - 1, RigidPose{}, true};
  link_of_body.push_back(u);
  multibody::BodyState s;
  s.R_space_body = pose[u].R;
  s.x_space = pose[u] * li.props.com;
  s.v_space = twist[u].at(s.x_space);
  s.omega_body = pose[u].R.transpose() * twist[u].omega;
  sc.initial.bodies.push_back(s);
  const std::string at = model.lines.file(link.line).empty() ? model.lines.label(link.line) + " of the file"
                                                             : model.lines.label(link.line);
  sc.body_descriptions.push_back(fmt::format("{}, inertia {}", at, li.how));
  sc.body_surfaces.push_back(nullptr);
}

namespace {

/// A mesh as drawn: the file's triangles at their scale, in the geometry's frame as the file writes it. For
/// MJCF this is where MuJoCo shows it too: MuJoCo moves a mesh to its centre of mass and principal axes and
/// moves the geom's frame back by as much (docs/robot_models.md). Throws InvalidInput when the mesh cannot
/// be read (it is then not drawn).
inertia::TriangleMesh drawn_mesh(const LinkGeometry& g) {
  inertia::TriangleMesh mesh = inertia::load_mesh(g.mesh_path);
  for (Vec3& v : mesh.vertices)
    v = g.mesh_scale.cwiseProduct(v);
  if (g.mesh_scale.prod() < 0.0) inertia::flip_orientation(mesh);  // a reflection reverses the winding
  return mesh;
}

}  // namespace

/// Each body's drawn surface (view.html): the shapes and meshes of its link and of the frames merged into it,
/// about its centre of mass in its frame.
void RobotSystemBuilder::add_surfaces() {
  std::vector<inertia::TriangleMesh> surfaces(static_cast<std::size_t>(sc.system.body_count()));
  for (std::size_t k = 0; k < place.size(); ++k) {
    if (place[k].body == kWorld) continue;
    const std::size_t b = static_cast<std::size_t>(place[k].body);
    const Vec3 com = inertia[link_of_body[b]].props.com;
    for (const LinkGeometry& g : model.links[k].geometry) {
      const bool mesh = g.shape.kind == "mesh";
      inertia::TriangleMesh part;
      try {
        part = mesh ? drawn_mesh(g) : inertia::tessellate(g.shape, inertia::kDrawnSurfaceSegments);
      } catch (const InvalidInput&) {
        // A shape too degenerate to draw, or a mesh that cannot be read; its mass is already accounted for
        // or refused.
        continue;
      }
      inertia::TriangleMesh& m = surfaces[b];
      const auto offset = static_cast<std::int32_t>(m.vertices.size());
      for (const Vec3& v : part.vertices)
        m.vertices.push_back(place[k].in_body * (g.R_link_geometry * v + g.position_link) - com);
      for (const auto& t : part.triangles)
        m.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
  }
  for (std::size_t b = 0; b < surfaces.size(); ++b) {
    if (!surfaces[b].triangles.empty())
      sc.body_surfaces[b] = std::make_shared<const inertia::TriangleMesh>(std::move(surfaces[b]));
  }
}

}  // namespace detail

namespace {

detail::RobotTree read_tree(const RobotModel& model) {
  const detail::XmlSource xml(model.text, model.lines);
  switch (model.format) {
    case RobotFormat::urdf:
      return detail::read_urdf_tree(xml, model);
    case RobotFormat::mjcf:
      return detail::read_mjcf_tree(xml, model);
    case RobotFormat::sdf:
      return detail::read_sdf_tree(xml, model);
  }
  return {};
}

}  // namespace

multibody::Scenario robot_scenario(const RobotModel& model, const RobotSystemOptions& options) {
  detail::RobotSystemBuilder bld(model, options, read_tree(model));
  bld.sc.source = model.source;
  bld.sc.title = fmt::format("{} model ({} links)", to_string(model.format), model.links.size());
  bld.sort_links();
  bld.read_coordinates();
  bld.pose_links();
  if (bld.floating_bases != 1 &&
      (options.base_position || options.base_rotation || options.base_velocity || options.base_omega_body)) {
    throw InvalidInput(
        fmt::format("base: the model has {} floating bases; expected exactly one (the URDF root "
                    "with floating_base, or the one free body of MJCF and SDF)",
                    bld.floating_bases));
  }
  bld.place_links();
  if (bld.sc.system.body_count() == 0)
    throw InvalidInput(
        fmt::format("{}: no link has mass and moves; expected at least one body", model.source));
  bld.add_joints();
  bld.add_loops();
  bld.add_surfaces();
  bld.sc.system.set_gravity(
      options.gravity.value_or(bld.tree.has_gravity ? bld.tree.gravity : Vec3(0.0, 0.0, -9.81)));
  std::size_t shapes = 0;
  for (const RobotLink& link : model.links)
    shapes += link.geometry.size();
  if (shapes > 0)
    bld.sc.not_modelled.push_back(fmt::format("contacts between the links' shapes ({} shapes)", shapes));
  for (std::string& line : bld.tree.not_modelled)
    bld.sc.not_modelled.push_back(std::move(line));
  multibody::project_velocities(bld.sc.system, bld.sc.initial);
  return std::move(bld.sc);
}

multibody::Scenario load_robot_scenario(const std::string& path, const RobotSystemOptions& options) {
  return robot_scenario(load_robot_model(path), options);
}

bool is_robot_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext == ".urdf" || ext == ".xml" || ext == ".sdf";
}

}  // namespace poinsot::io
