#include "poinsot/core/format.hpp"

#include <fmt/format.h>

namespace poinsot {

std::string format_number(double value) {
  return fmt::format("{}", value);
}

std::string format_number(double value, int digits) {
  return fmt::format("{:.{}g}", value, digits);
}

std::string format_vector(const Vec3& v) {
  return fmt::format("({}, {}, {})", v.x(), v.y(), v.z());
}

std::string format_matrix(const Mat3& m) {
  return fmt::format("[[{}, {}, {}], [{}, {}, {}], [{}, {}, {}]]", m(0, 0), m(0, 1), m(0, 2), m(1, 0),
                     m(1, 1), m(1, 2), m(2, 0), m(2, 1), m(2, 2));
}

std::string format_quaternion(const Quat& q) {
  return fmt::format("({}, {}, {}, {})", q.w(), q.x(), q.y(), q.z());
}

}  // namespace poinsot
