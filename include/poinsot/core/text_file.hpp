#pragma once
/// @file text_file.hpp
/// Reading a whole input file (scenario, body file, robot model) with a size limit checked before the
/// content is read, so that no input makes poinsot allocate without bound. Devices and pipes (/dev/zero, a
/// FIFO) are refused: they could be read without end.
#include <cstddef>
#include <string>
#include <string_view>

namespace poinsot {

/// Default size limit of an input file: 64 MiB, or the environment variable POINSOT_MAX_FILE_BYTES when it
/// is set to a positive integer.
std::size_t default_max_file_bytes();

/// The content of the regular file `path`, at most `max_bytes` bytes. Throws InvalidInput (one line, prefixed
/// by `what`) when it is a folder, not a regular file, cannot be read, or is larger than the limit (the
/// message names the limit and `raise_with`, the option or variable that raises it).
std::string read_file_limited(
    const std::string& path, std::string_view what, std::size_t max_bytes,
    std::string_view raise_with = "the environment variable POINSOT_MAX_FILE_BYTES");

}  // namespace poinsot
