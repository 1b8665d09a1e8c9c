#pragma once
/// @file error.hpp
/// The exceptions poinsot throws. Every message is one line that names the quantity, the value received and
/// what was expected, for example
/// `inertia: principal moments (1, 1, 5) kg·m² violate the triangle inequality I1 + I2 >= I3 (short by 3)`.
/// The command-line tool prints that line and exits with status 2; the Python module raises ValueError.

#include <stdexcept>
#include <string>

namespace poinsot {

/// Base class of every exception poinsot throws on purpose. The message is kept on one line: a line break in
/// it (from quoted input, such as a TOML string written over several lines) becomes a space.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(on_one_line(message)) {}

 private:
  static std::string on_one_line(std::string message) {
    for (char& c : message)
      if (c == '\n' || c == '\r') c = ' ';
    return message;
  }
};

/// Bad input: a value out of its domain, a malformed file, an inconsistent model. Nothing was computed.
class InvalidInput : public Error {
 public:
  using Error::Error;
};

/// A computation that started from valid input but could not finish: a non-finite state, a step that cannot
/// meet its tolerance, a Newton iteration that does not converge. The message says when and where.
class ComputationFailed : public Error {
 public:
  using Error::Error;
};

}  // namespace poinsot
