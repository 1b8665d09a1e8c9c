#include "xml_source.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <system_error>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"

namespace poinsot::io::detail {

std::size_t skip_non_element(std::string_view text, std::size_t i) {
  const auto past = [&](std::size_t from, std::string_view close) {
    const std::size_t k = text.find(close, from);
    return k == std::string_view::npos ? text.size() : k + close.size();
  };
  const std::string_view rest = text.substr(i);
  if (rest.starts_with("<!--")) return past(i + 4, "-->");
  if (rest.starts_with("<![CDATA[")) return past(i + 9, "]]>");
  if (rest.starts_with("<?")) return past(i + 2, "?>");
  if (rest.starts_with("<!") || rest.starts_with("</")) return past(i, ">");
  return i;
}

std::size_t start_tag_end(std::string_view text, std::size_t i) {
  char quote = 0;
  for (++i; i < text.size(); ++i) {
    const char c = text[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      return i + 1;
    }
  }
  return text.size();
}

namespace {

bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\n' || c == '\r';
}

/// Offsets of the start tags of `text` in document order (see the header comment); end of text on a
/// construct that is not closed (tinyxml2 has rejected such a document before this is called).
std::vector<std::size_t> start_tags(std::string_view text) {
  std::vector<std::size_t> starts;
  std::size_t i = 0;
  while ((i = text.find('<', i)) != std::string_view::npos) {
    if (const std::size_t after = skip_non_element(text, i); after != i) {
      i = after;
      continue;
    }
    starts.push_back(i);
    i = start_tag_end(text, i);
  }
  return starts;
}

void collect(const tinyxml2::XMLElement* e, std::vector<const tinyxml2::XMLElement*>& out) {
  // Iterative pre-order (tinyxml2 limits the depth, but recursion is avoided anyway).
  std::vector<const tinyxml2::XMLElement*> stack{e};
  while (!stack.empty()) {
    const tinyxml2::XMLElement* x = stack.back();
    stack.pop_back();
    out.push_back(x);
    std::vector<const tinyxml2::XMLElement*> children;
    for (const auto* c = x->FirstChildElement(); c != nullptr; c = c->NextSiblingElement())
      children.push_back(c);
    for (auto it = children.rbegin(); it != children.rend(); ++it)
      stack.push_back(*it);
  }
}

}  // namespace

std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

std::optional<std::vector<double>> parse_numbers(std::string_view text) {
  std::vector<double> values;
  std::size_t i = 0;
  while (true) {
    while (i < text.size() && is_space(text[i]))
      ++i;
    if (i == text.size()) break;
    std::size_t j = i;
    while (j < text.size() && !is_space(text[j]))
      ++j;
    std::string_view token = text.substr(i, j - i);
    if (token.starts_with('+')) token.remove_prefix(1);  // from_chars does not take a leading '+'
    double x = 0.0;
    const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), x);
    if (ec != std::errc() || end != token.data() + token.size() || !std::isfinite(x)) return std::nullopt;
    values.push_back(x);
    i = j;
  }
  return values;
}

XmlSource::XmlSource(std::string text, std::string source)
    : XmlSource(std::move(text), SourceLines{{std::move(source)}, {}}) {}

XmlSource::XmlSource(std::string text, SourceLines lines) : text_(std::move(text)), lines_(std::move(lines)) {
  if (lines_.files.empty()) lines_.files = {"<string>"};
  const std::string& source = lines_.files.at(0);
  if (doc_.Parse(text_.data(), text_.size()) != tinyxml2::XML_SUCCESS) {
    const char* reason = doc_.ErrorStr();
    throw InvalidInput(fmt::format("{}: XML error: {}; expected a well-formed XML document",
                                   lines_.location(doc_.ErrorLineNum()),
                                   one_line(reason != nullptr ? reason : "unknown")));
  }
  if (doc_.RootElement() == nullptr)
    throw InvalidInput(fmt::format("{}: no XML element; expected a robot model", source));
  // Every top-level element (XML allows one, tinyxml2 accepts several).
  std::vector<const tinyxml2::XMLElement*> all;
  for (const auto* top = doc_.FirstChildElement(); top != nullptr; top = top->NextSiblingElement())
    collect(top, all);
  const std::vector<std::size_t> starts = start_tags(text_);
  if (starts.size() != all.size()) {
    throw InvalidInput(
        fmt::format("{}: cannot locate the XML elements in the text ({} start tags, {} elements)", source,
                    starts.size(), all.size()));
  }
  for (std::size_t k = 0; k < all.size(); ++k) {
    const std::string_view name = all[k]->Name();
    if (text_.compare(starts[k] + 1, name.size(), name) != 0) {
      throw InvalidInput(fmt::format("{}: cannot locate the XML element <{}> in the text",
                                     lines_.location(all[k]->GetLineNum()), name));
    }
    start_.emplace(all[k], starts[k]);
  }
}

