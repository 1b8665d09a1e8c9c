#include "poinsot/ensemble/dispersion.hpp"

#include <array>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"

namespace poinsot::ensemble {
namespace {

// A truncated normal whose acceptance is at least erf(0.5/√2) = 38 % needs fewer than 200 tries with
// probability 1 − 0.62²⁰⁰ ≈ 1 − 1e-42; the cap only guards against a broken generator.
constexpr int kTruncatedNormalTries = 200;

}  // namespace

const char* to_string(Law law) {
  switch (law) {
    case Law::none:
      return "none";
    case Law::normal:
      return "normal";
    case Law::uniform:
      return "uniform";
    case Law::truncated_normal:
      return "truncated_normal";
  }
  return "?";
}

Law law_from_string(std::string_view name, std::string_view what) {
  for (Law l : {Law::none, Law::normal, Law::uniform, Law::truncated_normal})
    if (name == to_string(l)) return l;
  throw InvalidInput(
      fmt::format("{}: got \"{}\", expected one of none, normal, uniform, truncated_normal", what, name));
}

void validate(const ScalarDispersion& d, std::string_view what) {
  if (!(std::isfinite(d.width) && d.width >= 0.0)) {
    throw InvalidInput(fmt::format("{}: width {} {}; expected a finite number >= 0", what,
                                   format_number(d.width), d.relative ? "(relative)" : ""));
  }
  if (d.law == Law::truncated_normal && !(std::isfinite(d.truncation) && d.truncation >= 0.5)) {
    throw InvalidInput(
        fmt::format("{}: truncation {} σ; expected a number >= 0.5", what, format_number(d.truncation)));
  }
}

double disperse(const ScalarDispersion& d, double nominal, double scale, SampleStream& stream) {
  const double w = d.relative ? d.width * std::abs(scale) : d.width;
  switch (d.law) {
    case Law::none:
      return nominal;
    case Law::normal:
      return nominal + w * stream.normal();
    case Law::uniform:
      return nominal + w * (2.0 * stream.uniform() - 1.0);
    case Law::truncated_normal:
      for (int i = 0; i < kTruncatedNormalTries; ++i) {
        const double z = stream.normal();
        if (std::abs(z) <= d.truncation) return nominal + w * z;
      }
      throw ComputationFailed("ensemble: the truncated normal law found no draw within its bounds");
  }
  return nominal;
}

Vec3 disperse(const ScalarDispersion& d, const Vec3& nominal, SampleStream& stream) {
  const double scale = nominal.norm();
  return Vec3(disperse(d, nominal[0], scale, stream), disperse(d, nominal[1], scale, stream),
              disperse(d, nominal[2], scale, stream));
}

const char* to_string(RotationLaw law) {
  switch (law) {
    case RotationLaw::none:
      return "none";
    case RotationLaw::cone:
      return "cone";
    case RotationLaw::normal:
      return "normal";
  }
  return "?";
}

RotationLaw rotation_law_from_string(std::string_view name, std::string_view what) {
  for (RotationLaw l : {RotationLaw::none, RotationLaw::cone, RotationLaw::normal})
    if (name == to_string(l)) return l;
  throw InvalidInput(fmt::format("{}: got \"{}\", expected one of none, cone, normal", what, name));
}

void validate(const RotationDispersion& d, std::string_view what) {
  if (!(std::isfinite(d.angle) && d.angle >= 0.0)) {
    throw InvalidInput(
        fmt::format("{}: angle {} rad; expected a finite number >= 0", what, format_number(d.angle)));
  }
  if (d.law == RotationLaw::cone && d.angle > std::numbers::pi) {
    throw InvalidInput(
        fmt::format("{}: cone half-angle {} rad; expected at most π", what, format_number(d.angle)));
  }
}

double theta_minus_sin(double theta) {
  if (std::abs(theta) < 1.0) {
    // θ³ Σₖ (−θ²)ᵏ/(2k + 3)! for k = 0..9, by Horner: the first omitted term θ²³/23! < 4e-23 θ³.
    const double z = theta * theta;
    constexpr auto inverse_factorials = [] {  // 1/(2k + 3)!
      std::array<double, 10> c{};
      double f = 6.0;
      for (int k = 0; k < 10; ++k) {
        c[static_cast<std::size_t>(k)] = 1.0 / f;
        f *= (2 * k + 4) * (2 * k + 5);
      }
      return c;
    }();
    double sum = 0.0;
    for (int k = 9; k >= 0; --k)
      sum = inverse_factorials[static_cast<std::size_t>(k)] - z * sum;
    return theta * z * sum;
  }
  return theta - std::sin(theta);  // ≥ 0.158: the cancellation costs at most 7 ulps
}

Vec3 draw_rotation_vector(const RotationDispersion& d, SampleStream& stream) {
  switch (d.law) {
    case RotationLaw::none:
      return Vec3::Zero();
    case RotationLaw::normal: {
      const double x = stream.normal(), y = stream.normal(), z = stream.normal();
      return d.angle * Vec3(x, y, z);
    }
    case RotationLaw::cone: {
      // Axis uniform on the sphere (Archimedes: z uniform on [−1, 1]).
      const double z = 2.0 * stream.uniform() - 1.0;
      const double phi = 2.0 * std::numbers::pi * stream.uniform();
      const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
      const Vec3 n(r * std::cos(phi), r * std::sin(phi), z);
      // Angle by inversion of F(θ) = (θ − sin θ)/(α − sin α), increasing on [0, α]: bisection to the last bit
      // (80 halvings of [0, π] reach below 1e-23 rad).
      const double target = stream.uniform() * theta_minus_sin(d.angle);
      double lo = 0.0, hi = d.angle;
      for (int i = 0; i < 80; ++i) {
        const double mid = 0.5 * (lo + hi);
        (theta_minus_sin(mid) < target ? lo : hi) = mid;
      }
      return 0.5 * (lo + hi) * n;
    }
  }
  return Vec3::Zero();
}

}  // namespace poinsot::ensemble
