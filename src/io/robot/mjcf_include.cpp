// MJCF <include> elements replaced by the files they name (mjcf_include.hpp).
#include "mjcf_include.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>

#include <fmt/format.h>
#include <tinyxml2.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/text_file.hpp"
#include "xml_source.hpp"

namespace poinsot::io::detail {
namespace {

constexpr std::size_t npos = std::string::npos;

int line_at(const std::string& t, std::size_t i) {
  return 1 + static_cast<int>(std::count(t.begin(), t.begin() + static_cast<std::ptrdiff_t>(i), '\n'));
}

/// The value of attribute `name` in the start tag `tag`, or nothing.
std::optional<std::string> attribute(std::string_view tag, std::string_view name) {
  std::size_t i = tag.find_first_of(" \t\r\n");
  while (i != std::string_view::npos && i < tag.size()) {
    while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i])) != 0)
      ++i;
    const std::size_t name_begin = i;
    while (i < tag.size() && tag[i] != '=' && std::isspace(static_cast<unsigned char>(tag[i])) == 0 &&
           tag[i] != '>' && tag[i] != '/')
      ++i;
    const std::string_view attr = tag.substr(name_begin, i - name_begin);
    while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i])) != 0)
      ++i;
    if (i >= tag.size() || tag[i] != '=') return std::nullopt;
    ++i;
    while (i < tag.size() && std::isspace(static_cast<unsigned char>(tag[i])) != 0)
      ++i;
    if (i >= tag.size() || (tag[i] != '"' && tag[i] != '\'')) return std::nullopt;
    const char quote = tag[i];
    const std::size_t value_end = tag.find(quote, i + 1);
    if (value_end == std::string_view::npos) return std::nullopt;
    if (attr == name) return std::string(tag.substr(i + 1, value_end - i - 1));
    i = value_end + 1;
  }
  return std::nullopt;
}

/// The text being built and the origin of each of its lines.
struct Expansion {
  std::string base_dir;
  std::size_t max_bytes = 0;
  std::set<std::string> included;  // the files read, as normal absolute paths
  ExpandedText out;

  /// Appends `piece`, whose first character is on line `first_line` of file `file`.
  void append(std::string_view piece, int file, int first_line) {
    if (piece.empty()) return;
    if (out.text.empty() || out.text.back() == '\n') out.lines.origin.back() = {file, first_line};
    int line = first_line;
    for (const char c : piece) {
      out.text.push_back(c);
      if (c == '\n') out.lines.origin.emplace_back(file, ++line);
    }
  }

  /// Appends `t` (lines from `first_line` of file `file`) with its <include> elements replaced.
  void expand(const std::string& t, int file, int first_line) {
    std::size_t copied = 0;
    std::size_t pos = 0;
    const auto where = [&](std::size_t i) {
      return out.lines.files[static_cast<std::size_t>(file)] + ":" +
             std::to_string(first_line + line_at(t, i) - 1);
    };
    while ((pos = t.find('<', pos)) != npos) {
      if (const std::size_t after = skip_non_element(t, pos); after != pos) {
        pos = after;
        continue;
      }
      const bool include = t.compare(pos, 8, "<include") == 0 && pos + 8 < t.size() &&
                           (std::isspace(static_cast<unsigned char>(t[pos + 8])) != 0 || t[pos + 8] == '/' ||
                            t[pos + 8] == '>');
      if (!include) {
        ++pos;
        continue;
      }
      // tinyxml2 has parsed this text: its tags are closed.
      const std::size_t start_end = start_tag_end(t, pos);
      const std::string_view tag(t.data() + pos, start_end - pos);
      const std::optional<std::string> name = attribute(tag, "file");
      const std::string element =
          name ? fmt::format("<include file=\"{}\">", *name) : std::string("<include>");
      if (!name || name->empty()) {
        throw InvalidInput(fmt::format(
            "{}: {}: no file; expected file=\"PATH\", relative to the model's folder", where(pos), element));
      }
      std::size_t end = start_end;
      if (!tag.ends_with("/>")) {
        const std::size_t close = t.find("</include", start_end);
        const bool empty =
            close != npos && std::all_of(t.begin() + static_cast<std::ptrdiff_t>(start_end),
                                         t.begin() + static_cast<std::ptrdiff_t>(close), [](char c) {
                                           return std::isspace(static_cast<unsigned char>(c)) != 0;
                                         });
        if (!empty)
          throw InvalidInput(
              fmt::format("{}: {}: has content; expected an empty element", where(pos), element));
        end = start_tag_end(t, close);
      }
      append(std::string_view(t).substr(copied, pos - copied), file, first_line + line_at(t, copied) - 1);
      include_file(*name, where(pos) + ": " + element);
      copied = pos = end;
    }
    append(std::string_view(t).substr(copied), file, first_line + line_at(t, copied) - 1);
  }

  /// Appends the children of the top-level element of `name` (relative to the main file's folder).
  void include_file(const std::string& name, const std::string& element) {
    const std::filesystem::path p = std::filesystem::path(name).is_absolute()
                                        ? std::filesystem::path(name)
                                        : std::filesystem::path(base_dir) / name;
    const std::string key = std::filesystem::absolute(p).lexically_normal().string();
    if (!included.insert(key).second)
      throw InvalidInput(
          fmt::format("{}: {} is included already; expected each file once", element, p.string()));
    std::string text;
    try {
      text = read_file_limited(p.string(), "included model", max_bytes, "--max-file-bytes");
    } catch (const InvalidInput& e) {
      throw InvalidInput(fmt::format("{}: {}", element, e.what()));
    }
    tinyxml2::XMLDocument doc;
    if (doc.Parse(text.data(), text.size()) != tinyxml2::XML_SUCCESS || doc.RootElement() == nullptr) {
      const char* reason = doc.ErrorStr();
      throw InvalidInput(fmt::format("{}: {}:{}: XML error: {}; expected a well-formed XML document", element,
                                     p.string(), doc.ErrorLineNum(),
                                     one_line(reason != nullptr ? reason : "no element")));
    }
    // The top-level element's content: from the end of its start tag to its end tag.
    std::size_t root = 0;
    while ((root = text.find('<', root)) != npos) {
      const std::size_t after = skip_non_element(text, root);
      if (after == root) break;
      root = after;
    }
    if (root == npos) return;
    const std::size_t open_end = start_tag_end(text, root);
    if (text[open_end - 2] == '/') return;  // an empty top-level element: nothing to include
    const std::size_t close = text.rfind(std::string("</") + doc.RootElement()->Name());
    if (close == npos || close < open_end) return;
    out.lines.files.push_back(p.string());
    const int file = static_cast<int>(out.lines.files.size()) - 1;
    expand(text.substr(open_end, close - open_end), file, line_at(text, open_end));
  }
};

}  // namespace

ExpandedText expand_mjcf_includes(const std::string& text, const std::string& source,
                                  const std::string& base_dir, std::size_t max_bytes) {
  Expansion e;
  e.base_dir = base_dir;
  e.max_bytes = max_bytes;
  e.out.lines.files = {source};
  e.out.lines.origin = {{0, 1}};
  e.expand(text, 0, 1);
  return std::move(e.out);
}

}  // namespace poinsot::io::detail
