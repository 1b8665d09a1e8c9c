#pragma once
// The sub-commands of the poinsot tool. Each cmd_<name>.cpp defines one register_<name> that adds its
// sub-command to the app and sets its callback; register_commands (commands.cpp) calls them all. A callback
// reports bad input by throwing poinsot::Error; main prints the message on one line and exits with status 2.
#include <cstddef>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "poinsot/core/types.hpp"

namespace poinsot::cli {

/// Registers every sub-command on the root `app`, in the order `poinsot --help` lists them (commands.cpp).
void register_commands(CLI::App& app);

void register_version(CLI::App& app);
void register_rotation(CLI::App& app);
// hidden `completion bash|commands`: walks the app when it runs, so register it with the others
void register_completion(CLI::App& app);

// inertia: mass properties, principal axes, validity
void register_inertia(CLI::App& app);
/// `poinsot inertia check` (cmd_inertia_check.cpp), added to the inertia sub-command.
void register_inertia_check(CLI::App& inertia);

// run: a scenario file, single-body or multibody
void register_run(CLI::App& app);

// lambda: the multipliers Λ and the constraint stress
void register_lambda(CLI::App& app);

// view: the 3-D page of a run
void register_view(CLI::App& app);
// optimize (optimal reorientation)
void register_optimize(CLI::App& app);
// ensemble
void register_ensemble(CLI::App& app);

/// Runs python/poinsot/plot.py on an output folder (cmd_run.cpp); its output goes to stderr when stdout
/// carries JSON. Throws ComputationFailed when Python or the script fails.
void make_plots(const std::string& dir, bool stdout_is_json);

/// Three numbers of a list option, from `offset` on, as a vector (CLI11 has checked the option's length).
inline Vec3 vec3_from_list(const std::vector<double>& v, std::size_t offset = 0) {
  return Vec3(v[offset], v[offset + 1], v[offset + 2]);
}

}  // namespace poinsot::cli
