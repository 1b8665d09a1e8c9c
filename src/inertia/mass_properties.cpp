#include "poinsot/inertia/mass_properties.hpp"

#include <cmath>

#include <fmt/format.h>

#include "poinsot/core/check.hpp"
#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/so3/projection.hpp"
#include "poinsot/so3/rotation_check.hpp"

namespace poinsot::inertia {
namespace {

/// m(|d|² I − d⊗d): the tensor of a point mass m at offset d.
Mat3 point_tensor(double mass, const Vec3& d) {
  return mass * (d.squaredNorm() * Mat3::Identity() - d * d.transpose());
}

Mat3 symmetrised(const Mat3& m) {
  return 0.5 * (m + m.transpose());
}

void require_shift_input(double mass, const Vec3& com, const Mat3& J, const Vec3& point) {
  require_non_negative("inertia: mass", mass, "kg");
  require_finite("inertia: centre of mass (m)", com);
  require_finite("inertia: tensor (kg·m²)", J);
  require_finite("inertia: reference point (m)", point);
}

}  // namespace

Mat3 poinsot_from_inertia(const Mat3& J) {
  return 0.5 * J.trace() * Mat3::Identity() - J;
}

Mat3 inertia_from_poinsot(const Mat3& K) {
  return K.trace() * Mat3::Identity() - K;
}

Mat3 shift_from_com(const Mat3& J_com, double mass, const Vec3& com, const Vec3& point) {
  require_shift_input(mass, com, J_com, point);
  return J_com + point_tensor(mass, com - point);
}

Mat3 shift_to_com(const Mat3& J_point, double mass, const Vec3& com, const Vec3& point) {
  require_shift_input(mass, com, J_point, point);
  return J_point - point_tensor(mass, com - point);
}

Mat3 reexpress(const Mat3& tensor_F, const Mat3& R_B_F) {
  require_finite("inertia: tensor (kg·m²)", tensor_F);
  require_finite("inertia: rotation", R_B_F);
  if (!so3::is_rotation(R_B_F)) {
    throw InvalidInput(fmt::format(
        "inertia: rotation {} has orthogonality error {} and determinant {}; expected a rotation (RᵀR = I "
        "to {}, det = +1)",
        format_matrix(R_B_F), format_number(so3::orthogonality_error(R_B_F), 3),
        format_number(R_B_F.determinant(), 6), format_number(so3::kRotationTolerance)));
  }
  return symmetrised(R_B_F * tensor_F * R_B_F.transpose());
}

Mat3 MassProperties::inertia_about(const Vec3& point) const {
  return shift_from_com(inertia_com, mass, com, point);
}

Mat3 MassProperties::poinsot_com() const {
  return poinsot_from_inertia(inertia_com);
}

MassProperties MassProperties::placed(const Mat3& R_P_F, const Vec3& position_P) const {
  require_finite("inertia: position (m)", position_P);
  MassProperties out;
  out.mass = mass;
  out.inertia_com = reexpress(inertia_com, R_P_F);
  out.com = R_P_F * com + position_P;
  return out;
}

MassProperties from_inertia_about(double mass, const Vec3& com, const Mat3& J_point, const Vec3& point) {
  MassProperties out;
  out.mass = mass;
  out.com = com;
  out.inertia_com = shift_to_com(J_point, mass, com, point);
  return out;
}

MassProperties combine(const MassProperties& a, const MassProperties& b) {
  const double m = a.mass + b.mass;
  if (!(m > 0.0) || !std::isfinite(m)) {
    throw InvalidInput(
        fmt::format("inertia: composite of masses {} kg and {} kg has total mass {} kg; "
                    "expected a positive finite total",
                    format_number(a.mass), format_number(b.mass), format_number(m)));
  }
  MassProperties out;
  out.mass = m;
  // Weighted average written as a + (b − a)·m_b/m: exact when a == b, no cancellation of large coordinates.
  out.com = a.com + (b.com - a.com) * (b.mass / m);
  out.inertia_com = a.inertia_about(out.com) + b.inertia_about(out.com);
  out.inertia_com = symmetrised(out.inertia_com);
  return out;
}

MassProperties subtract(const MassProperties& whole, const MassProperties& removed) {
  require_non_negative("inertia: removed mass", removed.mass, "kg");
  const double m = whole.mass - removed.mass;
  if (!(m > 0.0) || !std::isfinite(m)) {
    throw InvalidInput(
        fmt::format("inertia: void of mass {} kg removed from a body of mass {} kg; expected "
                    "the removed mass to be less than the body's",
                    format_number(removed.mass), format_number(whole.mass)));
  }
  MassProperties out;
  out.mass = m;
  out.com = whole.com + (whole.com - removed.com) * (removed.mass / m);
  out.inertia_com = whole.inertia_about(out.com) - removed.inertia_about(out.com);
  out.inertia_com = symmetrised(out.inertia_com);
  return out;
}

}  // namespace poinsot::inertia
