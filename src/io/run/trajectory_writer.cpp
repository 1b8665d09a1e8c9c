// Streamed CSV trajectory (see trajectory_writer.hpp).
#include "poinsot/io/run/trajectory_writer.hpp"

#include <iterator>

#include <fmt/format.h>

namespace poinsot::io {

const std::vector<std::string>& TrajectoryCsvWriter::columns() {
  static const std::vector<std::string> names = {
      "t",      "qw",        "qx",        "qy",        "qz",       "wx",       "wy",      "wz",
      "energy", "L_space_x", "L_space_y", "L_space_z", "L_body_x", "L_body_y", "L_body_z"};
  return names;
}

TrajectoryCsvWriter::TrajectoryCsvWriter(const std::string& path, const dynamics::RigidBody& body,
                                         const Vec3& gravity_space)
    : file_(path), body_(body), gravity_space_(gravity_space) {
  std::string& buffer = file_.buffer();
  buffer =
      "# poinsot trajectory. Units: t s; qw qx qy qz 1 (unit quaternion of R, body to space, w >= 0); "
      "wx wy wz rad/s (omega, body frame); energy J (T + V); L_space_* kg·m²/s (R J omega, space frame); "
      "L_body_* kg·m²/s (J omega, body frame)\n";
  const auto& names = columns();
  for (std::size_t i = 0; i < names.size(); ++i) {
    buffer += names[i];
    buffer += i + 1 < names.size() ? ',' : '\n';
  }
  file_.flush();
}

void TrajectoryCsvWriter::write(const dynamics::State& s) {
  const Quat q = s.quaternion();
  const Vec3 Lb = dynamics::angular_momentum_body(body_, s);
  const Vec3 Ls = s.R_space_body * Lb;
  const double E = dynamics::total_energy(body_, s, gravity_space_);
  auto out = std::back_inserter(file_.buffer());
  fmt::format_to(out, "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", s.time, q.w(), q.x(), q.y(), q.z(),
                 s.omega_body.x(), s.omega_body.y(), s.omega_body.z(), E, Ls.x(), Ls.y(), Ls.z(), Lb.x(),
                 Lb.y(), Lb.z());
  file_.line_done();
}

}  // namespace poinsot::io
