// `poinsot version` and `poinsot --version`: print the library version.
#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/version.hpp"

namespace poinsot::cli {

void register_version(CLI::App& app) {
  auto* cmd = app.add_subcommand("version", "Print the version of poinsot");
  cmd->callback([] { fmt::print("poinsot {}\n", kVersion); });
  // `poinsot --version` too, as tools are expected to answer (help2man reads it).
  app.set_version_flag("--version", fmt::format("poinsot {}", kVersion),
                       "Print the version of poinsot and exit");
}

}  // namespace poinsot::cli
