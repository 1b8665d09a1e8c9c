#include "poinsot/core/text_file.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <system_error>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot {

std::size_t default_max_file_bytes() {
  constexpr std::size_t kDefault = std::size_t{64} << 20;
  const char* env = std::getenv("POINSOT_MAX_FILE_BYTES");
  if (env == nullptr || *env == '\0') return kDefault;
  char* end = nullptr;
  const unsigned long long v = std::strtoull(env, &end, 10);
  return (end != nullptr && *end == '\0' && v > 0) ? static_cast<std::size_t>(v) : kDefault;
}

std::string read_file_limited(const std::string& path, std::string_view what, std::size_t max_bytes,
                              std::string_view raise_with) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InvalidInput(fmt::format("{}: \"{}\" is a folder; expected a file", what, path));
  if (std::filesystem::exists(path, ec) && !std::filesystem::is_regular_file(path, ec))
    throw InvalidInput(fmt::format("{}: \"{}\" is not a regular file; expected a file", what, path));
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw InvalidInput(fmt::format("{}: cannot read \"{}\": {}; expected a readable file", what, path,
                                   std::strerror(errno)));
  }
  const auto size = std::filesystem::file_size(path, ec);
  if (!ec && size > max_bytes) {
    throw InvalidInput(fmt::format("{}: \"{}\" is {} bytes; the limit is {} bytes (raise it with {})", what,
                                   path, size, max_bytes, raise_with));
  }
  std::string text;
  char buffer[65536];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) {
      throw InvalidInput(fmt::format("{}: \"{}\" is over {} bytes, the limit (raise it with {})", what, path,
                                     max_bytes, raise_with));
    }
  }
  return text;
}

}  // namespace poinsot
