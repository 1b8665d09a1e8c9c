#pragma once
/// @file sampler.hpp
/// The bodies and initial conditions of an ensemble: sample i is a pure function of (seed, i) and the nominal
/// values (counter_rng.hpp), so it can be recomputed alone, on any thread or process.
///
/// A sample's inertia about its centre of mass, body frame (kg·m²), is J = P diag(I) Pᵀ with the moments I
/// dispersed one by one about the nominal moments and the axes P = P₀ δ turned by a misalignment δ
/// (dispersion.hpp). The nominal J₀ = P₀ diag(I₀) P₀ᵀ: for a nominal J that is diagonal in its body frame,
/// P₀ = 1 and I₀ its diagonal (in the body's axis order), otherwise its principal axes and moments.
///
/// Validity (inertia/validity.hpp): J is physical when I lies in the cone Iᵢ + Iⱼ ≥ Iₖ; the ensemble also
/// needs every moment > 1e-9·tr I (its integrators divide by the moments). A draw outside is handled by the
/// policy:
///   reject  redraw the moments (the next draws of the same stream) up to `max_tries` times; the number of
///           redraws is counted per sample; a sample that exhausts the cap is an InvalidInput naming it
///   repair  project the moments onto the cone (inertia::project_moments_to_valid, the inertia layer's
///   nearest
///           valid tensor with the same axes) and count the sample as repaired; a projection that leaves a
///           moment ≤ 1e-9·tr I (a drawn moment far below zero) is then redrawn like `reject`.
/// Every sample returned passes inertia::check_inertia.
#include <cstdint>

#include "poinsot/core/types.hpp"
#include "poinsot/dynamics/rigid_body.hpp"
#include "poinsot/dynamics/state.hpp"
#include "poinsot/dynamics/torque.hpp"
#include "poinsot/ensemble/dispersion.hpp"

namespace poinsot::ensemble {

enum class ValidityPolicy { reject, repair };
const char* to_string(ValidityPolicy policy);
ValidityPolicy policy_from_string(std::string_view name, std::string_view what);

/// The torque acting on every sample.
enum class TorqueKind { none, body, space, gravity };

/// The nominal sample: the body, its initial state and its torque.
struct Nominal {
  Vec3 moments = Vec3::Ones();   ///< principal moments about the centre of mass (kg·m²), order of `axes`
  Mat3 axes = Mat3::Identity();  ///< principal axes (columns) in the body frame, a rotation
  double mass = 0.0;             ///< kg (a top; 0 for a free body)
  Vec3 pivot_to_com = Vec3::Zero();  ///< m, body frame (a top)
  bool has_pivot = false;
  Vec3 omega_body = Vec3::Zero();  ///< rad/s
  Mat3 R = Mat3::Identity();       ///< body → space
  TorqueKind torque = TorqueKind::none;
  Vec3 torque_value = Vec3::Zero();  ///< N·m (body or space), or g (m/s², space) for gravity

  /// The nominal of a body (RigidBody::inertia_com, mass and pivot), a state and a torque (see the file
  /// comment for P₀ and I₀).
  static Nominal from(const dynamics::RigidBody& body, const dynamics::State& initial, TorqueKind torque,
                      const Vec3& torque_value);
};

/// What is dispersed, and how.
struct Dispersions {
  ScalarDispersion moments;         ///< each principal moment (relative: of that moment)
  RotationDispersion axes;          ///< misalignment of the principal axes
  ScalarDispersion mass;            ///< kg (a top)
  ScalarDispersion center_of_mass;  ///< each component of pivot_to_com (m; relative: of its norm)
  ScalarDispersion omega;           ///< each component of ω_body (rad/s; relative: of |ω|)
  RotationDispersion attitude;      ///< R = δ R₀
  ScalarDispersion torque;          ///< each component of the torque value (relative: of its norm)
  ValidityPolicy policy = ValidityPolicy::reject;
  int max_tries = 100;  ///< reject: the most draws of the moments for one sample
};

/// One sample.
struct Sample {
  std::uint64_t index = 0;
  Vec3 moments = Vec3::Ones();  ///< kg·m² (after any repair), order of `axes`
  Mat3 axes = Mat3::Identity();
  double misalignment = 0.0;  ///< rad, the angle of δ
  double mass = 0.0;
  Vec3 pivot_to_com = Vec3::Zero();
  bool has_pivot = false;
  dynamics::State initial;
  TorqueKind torque = TorqueKind::none;
  Vec3 torque_value = Vec3::Zero();
  int rejected = 0;       ///< redraws of the moments
  bool repaired = false;  ///< moved onto the valid cone by the repair policy

  /// J = P diag(I) Pᵀ about the centre of mass, body frame (kg·m²); exactly diagonal when P = 1.
  Mat3 inertia_com() const;
  /// The rigid body (with its pivot for a top).
  dynamics::RigidBody body() const;
  /// The torque model (null pointer never: TorqueModel::none() for none).
  std::shared_ptr<const dynamics::TorqueModel> torque_model(const dynamics::RigidBody& body) const;
};

class Sampler {
 public:
  /// Validates the dispersions (negative widths, angles, max_tries < 1) and the nominal body (its inertia
  /// must be valid: a fixed moment set violating the triangle inequality is refused here). Throws
  /// InvalidInput, one line naming the field.
  Sampler(const Nominal& nominal, const Dispersions& dispersions, std::uint64_t seed);

  /// Sample `index`: a pure function of (seed, index). Throws InvalidInput when the reject policy exhausts
  /// max_tries (naming the sample and the policy).
  Sample draw(std::uint64_t index) const;
  /// The nominal sample (no dispersion).
  Sample nominal() const;

  const Nominal& nominal_values() const { return nominal_; }
  const Dispersions& dispersions() const { return dispersions_; }
  std::uint64_t seed() const { return seed_; }

 private:
  Nominal nominal_;
  Dispersions dispersions_;
  std::uint64_t seed_;
};

/// True when the moments (kg·m²) are usable by the ensemble: inside the cone of valid moments to
/// inertia::check_inertia's tolerance and each > 1e-9 times their sum.
bool usable_moments(const Vec3& moments);

}  // namespace poinsot::ensemble
