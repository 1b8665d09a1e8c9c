#pragma once
// Shared by the fuzz harnesses (fuzz/fuzz_*.cpp). A harness feeds its input to one reader and accepts only
// two outcomes: success, or a poinsot::Error whose message is one line. Anything else — another exception,
// a message with a line break, a sanitizer report, a crash, a hang — is a finding: the process aborts so
// that libFuzzer (or the replay driver of replay_main.cpp) reports it.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "poinsot/core/error.hpp"

namespace poinsot::fuzz {

[[noreturn]] inline void finding(const char* what, const std::string& detail) {
  std::fprintf(stderr, "fuzz finding: %s: %s\n", what, detail.c_str());
  std::abort();
}

/// Runs `f`; a poinsot::Error must be one line, every other exception is a finding.
template <class F>
void expect_clean(F&& f) {
  try {
    f();
  } catch (const poinsot::Error& e) {
    const std::string_view m = e.what();
    if (m.empty() || m.find('\n') != std::string_view::npos || m.find('\r') != std::string_view::npos)
      finding("error message is not one line", std::string(m));
  } catch (const std::exception& e) {
    finding("unexpected exception", e.what());
  }
}

/// The files input_file wrote in this process, removed when it exits.
struct InputFiles {
  std::vector<std::string> paths;
  InputFiles() = default;
  InputFiles(const InputFiles&) = delete;
  InputFiles& operator=(const InputFiles&) = delete;
  ~InputFiles() {
    for (const auto& p : paths)
      std::remove(p.c_str());
  }
};

/// The input written to a file of this process with extension `ext` (the mesh reader takes a path and picks
/// the format by extension); the same path each call for one extension, removed when the process exits.
inline std::string input_file(const std::uint8_t* data, std::size_t size, const char* ext) {
  static InputFiles written;
  const std::string path = "/tmp/poinsot_fuzz_" + std::to_string(::getpid()) + ext;
  if (std::find(written.paths.begin(), written.paths.end(), path) == written.paths.end())
    written.paths.push_back(path);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));  // NOLINT: bytes
  return path;
}

/// A folder that does not exist, as the base folder of relative paths in fuzzed files (absolute paths in the
/// input still reach the file system; the readers refuse what is not a regular file).
inline constexpr const char* kNoDir = "/nonexistent/poinsot-fuzz";

}  // namespace poinsot::fuzz
