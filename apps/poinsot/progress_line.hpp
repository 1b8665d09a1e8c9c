#pragma once
// One progress line on stderr for the sub-commands that run for long (run, optimize): drawn only when stderr
// is a terminal (never into a pipe or a file), from the first second on, redrawn at most ten times a second
// unless the caller forces it (a new phase), and erased when the work ends.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>

namespace poinsot::cli {

class ProgressLine {
 public:
  /// `enabled`: the caller's wish (false with --quiet or --json); the line is drawn only on a terminal.
  explicit ProgressLine(bool enabled) : enabled_(enabled && isatty(STDERR_FILENO) == 1) {}
  ~ProgressLine() { finish(); }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  /// True when the line should be redrawn now (and marks it drawn at this time): drawing enabled, a second
  /// since the start, and 100 ms since the last draw unless `force`.
  bool due(bool force = false) {
    if (!enabled_) return false;
    const auto now = std::chrono::steady_clock::now();
    if (elapsed() < 1.0 || (!force && now - last_ < std::chrono::milliseconds(100))) return false;
    last_ = now;
    return true;
  }
  /// Seconds since the line was made.
  double elapsed() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }
  /// Replaces the line's text (and clears what a longer previous text left after it).
  void draw(const std::string& text) {
    fmt::print(stderr, "\r{}\033[K", text);
    std::fflush(stderr);
    drawn_ = true;
  }
  /// Erases the line, if drawn.
  void finish() {
    if (drawn_) fmt::print(stderr, "\r\033[K");
    drawn_ = false;
  }

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
  std::chrono::steady_clock::time_point last_ = start_;
};

}  // namespace poinsot::cli
