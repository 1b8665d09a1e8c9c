#pragma once
/// @file dispersion.hpp
/// The laws by which an ensemble disperses a quantity about its nominal value.
///
/// Scalars (a principal moment, the mass, a component of ω, of the centre of mass or of a torque), with
/// width w (absolute, in the quantity's unit, or relative: w·|nominal|, or w·‖nominal vector‖ for a
/// component of a vector):
///   normal            x = x₀ + w z,            z ~ N(0, 1)
///   uniform           x = x₀ + w (2u − 1),     u ~ U(0, 1), i.e. uniform on [x₀ − w, x₀ + w]
///   truncated normal  x = x₀ + w z,            z ~ N(0, 1) conditioned on |z| ≤ c (c = `truncation` ≥ 0.5;
///                                              drawn by rejection, acceptance ≥ 38 %)
///
/// Rotations δ (a misalignment of the principal axes, a perturbation of the initial attitude), applied as
/// R = δ R₀ (attitude) or P = P₀ δ (axes, so each principal axis turns by the angle of δ):
///   cone    δ = exp(j(θ n)), n uniform on the unit sphere and θ ∈ [0, α] with density ∝ 1 − cos θ: the
///           Haar (uniform) measure on SO(3) restricted to rotations by at most the half-angle α (rad). Every
///           axis then moves by at most α. CDF of θ: (θ − sin θ)/(α − sin α).
///   normal  δ = exp(j(v)), v ~ N(0, σ² I₃): the angle |v| follows σ times a χ distribution with 3 degrees of
///           freedom.
#include <string>
#include <string_view>

#include "poinsot/core/types.hpp"
#include "poinsot/ensemble/counter_rng.hpp"

namespace poinsot::ensemble {

enum class Law { none, normal, uniform, truncated_normal };

/// "none", "normal", "uniform", "truncated_normal".
const char* to_string(Law law);
/// The law named by `name`; throws InvalidInput naming `what`, the value and the valid names otherwise.
Law law_from_string(std::string_view name, std::string_view what);

struct ScalarDispersion {
  Law law = Law::none;
  double width = 0.0;     ///< σ (normal laws) or the half-width (uniform); unit of the quantity, or relative
  bool relative = false;  ///< width is a fraction of |nominal|
  double truncation = 3.0;  ///< truncated normal: |z| ≤ truncation (in σ)
};

/// Throws InvalidInput, naming `what`, for a negative or non-finite width or a truncation below 0.5.
void validate(const ScalarDispersion& d, std::string_view what);

/// One draw of x about `nominal`; `scale` is the magnitude a relative width multiplies (|nominal| for a
/// scalar, the vector's norm for a component). Consumes no draws for Law::none.
double disperse(const ScalarDispersion& d, double nominal, double scale, SampleStream& stream);

/// Each component of `nominal` dispersed by `d` (relative widths scale with ‖nominal‖).
Vec3 disperse(const ScalarDispersion& d, const Vec3& nominal, SampleStream& stream);

enum class RotationLaw { none, cone, normal };

/// "none", "cone", "normal".
const char* to_string(RotationLaw law);
RotationLaw rotation_law_from_string(std::string_view name, std::string_view what);

struct RotationDispersion {
  RotationLaw law = RotationLaw::none;
  double angle = 0.0;  ///< rad: the cone's half-angle α (≤ π), or σ of each rotation-vector component
};

/// Throws InvalidInput for a negative or non-finite angle, or a cone wider than π.
void validate(const RotationDispersion& d, std::string_view what);

/// The rotation vector θ n of one draw (rad); zero for RotationLaw::none (no draws consumed).
Vec3 draw_rotation_vector(const RotationDispersion& d, SampleStream& stream);

/// θ − sin θ without cancellation (a series below θ = 1), for the cone law's CDF.
double theta_minus_sin(double theta);

}  // namespace poinsot::ensemble
