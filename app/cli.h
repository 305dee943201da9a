// The command line: `voxflame [PRESET.json]` opens the explorer; `voxflame render ...` and the
// other subcommands work headless. Each subcommand parses its own options into a struct.
#pragma once

#include <string>
#include <vector>

namespace voxflame::app {

// Runs the command line; returns the process exit status. Errors print one clear line.
int runCommandLine(const std::vector<std::string>& args);

}  // namespace voxflame::app
