// A text file written in whole lines (see line_file.hpp).
#include "poinsot/io/run/line_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::io {
namespace {
constexpr std::size_t kFlushBytes = 64 * 1024;
constexpr auto kFlushInterval = std::chrono::milliseconds(250);
}  // namespace

LineFile::LineFile(const std::string& path) : path_(path), last_flush_(std::chrono::steady_clock::now()) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) {
    throw InvalidInput(fmt::format("output: cannot create \"{}\": {}; expected a writable folder", path,
                                   std::strerror(errno)));
  }
}

LineFile::~LineFile() {
  try {
    flush();
  } catch (const std::exception&) {  // nothing more can be done in a destructor
  }
  if (fd_ >= 0) ::close(fd_);
}

void LineFile::line_done() {
  ++lines_;
  if (buffer_.size() >= kFlushBytes || std::chrono::steady_clock::now() - last_flush_ >= kFlushInterval) {
    flush();
  }
}

void LineFile::flush() {
  const char* p = buffer_.data();
  std::size_t left = buffer_.size();
  while (left > 0) {
    const ssize_t n = ::write(fd_, p, left);
    if (n < 0) {
      if (errno == EINTR) continue;  // a signal arrived (Ctrl-C): finish the lines
      throw ComputationFailed(fmt::format("output: writing \"{}\" failed: {}", path_, std::strerror(errno)));
    }
    p += n;
    left -= static_cast<std::size_t>(n);
  }
  buffer_.clear();
  last_flush_ = std::chrono::steady_clock::now();
}

}  // namespace poinsot::io
