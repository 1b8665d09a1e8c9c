#include "poinsot/ensemble/sampler.hpp"

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/inertia/principal_axes.hpp"
#include "poinsot/inertia/validity.hpp"
#include "poinsot/so3/exp_log.hpp"

namespace poinsot::ensemble {
namespace {

bool is_diagonal(const Mat3& J) {
  return J(0, 1) == 0.0 && J(0, 2) == 0.0 && J(1, 0) == 0.0 && J(1, 2) == 0.0 && J(2, 0) == 0.0 &&
         J(2, 1) == 0.0;
}

}  // namespace

const char* to_string(ValidityPolicy policy) {
  return policy == ValidityPolicy::reject ? "reject" : "repair";
}

ValidityPolicy policy_from_string(std::string_view name, std::string_view what) {
  if (name == "reject") return ValidityPolicy::reject;
  if (name == "repair") return ValidityPolicy::repair;
  throw InvalidInput(fmt::format("{}: got \"{}\", expected one of reject, repair", what, name));
}

bool usable_moments(const Vec3& moments) {
  if (!moments.allFinite()) return false;
  const double floor = 1e-9 * moments.sum();
  if (!(moments.minCoeff() > floor)) return false;
  return inertia::check_inertia(Mat3(moments.asDiagonal())).valid;
}

Nominal Nominal::from(const dynamics::RigidBody& body, const dynamics::State& initial, TorqueKind torque,
                      const Vec3& torque_value) {
  Nominal n;
  const Mat3& J = body.inertia_com();
  if (is_diagonal(J)) {
    n.moments = J.diagonal();
  } else {
    const inertia::PrincipalAxes pa = inertia::principal_axes(J);
    n.moments = pa.moments;
    n.axes = pa.axes;
  }
  n.has_pivot = body.has_pivot();
  n.mass = body.mass();
  n.pivot_to_com = body.pivot_to_com();
  n.omega_body = initial.omega_body;
  n.R = initial.R_space_body;
  n.torque = torque;
  n.torque_value = torque_value;
  return n;
}

Mat3 Sample::inertia_com() const {
  if (axes == Mat3::Identity()) return Mat3(moments.asDiagonal());
  const Mat3 J = axes * moments.asDiagonal() * axes.transpose();
  return 0.5 * (J + J.transpose());  // exactly symmetric
}

dynamics::RigidBody Sample::body() const {
  const dynamics::RigidBody free = dynamics::RigidBody::from_inertia(inertia_com());
  return has_pivot ? free.with_pivot(mass, pivot_to_com) : free;
}

std::shared_ptr<const dynamics::TorqueModel> Sample::torque_model(const dynamics::RigidBody& body) const {
  switch (torque) {
    case TorqueKind::none:
      return dynamics::TorqueModel::none();
    case TorqueKind::body:
      return dynamics::TorqueModel::constant_body(torque_value);
    case TorqueKind::space:
      return dynamics::TorqueModel::constant_space(torque_value);
    case TorqueKind::gravity:
      return dynamics::TorqueModel::gravity(body, torque_value);
  }
  return dynamics::TorqueModel::none();
}

Sampler::Sampler(const Nominal& nominal, const Dispersions& d, std::uint64_t seed)
    : nominal_(nominal), dispersions_(d), seed_(seed) {
  validate(d.moments, "[ensemble] moments");
  validate(d.axes, "[ensemble] axes");
  validate(d.mass, "[ensemble] mass");
  validate(d.center_of_mass, "[ensemble] center_of_mass");
  validate(d.omega, "[ensemble] omega");
  validate(d.attitude, "[ensemble] attitude");
  validate(d.torque, "[ensemble] torque");
  if (d.max_tries < 1) {
    throw InvalidInput(fmt::format("[ensemble] max_tries: got {}, expected an integer >= 1", d.max_tries));
  }
  if (!usable_moments(nominal.moments)) {
    const inertia::InertiaCheck c = inertia::check_inertia(Mat3(nominal.moments.asDiagonal()));
    throw InvalidInput(fmt::format(
        "ensemble: the nominal principal moments {} kg·m² are not a usable body ({}); expected moments > 0 "
        "with Ii + Ij >= Ik",
        format_vector(nominal.moments), c.valid ? "a moment is zero" : c.message));
  }
  if ((d.mass.law != Law::none || d.center_of_mass.law != Law::none) && !nominal.has_pivot) {
    throw InvalidInput(
        "[ensemble] mass: a mass or centre-of-mass dispersion needs a body held at a pivot ([body] mass and "
        "pivot_to_com)");
  }
  if (d.torque.law != Law::none && nominal.torque == TorqueKind::none) {
    throw InvalidInput(
        "[ensemble] torque: a torque dispersion needs a [torque] of type body, space or gravity");
  }
}

Sample Sampler::nominal() const {
  Sample s;
  s.moments = nominal_.moments;
  s.axes = nominal_.axes;
  s.mass = nominal_.mass;
  s.pivot_to_com = nominal_.pivot_to_com;
  s.has_pivot = nominal_.has_pivot;
  s.initial.R_space_body = nominal_.R;
  s.initial.omega_body = nominal_.omega_body;
  s.torque = nominal_.torque;
  s.torque_value = nominal_.torque_value;
  return s;
}

Sample Sampler::draw(std::uint64_t index) const {
  const Dispersions& d = dispersions_;
  Sample s = nominal();
  s.index = index;
  const auto exhausted = [&](std::string_view what) {
    return InvalidInput(fmt::format(
        "ensemble: sample {}: no usable {} after {} draws (policy {}); expected dispersions that can produce "
        "a valid body, a larger max_tries, or policy = \"repair\"",
        index, what, d.max_tries, to_string(d.policy)));
  };

  SampleStream moments(seed_, index, Stream::moments);
  for (int attempt = 1;; ++attempt) {
    Vec3 I;
    for (int k = 0; k < 3; ++k)
      I[k] = disperse(d.moments, nominal_.moments[k], nominal_.moments[k], moments);
    if (usable_moments(I)) {
      s.moments = I;
      break;
    }
    if (d.policy == ValidityPolicy::repair) {
      const Vec3 p = inertia::project_moments_to_valid(I);
      if (usable_moments(p)) {
        s.moments = p;
        s.repaired = true;
        break;
      }
    }
    ++s.rejected;
    if (attempt >= d.max_tries) throw exhausted("principal moments");
  }

  SampleStream axes(seed_, index, Stream::axes);
  if (d.axes.law != RotationLaw::none) {
    const Vec3 v = draw_rotation_vector(d.axes, axes);
    s.misalignment = v.norm();
    s.axes = nominal_.axes * so3::exp(v);
  }

  if (nominal_.has_pivot) {
    SampleStream mass(seed_, index, Stream::mass);
    for (int attempt = 1;; ++attempt) {
      s.mass = disperse(d.mass, nominal_.mass, nominal_.mass, mass);
      if (s.mass > 0.0) break;
      ++s.rejected;
      if (attempt >= d.max_tries) throw exhausted("mass");
    }
    SampleStream com(seed_, index, Stream::center_of_mass);
    s.pivot_to_com = disperse(d.center_of_mass, nominal_.pivot_to_com, com);
  }

  SampleStream omega(seed_, index, Stream::omega);
  s.initial.omega_body = disperse(d.omega, nominal_.omega_body, omega);
  SampleStream attitude(seed_, index, Stream::attitude);
  if (d.attitude.law != RotationLaw::none)
    s.initial.R_space_body = so3::exp(draw_rotation_vector(d.attitude, attitude)) * nominal_.R;
  SampleStream torque(seed_, index, Stream::torque);
  s.torque_value = disperse(d.torque, nominal_.torque_value, torque);
  return s;
}

}  // namespace poinsot::ensemble
