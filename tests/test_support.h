// Helpers shared by the test suites: where the shared meshes are, temporary folders, running
// the voxflame binary and capturing what it prints.
#pragma once

#include <cstdint>
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

// A tiny animation for `voxflame animate`: a 32³ grid in the built-in bunny, 21 frames (two seconds
// at 10 fps) of one lorenz84 layer turning 60° about y, `points` per frame. A transform moves the
// same orbits (same seed, same parameters) through the grid, so the change between frames is the
// motion alone. (Animating an attractor parameter changes every chaotic orbit: at these point
// counts the frame-to-frame noise then is as large as the motion.)
std::string tinyAnimationPreset(std::uint64_t points);
// The frame size the animation tests render the tiny animation at, as command-line options.
inline const std::string kTinyFrameSize = " --width 48 --height 32";

}  // namespace voxflame::test
