// `poinsot view OUT_DIR`: writes OUT_DIR/view.html, the self-contained 3-D page of a finished run (see
// docs/viewer.md and io/view/view_page.hpp). Bad input (no finished run, --frames out of range, a run too
// large for the frames asked for) is one line on stderr, status 2, and nothing written.
#include <string>

#include <fmt/format.h>

#include "commands.hpp"
#include "poinsot/io/view/view_page.hpp"

namespace poinsot::cli {

void register_view(CLI::App& app) {
  auto dir = std::make_shared<std::string>();
  auto options = std::make_shared<io::ViewOptions>();
  auto* cmd = app.add_subcommand("view", "Write view.html: the 3-D page of a finished run (docs/viewer.md)");
  cmd->add_option("out_dir", *dir, "the output folder of a finished `poinsot run` or `poinsot optimize`")
      ->required();
  cmd->add_option(
      "--frames", options->frames,
      fmt::format("most frames in the page; longer runs are decimated (default {})", io::kViewFramesDefault));
  cmd->add_option("--scenario", options->scenario_path,
                  "the scenario file of the run, for the model (default: the path in summary.json, if it "
                  "still reads)");
  cmd->callback([dir, options] {
    const std::string path = io::write_view_page(*dir, *options);
    fmt::print("{}\n", path);
  });
}

}  // namespace poinsot::cli
