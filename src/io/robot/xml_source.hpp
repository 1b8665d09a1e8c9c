#pragma once
// Internal to the io layer: an XML document parsed by tinyxml2 together with the byte offsets of its
// elements in the source text, so that a value can be located (for messages) and replaced in place (for
// `poinsot inertia check --repair`) without re-serialising the document.
//
// tinyxml2 does not record offsets. They come from a scan of the text that recognises what tinyxml2
// recognises — comments `<!-- -->`, CDATA `<![CDATA[ ]]>`, declarations `<? ?>`, other `<! >` nodes, end
// tags, and start tags whose attribute values are quoted with ' or " — and lists the start tags in document
// order, which is the pre-order of tinyxml2's element tree. The two are matched element by element (names
// compared); a mismatch is reported, never guessed.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include <tinyxml2.h>

#include "poinsot/core/types.hpp"
#include "poinsot/io/robot/robot_model.hpp"

namespace poinsot::io::detail {

/// Half-open byte range [begin, end) of the source text.
struct TextSpan {
  std::size_t begin = 0;
  std::size_t end = 0;
};

class XmlSource {
 public:
  /// Parses `text` (named `source` in messages). Throws InvalidInput `SOURCE:LINE: XML error: ...` for
  /// malformed XML (tinyxml2's reason) and when the element offsets cannot be matched.
  XmlSource(std::string text, std::string source);
  /// The same for a text whose lines come from the files of `lines` (an MJCF text with its <include>
  /// elements replaced): messages name each element's own file and line.
  XmlSource(std::string text, SourceLines lines);
  XmlSource(const XmlSource&) = delete;
  XmlSource& operator=(const XmlSource&) = delete;

  const std::string& text() const { return text_; }
  const std::string& source() const { return lines_.files[0]; }
  const SourceLines& lines() const { return lines_; }
  const tinyxml2::XMLElement* root() const { return doc_.RootElement(); }

  /// "SOURCE:LINE: <name>" for messages (the element's own file and line).
  std::string where(const tinyxml2::XMLElement& e) const;
  /// "line N" for an element of the model's own file, "line N of FILE" for one of an included file.
  std::string line_label(const tinyxml2::XMLElement& e) const { return lines_.label(e.GetLineNum()); }

  /// The value of attribute `name` of `e` (between its quotes), or nothing when `e` has no such attribute.
  std::optional<TextSpan> attribute_span(const tinyxml2::XMLElement& e, std::string_view name) const;
  /// The text content of `e` (between `>` and the next `<`), trimmed of white space; nothing when `e` is
  /// empty or its content is not a single plain text (a comment or CDATA inside, entities).
  std::optional<TextSpan> text_span(const tinyxml2::XMLElement& e) const;

  /// A number or a list of numbers from attribute `attribute` of `e`, exactly `count` of them, finite.
  /// Throws InvalidInput `SOURCE:LINE: <e> attribute="VALUE": expected N finite numbers` otherwise. Absent:
  /// nothing.
  std::optional<std::vector<double>> numbers_attribute(const tinyxml2::XMLElement& e, const char* attribute,
                                                       std::size_t count) const;
  /// The same for the text content of `e`.
  std::vector<double> numbers_text(const tinyxml2::XMLElement& e, std::size_t count) const;

 private:
  std::size_t start_of(const tinyxml2::XMLElement& e) const;
  std::string text_;
  SourceLines lines_;
  tinyxml2::XMLDocument doc_;
  std::unordered_map<const tinyxml2::XMLElement*, std::size_t> start_;  // offset of the element's '<'
};

/// The position after the comment, CDATA section, processing instruction, declaration or end tag that starts
/// at text[i] = '<'; i itself when a start tag starts there. The end of the text for one that is not closed.
std::size_t skip_non_element(std::string_view text, std::size_t i);
/// One past the '>' of the start tag at text[i] = '<' (the first '>' outside quoted attribute values); the
/// end of the text when there is none.
std::size_t start_tag_end(std::string_view text, std::size_t i);

/// `s` on one line (line breaks as spaces) and at most 80 characters, for messages.
std::string one_line(std::string s);

/// Parses white-space separated numbers (C locale, strtod syntax without hex); nothing when a token is not a
/// finite number.
std::optional<std::vector<double>> parse_numbers(std::string_view text);

}  // namespace poinsot::io::detail
