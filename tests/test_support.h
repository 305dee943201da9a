// Helpers shared by the test suites: where the shared meshes are, temporary folders, running
// the voxflame binary and capturing what it prints.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace voxflame::test {

std::filesystem::path meshPath(const std::string& name);  // ../shared/data/meshes/NAME
std::filesystem::path sourcePath(const std::string& relative);

// A fresh, empty folder removed when the object goes away.
class TemporaryFolder {
 public:
  TemporaryFolder();
  ~TemporaryFolder();
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// The names of the files in `folder` that start with `prefix`, sorted: {"out.png"} for
// "out.png" when no temporary of it was left beside it.
std::vector<std::string> filesStartingWith(const std::filesystem::path& folder, const std::string& prefix);

// The message core::sceneFromJson gives for this preset text, or "" when it loads.
std::string presetErrorOf(const std::string& json);

struct CommandResult {
  int exitStatus = -1;
  std::string output;  // stdout and stderr together
};
// Runs the built voxflame binary with these arguments (a shell-quoted string) in `workingDir`.
CommandResult runVoxflame(const std::string& arguments, const std::filesystem::path& workingDir = {},
                          const std::string& environment = "");
// Runs a shell command in `folder` (a job script as a scheduler would run it).
CommandResult runShell(const std::string& command, const std::filesystem::path& folder);

}  // namespace voxflame::test
