#pragma once
// Internal to the io layer: an MJCF text with its <include file="F"/> elements replaced by the children of
// F's top-level element, as MuJoCo reads it (F relative to the main file's folder, each file at most once,
// includes nested), and the origin of every line of the result (robot_model.hpp, SourceLines).
#include <cstddef>
#include <string>

#include "poinsot/io/robot/robot_model.hpp"

namespace poinsot::io::detail {

struct ExpandedText {
  std::string text;
  SourceLines lines;
};

/// `text` (named `source` in messages) with its <include> elements replaced, recursively. Throws InvalidInput
/// `FILE:LINE: <include file="F">: ...` for an element without `file`, with content, or whose file cannot be
/// read, is larger than `max_bytes`, is not well-formed XML or was included already.
ExpandedText expand_mjcf_includes(const std::string& text, const std::string& source,
                                  const std::string& base_dir, std::size_t max_bytes);

}  // namespace poinsot::io::detail
