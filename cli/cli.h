// The command line: `voxflame [FILE]` opens the explorer; `voxflame render ...` and the other
// subcommands work headless. CLI11 parses argv into each subcommand's option struct
// (app/commands.h), checks ranges and choices, and generates `voxflame [SUB] --help`.
#pragma once

#include <string>
#include <vector>

namespace voxflame::cli {

// Runs the command line (argv: [0] the program) and returns the process exit status: 0 for
// --help and --version, 2 for a usage error (one line naming the option, then where the help
// is), 1 for an error while running, each printed as one clear line.
int runCommandLine(const std::vector<std::string>& args);

// The usage error runCommandLine would report for `args`, found by parsing alone (nothing runs),
// or "" when they parse. For tests of the option table.
std::string usageErrorOf(const std::vector<std::string>& args);

}  // namespace voxflame::cli
