// `poinsot version`: prints the library version.
#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/version.hpp"

namespace poinsot::cli {

void register_version(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the version of poinsot");
  cmd->callback([] { fmt::print("poinsot {}\n", kVersion); });
}

}  // namespace poinsot::cli
