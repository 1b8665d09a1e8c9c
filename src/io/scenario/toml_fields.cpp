// Typed, located access to the keys of a TOML table (see toml_fields.hpp).
#include "toml_fields.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <utility>

#include <fmt/format.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/format.hpp"
#include "poinsot/core/text_file.hpp"
#include "poinsot/io/robot/robot_system.hpp"

namespace poinsot::io::detail {

toml::table parse_toml(std::string_view text, std::string_view source) {
  try {
    return toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    const auto& where = e.source().begin;
    // toml++ may quote text over several lines: Error keeps the message on one line.
    throw InvalidInput(fmt::format("{}:{}:{}: TOML syntax error: {}", source, where.line, where.column,
                                   std::string(e.description())));
  }
}

std::string read_text_file(const std::string& path) {
  return read_file_limited(path, "scenario", default_max_file_bytes());
}

std::string read_scenario_file(const std::string& path) {
  if (is_robot_file(path)) {
    throw InvalidInput(fmt::format(
        "{}: a robot file (URDF, MJCF or SDF), which `poinsot run {}` simulates as it is; expected a TOML "
        "scenario (one names a robot file with [model] file = \"...\": docs/robot_models.md)",
        path, path));
  }
  return read_text_file(path);
}

std::string location(const Source& source, const toml::node* node) {
  if (node != nullptr) {
    const auto& where = node->source();
    if (where.begin.line > 0)
      return fmt::format("{}:{}:{}: ", source.name, where.begin.line, where.begin.column);
  }
  return fmt::format("{}: ", source.name);
}

std::string join(std::initializer_list<std::string_view> items) {
  std::string out;
  for (const auto& s : items) {
    if (!out.empty()) out += ", ";
    out += s;
  }
  return out;
}

std::string describe(const toml::node& node) {
  if (node.is_string()) return fmt::format("\"{}\"", node.value_or(std::string_view{}));
  if (node.is_integer()) return fmt::format("{}", node.value_or(std::int64_t{0}));
  if (node.is_floating_point()) return format_number(node.value_or(0.0));
  if (node.is_boolean()) return node.value_or(false) ? "true" : "false";
  if (node.is_table()) return "a table";
  if (node.is_array()) {
    const auto& a = *node.as_array();
    std::string out = "[";
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (i > 0) out += ", ";
      out += describe(a[i]);
    }
    return out + "]";
  }
  if (node.is_date()) return "a date";
  if (node.is_time()) return "a time";
  return "a date-time";
}

namespace {

/// The top-level sections that make a scenario file the input of one sub-command: a file given to another
/// sub-command is answered with the one that reads it.
constexpr std::pair<std::string_view, std::string_view> kSectionReaders[] = {
    {"ensemble", "poinsot ensemble"},
    {"optimal_control", "poinsot optimize"},
};

}  // namespace

void require_optimal_control_section(const Source& source, const toml::table& root) {
  if (root.get("optimal_control") != nullptr) return;
  throw InvalidInput(
      fmt::format("{}[top level] optimal_control: missing; expected an [optimal_control] section (a "
                  "scenario without one is simulated by `poinsot run {}`)",
                  location(source, nullptr), source.name));
}

Section::Section(const Source& source, const toml::table* table, std::string name,
                 std::initializer_list<std::string_view> valid, const toml::node* position)
    : source_(source), table_(table), name_(std::move(name)), position_(position ? position : table) {
  if (table_ == nullptr) return;
  for (const auto& [key, value] : *table_) {
    bool known = false;
    for (const auto& v : valid)
      known = known || key.str() == v;
    if (!known) {
      const auto& at = key.source().begin;
      const std::string where = at.line > 0 ? fmt::format("{}:{}:{}: ", source_.name, at.line, at.column)
                                            : location(source_, &value);
      if (name_ == "top level") {
        for (const auto& [section, reader] : kSectionReaders) {
          if (key.str() == section) {
            throw InvalidInput(fmt::format(
                "{}[{}] is read by `{}`, not by this sub-command; expected `{} {}` (or a file without [{}])",
                where, section, reader, reader, source_.name, section));
          }
        }
      }
      throw InvalidInput(
          fmt::format("{}[{}] unknown key \"{}\"; valid keys: {}", where, name_, key.str(), join(valid)));
    }
  }
}

bool Section::has(std::string_view key) const {
  return node(key) != nullptr;
}

const toml::node* Section::node(std::string_view key) const {
  return table_ == nullptr ? nullptr : table_->get(key);
}

std::string Section::label(std::string_view key) const {
  return fmt::format("[{}] {}", name_, key);
}

void Section::fail(std::string_view key, std::string_view message) const {
  const toml::node* n = node(key);
  throw InvalidInput(fmt::format("{}{}: {}", location(source_, n ? n : position_), label(key), message));
}

