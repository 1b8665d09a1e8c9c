#pragma once
// Internal to the io layer: typed, located access to the keys of a TOML table, for scenario files.
// Every error is an InvalidInput whose message starts with `SOURCE:LINE:COLUMN: [section] key: ...`.
// toml++ is used header-only (TOML_HEADER_ONLY=1) in the io sources that include this header, so that the
// exported library carries no link dependency on it.

#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#ifndef TOML_HEADER_ONLY
#define TOML_HEADER_ONLY 1
#endif
#include <toml++/toml.h>

#include "poinsot/core/error.hpp"
#include "poinsot/core/types.hpp"

namespace poinsot::io::detail {

/// Where the text came from, for messages.
struct Source {
  std::string name;  ///< path or "<string>"
};

/// Parses TOML text; a syntax error is an InvalidInput `SOURCE:LINE:COLUMN: TOML syntax error: ...`.
toml::table parse_toml(std::string_view text, std::string_view source);

/// The whole content of a text file; InvalidInput `scenario: cannot read "PATH": REASON; ...` otherwise.
std::string read_text_file(const std::string& path);

/// The text of a TOML scenario file (read_text_file). A robot file (URDF, MJCF or SDF, by its extension) is
/// refused with a line that says `poinsot run PATH` simulates it and a scenario names it in `[model]`.
std::string read_scenario_file(const std::string& path);

/// "SOURCE:LINE:COLUMN: " for a node (or "SOURCE: " when the node has no position).
std::string location(const Source& source, const toml::node* node);

/// Throws InvalidInput `SOURCE: [top level] optimal_control: missing; expected an [optimal_control] section
/// (a scenario without one is simulated by `poinsot run SOURCE`)` when the file has no [optimal_control]:
/// checked before its other keys, so that a run scenario given to `poinsot optimize` is answered with its
/// sub-command rather than with its first key that an optimal-control file does not have.
void require_optimal_control_section(const Source& source, const toml::table& root);

/// One table of the file ("body", "initial.orientation", ...), with the keys it accepts.
class Section {
 public:
  /// `table` may be null (the section is absent: every key is then missing). Throws InvalidInput naming the
  /// first key of `table` that is not in `valid`, with the valid keys listed.
  Section(const Source& source, const toml::table* table, std::string name,
          std::initializer_list<std::string_view> valid, const toml::node* position = nullptr);

  const std::string& name() const { return name_; }
  bool present() const { return table_ != nullptr; }
  bool has(std::string_view key) const;
  const toml::node* node(std::string_view key) const;

  /// Throws `LOCATION: [name] key: MESSAGE` at the key's value (or at the section when absent).
  [[noreturn]] void fail(std::string_view key, std::string_view message) const;
  /// The prefix "[name] key" used in messages.
  std::string label(std::string_view key) const;

  /// A finite number (TOML integer or float); nullopt when absent.
  std::optional<double> number(std::string_view key) const;
  /// A whole number from `lo` to `hi` (a TOML integer, or a float with no fractional part); nullopt when
  /// absent. Throws `got V, expected an integer from LO to HI` otherwise.
  std::optional<int> integer(std::string_view key, int lo, int hi) const;
  /// An array of exactly three finite numbers.
  std::optional<Vec3> vec3(std::string_view key) const;
  /// An array of n finite numbers.
  std::optional<std::vector<double>> numbers(std::string_view key, std::size_t n) const;
  /// A 3×3 matrix given as three rows of three finite numbers.
  std::optional<Mat3> mat3(std::string_view key) const;
  std::optional<std::string> string(std::string_view key) const;
  std::optional<bool> boolean(std::string_view key) const;
  /// A sub-table (inline or not), or nullptr when absent; throws when the key is not a table.
  const toml::table* table(std::string_view key) const;

  /// Throws unless exactly one of `keys` is present; returns it.
  std::string_view exactly_one(std::initializer_list<std::string_view> keys, std::string_view what) const;
  /// Throws "missing" unless the key is present.
  void require(std::string_view key, std::string_view expected) const;

 private:
  const Source& source_;
  const toml::table* table_;
  std::string name_;
  const toml::node* position_;
};

/// "a, b, c".
std::string join(std::initializer_list<std::string_view> items);

/// The text form of a node's value for messages (`"abc"`, `1.5`, `[1, 2]`, `a table`).
std::string describe(const toml::node& node);

/// Runs f(); an InvalidInput from a lower layer (a constructor's validation) is re-thrown with the place in
/// the file and the key in front, through section.fail.
template <class F>
auto located(const Section& section, std::string_view key, F&& f) {
  try {
    return f();
  } catch (const InvalidInput& e) {
    section.fail(key, e.what());
  }
}

/// Runs f(); an InvalidInput from a lower layer (a whole problem's validation) is re-thrown with the place of
/// `node` (a section) in front.
template <class F>
auto located(const Source& source, const toml::node* node, F&& f) {
  try {
    return f();
  } catch (const InvalidInput& e) {
    throw InvalidInput(location(source, node) + e.what());
  }
}

}  // namespace poinsot::io::detail
