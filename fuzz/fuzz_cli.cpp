// Fuzz harness: the command-line parser of the poinsot tool (CLI11 with every sub-command and option of
// apps/poinsot registered, as main.cpp does). The input is the argument list, separated by NUL bytes. The
// sub-commands' actions are replaced by no-ops: this harness exercises the parsing and conversion of
// arguments; the actions' readers have their own harnesses.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.hpp"
#include "fuzz_support.hpp"

namespace {

void disarm(CLI::App& app) {
  for (CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; })) {
    sub->callback([] {});
    disarm(*sub);
  }
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
  if (!current.empty()) args.push_back(current);
  std::vector<char*> argv;
  for (std::string& a : args)
    argv.push_back(a.data());
  CLI::App app{"poinsot", "poinsot"};
  app.require_subcommand(1);
  poinsot::cli::register_version(app);
  poinsot::cli::register_rotation(app);
  poinsot::cli::register_inertia(app);
  poinsot::cli::register_run(app);
  poinsot::cli::register_lambda(app);
  disarm(app);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error&) {
    // help, version and parse errors: main.cpp prints them; nothing more to check here
  } catch (const std::exception& e) {
    poinsot::fuzz::finding("unexpected exception", e.what());
  }
  return 0;
}
