// Fuzz harness: the command-line parser of the poinsot tool — CLI11 with every sub-command and option of
// apps/poinsot registered as main.cpp registers them. The input is the argument list, separated by NUL bytes
// (at most 64 arguments).
//
// The whole parse runs: options matched and converted, validators, requirements and exclusions, help and
// version requests. Only the sub-commands' actions do not: CLI11 calls the root app's parse-complete
// callback after all of that and before any sub-command's callback, so the harness sets it to throw
// `Parsed`, which ends the parse there. The actions' callbacks are left in place, so the options they own
// stay alive (replacing the callbacks by no-ops freed them: the use-after-free of an earlier version of this
// harness). The actions' readers have their own harnesses.
//
// Accepted outcomes: `Parsed`, a CLI11 error (main.cpp prints it, exit 2) or a poinsot::Error, each of one
// line unless an argument itself holds a line break (the messages quote arguments). Anything else — another
// exception (main.cpp: "internal error", exit 1), a sanitizer report — is a finding.
#include <string>
#include <string_view>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "fuzz_support.hpp"

namespace {

/// Thrown when the parse is complete, before the actions.
struct Parsed {};

bool has_line_break(std::string_view s) {
  return s.find('\n') != std::string_view::npos || s.find('\r') != std::string_view::npos;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"poinsot"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < 64; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  if (!current.empty() && args.size() < 64) args.push_back(current);
  std::vector<char*> argv;
  bool argument_breaks_lines = false;
  for (std::string& a : args) {
    argv.push_back(a.data());
    argument_breaks_lines = argument_breaks_lines || has_line_break(a);
  }
  const auto expect_one_line = [&](const char* what, std::string_view m) {
    if (has_line_break(m) && !argument_breaks_lines) poinsot::fuzz::finding(what, std::string(m));
  };

  // The sub-commands of the tool, registered as main.cpp registers them.
  CLI::App app{"poinsot", "poinsot"};
  app.require_subcommand(1);
  poinsot::cli::register_commands(app);
  app.parse_complete_callback([] { throw Parsed{}; });

  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
    poinsot::fuzz::finding("an action ran", "the parse-complete callback was not called");
  } catch (const Parsed&) {
  } catch (const CLI::CallForHelp&) {
  } catch (const CLI::CallForAllHelp&) {
  } catch (const CLI::CallForVersion&) {
  } catch (const CLI::ParseError& e) {
    expect_one_line("CLI11 error message is not one line", e.what());
  } catch (const poinsot::Error& e) {
    expect_one_line("error message is not one line", e.what());
  } catch (const std::exception& e) {
    poinsot::fuzz::finding("unexpected exception", e.what());
  }
  return 0;
}
