// poinsot: the command-line tool. Usage: `poinsot <command> [options]`; `poinsot --help` lists the commands.
// Exit status: 0 on success, 2 on bad input (one line on stderr), 1 on an unexpected internal error.
#include <cstdio>
#include <exception>

#include <fmt/format.h>
#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "poinsot/core/error.hpp"

int main(int argc, char** argv) {
  CLI::App app{"poinsot: rotation of rigid bodies (inertia, Euler's equations, Lagrange multipliers)",
               "poinsot"};
  app.require_subcommand(1);
  poinsot::cli::register_commands(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, then the usage hint; status 2 like every other bad input.
    fmt::print(stderr, "poinsot: {}\n", e.what());
    return 2;
  } catch (const poinsot::Error& e) {
    fmt::print(stderr, "poinsot: {}\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    fmt::print(stderr, "poinsot: internal error: {}\n", e.what());
    return 1;
  }
  return 0;
}
