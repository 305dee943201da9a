#include "test_support.h"

#include "core/error.h"
#include "core/mesh.h"
#include "core/scene.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstdlib>
#include <random>

namespace voxflame::test {

namespace {
// Every test process, and every voxflame it starts, keeps its mask cache in a temporary folder
// of its own: tests never write to the user's real ~/.cache.
struct PrivateCacheFolder {
  TemporaryFolder folder;
  PrivateCacheFolder() { setenv("XDG_CACHE_HOME", folder.path().c_str(), 1); }
};
const PrivateCacheFolder privateCacheFolder;

// Meshes are imported in a child process as in voxflame itself: the built binary's hidden
// subcommand (a test program cannot run itself for that).
struct MeshImportByTheBinary {
  MeshImportByTheBinary() { core::setMeshImportChild({VOXFLAME_BINARY, {core::kMeshImportSubcommand, "--"}}); }
};
const MeshImportByTheBinary meshImportByTheBinary;
}  // namespace

std::filesystem::path meshPath(const std::string& name) {
  return std::filesystem::path(VOXFLAME_TEST_MESHES) / name;
}
std::filesystem::path sourcePath(const std::string& relative) {
  return std::filesystem::path(VOXFLAME_SOURCE_DIR) / relative;
}

TemporaryFolder::TemporaryFolder() {
  std::random_device random;
  path_ =
      std::filesystem::temp_directory_path() / ("voxflame-test-" + std::to_string(random()) + std::to_string(random()));
  std::filesystem::create_directories(path_);
}

TemporaryFolder::~TemporaryFolder() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string presetErrorOf(const std::string& json) {
  try {
    core::sceneFromJson(json, "test.json");
  } catch (const core::Error& e) {
    return e.what();
  }
  return "";
}

CommandResult runVoxflame(const std::string& arguments, const std::filesystem::path& workingDir,
                          const std::string& environment) {
  std::string command;
  if (!workingDir.empty()) command += "cd '" + workingDir.string() + "' && ";
  command += environment + " '" + std::string(VOXFLAME_BINARY) + "' " + arguments + " 2>&1";
  CommandResult result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  std::array<char, 4096> buffer{};
  std::size_t count = 0;
  while ((count = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), count);
  const int status = pclose(pipe);
  result.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::vector<std::string> filesStartingWith(const std::filesystem::path& folder, const std::string& prefix) {
  std::vector<std::string> names;
  std::error_code ec;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    std::string name = item.path().filename().string();
    if (name.starts_with(prefix)) names.push_back(std::move(name));
  }
  std::sort(names.begin(), names.end());
  return names;
}

CommandResult runShell(const std::string& command, const std::filesystem::path& folder) {
  CommandResult result;
  FILE* pipe = popen(("cd '" + folder.string() + "' && " + command + " 2>&1").c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  for (std::size_t count; (count = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;)
    result.output.append(buffer, count);
  const int status = pclose(pipe);
  result.exitStatus = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

std::string tinyAnimationPreset(std::uint64_t points) {
  std::string preset = R"({"schema_version":2,"name":"tiny","mesh":{"path":"builtin:meshes/bunny.obj"},
  "grid":{"resolution":32},
  "layers":[{"attractor":"lorenz84","params":{"a":1.111,"b":1.479,"f":4.494,"g":0.44},"transform":{"scale":0.75}}],
  "points":)";
  preset.append(std::to_string(points)).append(R"(,"animation":{"fps":10,"duration":2},
  "keyframes":[{"path":"/layers/0/transform/rotation_deg","interpolation":"linear",
                "keys":[{"time":0,"value":[0,0,0]},{"time":2,"value":[0,60,0]}]}]})");
  return preset;
}

}  // namespace voxflame::test
