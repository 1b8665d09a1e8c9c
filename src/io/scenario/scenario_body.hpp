#pragma once
// Internal to the io layer: the inertia of a scenario's body, read the same way for the `[body]` of a
// single-body scenario and for every `[[bodies]]` entry of a multibody one (docs/scenario.md,
// docs/multibody.md): explicit tensors, a shape of the inertia layer, a mesh file or a composite body file.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"
#include "poinsot/inertia/mesh.hpp"
#include "toml_fields.hpp"

namespace poinsot::io::detail {

/// Mass properties of a body as the scenario gave them, in the body's frame: the frame its data were given in
/// (a shape's own frame, a mesh's or composite file's frame; for explicit tensors a frame at the centre of
/// mass), possibly with the centre of mass away from its origin.
struct BodyInertia {
  std::string how;  ///< the key used: one of principal_moments, inertia, poinsot, shape, mesh, composite
  Mat3 inertia_com = Mat3::Identity();  ///< J about the centre of mass, body axes (kg·m²)
  /// K = tr(J)/2·I − J about the centre of mass (kg·m²); exactly the file's values with `poinsot`.
  Mat3 poinsot_com = Mat3::Identity();
  /// kg: from the shape, mesh or composite, or the body's `mass` key; nullopt for an explicit tensor given
  /// without `mass`.
  std::optional<double> mass;
  Vec3 com = Vec3::Zero();  ///< centre of mass in the body's frame (m); 0 but for meshes and composites
  std::string description;  ///< for the report, e.g. "box size [0.3, 0.1, 0.02] m, mass 0.4 kg (...)"
  /// The body's surface about its centre of mass (body axes, m), for drawing: a shape's tessellation
  /// (inertia::kDrawnSurfaceSegments around its axis), a mesh file's triangles; null for explicit tensors,
  /// composites and the shapes without a solid (point, rod without radius, thin shells).
  std::shared_ptr<const inertia::TriangleMesh> surface;
};

/// Reads the inertia of the body table `body` (a Section whose valid keys include the six keys below and
/// `mass`): exactly one of
///  - `principal_moments = [I1, I2, I3]`, `inertia` (J: [Jxx, Jyy, Jzz] or 3×3) or `poinsot` (K, same
///    forms), kg·m², about the centre of mass; the body's `mass` (kg) is returned as is (the caller decides
///    whether it needs one);
///  - `shape = { type, sizes, mass | density, axis }`: a homogeneous shape of the inertia layer; its mass may
///    instead be the body's `mass` (not both). `axis` ("x", "y" or "z") lays the symmetry axis of a rod,
///    cylinder, cone, capsule or torus along that body axis, default `default_axis`; a rod with a `radius` is
///    a solid cylinder;
///  - `mesh = { file, mass | density, shell, flip_inward }`: a closed triangle mesh (file relative to
///    `base_dir`); its mass may instead be the body's `mass`;
///  - `composite = { file }`: a composite body file (inertia/body_file.hpp, relative to `base_dir`), which
///    gives the mass.
/// Throws InvalidInput located at the key (`FILE:LINE:COLUMN: [body.shape] size: ...`) for any problem,
/// with the inertia layer's message for values it refuses. Explicit tensors are only read here: the caller
/// validates them (RigidBody, multibody::System).
BodyInertia read_body_inertia(const Source& source, const Section& body, std::string_view base_dir,
                              char default_axis);

}  // namespace poinsot::io::detail