void Section::require(std::string_view key, std::string_view expected) const {
  if (has(key)) return;
  if (table_ == nullptr) {
    throw InvalidInput(fmt::format("{}[{}] section is missing; expected it with {}",
                                   location(source_, position_), name_, expected));
  }
  fail(key, fmt::format("missing; expected {}", expected));
}

std::optional<double> Section::number(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_number()) fail(key, fmt::format("got {}, expected a number", describe(*n)));
  const double x = n->is_integer() ? static_cast<double>(n->value_or(std::int64_t{0})) : n->value_or(0.0);
  if (!std::isfinite(x)) fail(key, fmt::format("got {}, expected a finite number", format_number(x)));
  return x;
}

std::optional<int> Section::integer(std::string_view key, int lo, int hi) const {
  const auto v = number(key);
  if (!v) return std::nullopt;
  if (!(*v >= lo && *v <= hi && *v == std::floor(*v)))
    fail(key, fmt::format("got {}, expected an integer from {} to {}", format_number(*v), lo, hi));
  return static_cast<int>(*v);
}

std::optional<std::vector<double>> Section::numbers(std::string_view key, std::size_t count) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  const auto* a = n->as_array();
  if (a == nullptr || a->size() != count) {
    fail(key, fmt::format("got {}, expected an array of {} numbers", describe(*n), count));
  }
  std::vector<double> out;
  for (const auto& e : *a) {
    if (!e.is_number())
      fail(key, fmt::format("got {}, expected an array of {} numbers", describe(*n), count));
    const double x = e.is_integer() ? static_cast<double>(e.value_or(std::int64_t{0})) : e.value_or(0.0);
    if (!std::isfinite(x)) {
      fail(key, fmt::format("got {}, expected finite numbers", describe(*n)));
    }
    out.push_back(x);
  }
  return out;
}

std::optional<Vec3> Section::vec3(std::string_view key) const {
  const auto v = numbers(key, 3);
  if (!v) return std::nullopt;
  return Vec3((*v)[0], (*v)[1], (*v)[2]);
}

std::optional<Mat3> Section::mat3(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  const auto* rows = n->as_array();
  const auto bad = [&] {
    fail(key, fmt::format("got {}, expected three rows of three numbers [[a, b, c], [d, e, f], [g, h, i]]",
                          describe(*n)));
  };
  if (rows == nullptr || rows->size() != 3) bad();
  Mat3 m;
  for (std::size_t i = 0; i < 3; ++i) {
    const auto* row = (*rows)[i].as_array();
    if (row == nullptr || row->size() != 3) bad();
    for (std::size_t j = 0; j < 3; ++j) {
      const auto& e = (*row)[j];
      if (!e.is_number()) bad();
      const double x = e.is_integer() ? static_cast<double>(e.value_or(std::int64_t{0})) : e.value_or(0.0);
      if (!std::isfinite(x)) fail(key, fmt::format("got {}, expected finite numbers", describe(*n)));
      m(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = x;
    }
  }
  return m;
}

std::optional<std::string> Section::string(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_string()) fail(key, fmt::format("got {}, expected a string", describe(*n)));
  return std::string(n->value_or(std::string_view{}));
}

std::optional<bool> Section::boolean(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  if (!n->is_boolean()) fail(key, fmt::format("got {}, expected true or false", describe(*n)));
  return n->value_or(false);
}

const toml::table* Section::table(std::string_view key) const {
  const toml::node* n = node(key);
  if (n == nullptr) return nullptr;
  if (!n->is_table()) fail(key, fmt::format("got {}, expected a table {{ ... }}", describe(*n)));
  return n->as_table();
}

std::string_view Section::exactly_one(std::initializer_list<std::string_view> keys,
                                      std::string_view what) const {
  std::vector<std::string_view> given;
  for (const auto& k : keys) {
    if (has(k)) given.push_back(k);
  }
  if (given.size() == 1) return given.front();
  if (given.empty()) {
    if (table_ == nullptr) {
      throw InvalidInput(fmt::format("{}[{}] section is missing; expected it with exactly one of {} ({})",
                                     location(source_, position_), name_, join(keys), what));
    }
    throw InvalidInput(fmt::format("{}[{}] {} is missing; expected exactly one of {}",
                                   location(source_, position_), name_, what, join(keys)));
  }
  std::string both;
  for (const auto& k : given)
    both += (both.empty() ? "" : " and ") + std::string(k);
  throw InvalidInput(fmt::format("{}[{}] {} is given {} times ({}); expected exactly one of {}",
                                 location(source_, node(given[1])), name_, what, given.size(), both,
                                 join(keys)));
}

}  // namespace poinsot::io::detail
