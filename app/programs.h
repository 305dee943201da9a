// Other programs voxflame runs (ffmpeg, sbatch): finding them on PATH, running them without a
// shell, and printing a command a user can paste into one.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace voxflame::app {

// The executable file `program` in a folder of $PATH, or nothing.
std::optional<std::string> findOnPath(const std::string& program);

// Runs the program with these arguments (argv[0] included; no shell, so no quoting) and returns
// its exit status (128 + the signal when a signal ended it). With `output`, its standard output
// is collected there instead of passing through; its standard error passes through, or with
// `collectErrors` is collected there too.
int runProgram(const std::string& program, const std::vector<std::string>& arguments, std::string* output = nullptr,
               bool collectErrors = false);

// The arguments as one shell command line, quoting those that need it.
std::string shellQuoted(const std::vector<std::string>& arguments);

// The absolute path of the running voxflame binary (for job scripts that run it again).
std::string currentExecutable();

}  // namespace voxflame::app
