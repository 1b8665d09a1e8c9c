#pragma once
/// @file line_file.hpp
/// A text file written in whole lines, streamed: the trajectories and diagnostics of every run go through it.
///
/// Robustness: only whole lines are ever handed to the file (lines are gathered in memory and written in one
/// system call of complete lines, at least every 0.25 s and whenever 64 KiB have gathered), so a run killed
/// at any moment leaves a file complete up to its last full line; flush() writes out every line. Memory stays
/// constant whatever the number of lines.

#include <chrono>
#include <string>

namespace poinsot::io {

class LineFile {
 public:
  /// Creates (or truncates) `path`. Throws InvalidInput naming the file and the system's reason if it cannot.
  explicit LineFile(const std::string& path);
  ~LineFile();  ///< flushes (errors ignored) and closes
  LineFile(const LineFile&) = delete;
  LineFile& operator=(const LineFile&) = delete;

  /// The buffer to append complete lines to (each ending in '\n'); call line_done() after each.
  std::string& buffer() { return buffer_; }
  /// Counts one line appended to buffer() and hands the gathered lines to the system when due.
  void line_done();
  /// Hands every gathered line to the operating system. Throws ComputationFailed on a write error.
  void flush();
  /// Lines counted by line_done() so far.
  long long lines() const { return lines_; }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int fd_ = -1;
  std::string buffer_;
  long long lines_ = 0;
  std::chrono::steady_clock::time_point last_flush_;
};

}  // namespace poinsot::io
