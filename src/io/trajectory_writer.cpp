// Streamed CSV trajectory (see trajectory_writer.hpp).
#include "poinsot/io/trajectory_writer.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iterator>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::io {
namespace {
constexpr std::size_t kFlushBytes = 64 * 1024;
constexpr auto kFlushInterval = std::chrono::milliseconds(250);
}  // namespace

const std::vector<std::string>& TrajectoryCsvWriter::columns() {
  static const std::vector<std::string> names = {
      "t",      "qw",        "qx",        "qy",        "qz",       "wx",       "wy",      "wz",
      "energy", "L_space_x", "L_space_y", "L_space_z", "L_body_x", "L_body_y", "L_body_z"};
  return names;
}

TrajectoryCsvWriter::TrajectoryCsvWriter(const std::string& path, const dynamics::RigidBody& body,
                                         const Vec3& gravity_space)
    : path_(path), body_(body), gravity_space_(gravity_space) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InvalidInput(fmt::format("output: cannot create \"{}\": {}; expected a writable folder", path,
                                   std::strerror(errno)));
  }
  buffer_ =
      "# poinsot trajectory. Units: t s; qw qx qy qz 1 (unit quaternion of R, body to space, w >= 0); "
      "wx wy wz rad/s (omega, body frame); energy J (T + V); L_space_* kg·m²/s (R J omega, space frame); "
      "L_body_* kg·m²/s (J omega, body frame)\n";
  const auto& names = columns();
  for (std::size_t i = 0; i < names.size(); ++i) {
    buffer_ += names[i];
    buffer_ += i + 1 < names.size() ? ',' : '\n';
  }
  flush();
}

TrajectoryCsvWriter::~TrajectoryCsvWriter() {
  try {
    flush();
  } catch (const std::exception&) {  // nothing more can be done in a destructor
  }
  if (fd_ >= 0) ::close(fd_);
}

void TrajectoryCsvWriter::write(const dynamics::State& s) {
  const Quat q = s.quaternion();
  const Vec3 Lb = dynamics::angular_momentum_body(body_, s);
  const Vec3 Ls = s.R * Lb;
  const double E = dynamics::total_energy(body_, s, gravity_space_);
  auto out = std::back_inserter(buffer_);
  fmt::format_to(out, "{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", s.t, q.w(), q.x(), q.y(), q.z(),
                 s.omega_body.x(), s.omega_body.y(), s.omega_body.z(), E, Ls.x(), Ls.y(), Ls.z(), Lb.x(),
                 Lb.y(), Lb.z());
  ++rows_;
  if (buffer_.size() >= kFlushBytes || std::chrono::steady_clock::now() - last_flush_ >= kFlushInterval) {
    flush();
  }
}

void TrajectoryCsvWriter::flush() {
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;  // a signal arrived (Ctrl-C): finish the rows
      throw ComputationFailed(fmt::format("output: writing \"{}\" failed: {}", path_, std::strerror(errno)));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  buffer_.clear();
  last_flush_ = std::chrono::steady_clock::now();
}

}  // namespace poinsot::io
