// MJCF frame orientations (see mjcf_orientation.hpp).
#include "mjcf_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/so3/axis_angle.hpp"
#include "poinsot/so3/euler_angles.hpp"
#include "poinsot/so3/quaternion.hpp"

namespace poinsot::io::detail {
namespace {

using tinyxml2::XMLElement;

/// The unit vector of `v`, written by `e` as attribute `what`; throws for a zero vector.
Vec3 nonzero_unit(const XmlSource& xml, const XMLElement& e, const char* what, const Vec3& v) {
  const double n = v.norm();
  if (!(n > 0.0))
    throw InvalidInput(fmt::format("{} {}: zero length; expected a non-zero axis", xml.where(e), what));
  return v / n;
}

Vec3 first3(const std::vector<double>& v, std::size_t offset = 0) {
  return Vec3(v[offset], v[offset + 1], v[offset + 2]);
}

}  // namespace

MjcfCompiler read_mjcf_compiler(const XmlSource& xml) {
  MjcfCompiler c;
  for (const XMLElement* e = xml.root()->FirstChildElement("compiler"); e != nullptr;
       e = e->NextSiblingElement("compiler")) {
    if (const char* a = e->Attribute("angle")) {
      const std::string_view v = a;
      if (v != "radian" && v != "degree")
        throw InvalidInput(fmt::format("{} angle=\"{}\": expected radian or degree", xml.where(*e), v));
      c.angle_unit = v == "radian" ? 1.0 : std::numbers::pi / 180.0;
    }
    if (const char* s = e->Attribute("eulerseq")) c.eulerseq = s;
    if (const char* g = e->Attribute("inertiafromgeom")) c.inertiafromgeom = g;
  }
  return c;
}

namespace {

Mat3 orientation_as_written(const XmlSource& xml, const XMLElement& e, const MjcfCompiler& c,
                            const MjcfNumbers& numbers) {
  if (auto q = numbers("quat", 4)) {
    const Quat quat((*q)[0], (*q)[1], (*q)[2], (*q)[3]);
    if (!(quat.norm() > 0.0))
      throw InvalidInput(fmt::format("{} quat: zero quaternion; expected w x y z, not all 0", xml.where(e)));
    return so3::rotation_from_quaternion(quat.normalized());
  }
  if (auto aa = numbers("axisangle", 4))
    return so3::rotation_from_axis_angle(nonzero_unit(xml, e, "axisangle", first3(*aa)),
                                         (*aa)[3] * c.angle_unit);
  if (auto eu = numbers("euler", 3)) {
    const std::string& s = c.eulerseq;
    const auto all = [&](auto pred) { return s.size() == 3 && std::all_of(s.begin(), s.end(), pred); };
    const bool rotating = all([](char ch) { return ch == 'x' || ch == 'y' || ch == 'z'; });
    const bool fixed = all([](char ch) { return ch == 'X' || ch == 'Y' || ch == 'Z'; });
    if (!rotating && !fixed) {
      throw InvalidInput(
          fmt::format("{} euler: <compiler eulerseq=\"{}\">: expected three of x, y, z (axes "
                      "that rotate with the frame) or three of X, Y, Z (fixed axes)",
                      xml.where(e), s));
    }
    const Vec3 a = c.angle_unit * first3(*eu);
    if (rotating) return so3::rotation_from_euler(so3::EulerSequence::parse(s), a);
    // About fixed axes: the reversed rotating sequence with the angles reversed.
    return so3::rotation_from_euler(so3::EulerSequence::parse(std::string{s[2], s[1], s[0]}),
                                    Vec3(a[2], a[1], a[0]));
  }
  if (auto xy = numbers("xyaxes", 6)) {
    const Vec3 x = nonzero_unit(xml, e, "xyaxes", first3(*xy));
    const Vec3 y =
        nonzero_unit(xml, e, "xyaxes (its y along its x)", first3(*xy, 3) - x * x.dot(first3(*xy, 3)));
    Mat3 R;
    R << x, y, x.cross(y);
    return R;
  }
  if (auto z = numbers("zaxis", 3)) {
    const Vec3 to = nonzero_unit(xml, e, "zaxis", first3(*z));
    const Vec3 k = Vec3::UnitZ().cross(to);
    const double s = k.norm();
    if (!(s > 1e-15)) return to.z() > 0.0 ? Mat3::Identity() : Mat3(Vec3(1.0, -1.0, -1.0).asDiagonal());
    return so3::rotation_from_axis_angle(k / s, std::atan2(s, to.z()));
  }
  return Mat3::Identity();
}

}  // namespace

Mat3 mjcf_orientation(const XmlSource& xml, const XMLElement& e, const MjcfCompiler& c,
                      const MjcfNumbers& numbers) {
  const Mat3 R = orientation_as_written(xml, e, c, numbers);
  if (!R.allFinite()) {
    throw InvalidInput(
        fmt::format("{}: its orientation is not a finite rotation; expected finite numbers (angles "
                    "of moderate size) in quat, axisangle, euler, xyaxes or zaxis",
                    xml.where(e)));
  }
  return R;
}

Mat3 mjcf_orientation(const XmlSource& xml, const XMLElement& e, const MjcfCompiler& compiler) {
  return mjcf_orientation(xml, e, compiler, [&](const char* name, std::size_t count) {
    return xml.numbers_attribute(e, name, count);
  });
}

}  // namespace poinsot::io::detail
