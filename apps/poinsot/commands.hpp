#pragma once
// The sub-commands of the poinsot tool. Each cmd_<name>.cpp defines one register_<name> that adds its
// sub-command to the app and sets its callback; main.cpp calls them all. A callback reports bad input by
// throwing poinsot::Error; main prints the message on one line and exits with status 2.
#include <CLI/CLI.hpp>

namespace poinsot::cli {

void register_version(CLI::App& app);
void register_rotation(CLI::App& app);

// inertia (issue 3)
void register_inertia(CLI::App& app);
/// `poinsot inertia check` (cmd_inertia_check.cpp), added to the inertia sub-command.
void register_inertia_check(CLI::App& inertia);

// run (issue 6)
void register_run(CLI::App& app);

// lambda (issue 5)
void register_lambda(CLI::App& app);

}  // namespace poinsot::cli