std::string XmlSource::where(const tinyxml2::XMLElement& e) const {
  return fmt::format("{}: <{}>", lines_.location(e.GetLineNum()), e.Name());
}

std::size_t XmlSource::start_of(const tinyxml2::XMLElement& e) const {
  return start_.at(&e);
}

std::optional<TextSpan> XmlSource::attribute_span(const tinyxml2::XMLElement& e,
                                                  std::string_view name) const {
  std::size_t i = start_of(e) + 1 + std::string_view(e.Name()).size();
  const std::size_t n = text_.size();
  while (i < n) {
    while (i < n && is_space(text_[i]))
      ++i;
    if (i >= n || text_[i] == '>' || text_[i] == '/') return std::nullopt;
    const std::size_t name_begin = i;
    while (i < n && text_[i] != '=' && !is_space(text_[i]) && text_[i] != '>')
      ++i;
    const std::string_view attr(text_.data() + name_begin, i - name_begin);
    while (i < n && is_space(text_[i]))
      ++i;
    if (i >= n || text_[i] != '=') return std::nullopt;
    ++i;
    while (i < n && is_space(text_[i]))
      ++i;
    if (i >= n || (text_[i] != '"' && text_[i] != '\'')) return std::nullopt;
    const char quote = text_[i++];
    const std::size_t value_begin = i;
    while (i < n && text_[i] != quote)
      ++i;
    if (i >= n) return std::nullopt;
    if (attr == name) return TextSpan{value_begin, i};
    ++i;
  }
  return std::nullopt;
}

std::optional<TextSpan> XmlSource::text_span(const tinyxml2::XMLElement& e) const {
  std::size_t i = start_of(e);
  char quote = 0;
  for (++i; i < text_.size(); ++i) {
    const char c = text_[i];
    if (quote != 0) {
      if (c == quote) quote = 0;
    } else if (c == '"' || c == '\'') {
      quote = c;
    } else if (c == '>') {
      break;
    }
  }
  if (i >= text_.size() || text_[i - 1] == '/') return std::nullopt;  // self-closing: no content
  std::size_t begin = i + 1;
  std::size_t end = text_.find('<', begin);
  if (end == std::string::npos || text_.compare(end, 2, "</") != 0) return std::nullopt;
  while (begin < end && is_space(text_[begin]))
    ++begin;
  while (end > begin && is_space(text_[end - 1]))
    --end;
  if (begin == end || text_.find('&', begin) < end) return std::nullopt;
  return TextSpan{begin, end};
}

std::optional<std::vector<double>> XmlSource::numbers_attribute(const tinyxml2::XMLElement& e,
                                                                const char* attribute,
                                                                std::size_t count) const {
  const char* value = e.Attribute(attribute);
  if (value == nullptr) return std::nullopt;
  auto numbers = parse_numbers(value);
  if (!numbers || numbers->size() != count) {
    throw InvalidInput(fmt::format("{} {}=\"{}\": expected {} finite number{}", where(e), attribute,
                                   one_line(value), count, count == 1 ? "" : "s"));
  }
  return numbers;
}

std::vector<double> XmlSource::numbers_text(const tinyxml2::XMLElement& e, std::size_t count) const {
  const char* value = e.GetText();
  auto numbers = parse_numbers(value != nullptr ? value : "");
  if (!numbers || numbers->size() != count) {
    throw InvalidInput(fmt::format("{} \"{}\": expected {} finite number{}", where(e),
                                   one_line(value != nullptr ? value : ""), count, count == 1 ? "" : "s"));
  }
  return *numbers;
}

}  // namespace poinsot::io::detail
