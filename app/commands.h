// The subcommands of the voxflame binary. Each lives in its own file and is listed once in
// subcommands(); runCommandLine dispatches on the first argument.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/flame_xml.h"
#include "core/scene.h"

namespace voxflame::app {

using CommandArgs = std::vector<std::string>;  // the whole argv: [0] program, [1] subcommand

struct Subcommand {
  const char* name;
  int (*run)(const CommandArgs& args);
};
const std::vector<Subcommand>& subcommands();

int renderCommand(const CommandArgs& args);   // cli.cpp
int animateCommand(const CommandArgs& args);  // animate_command.cpp
int benchCommand(const CommandArgs& args);    // bench/bench_command.cpp
int listCommand(const CommandArgs& args);     // catalogue_commands.cpp
int infoCommand(const CommandArgs& args);     // catalogue_commands.cpp
int searchCommand(const CommandArgs& args);   // catalogue_commands.cpp
int maskCommand(const CommandArgs& args);     // mask_command.cpp
int importCommand(const CommandArgs& args);   // import_command.cpp

// Points of a still for an imported flame: a chaos game's dust needs fewer than a smooth attractor
// to look clean, and flames are sampled at well over a million points a second.
inline constexpr std::uint64_t kImportedFlamePoints = 60'000'000;

// The scene an imported flame goes into when there is no current one: the default preset's mesh
// and camera, kImportedFlamePoints, the points render method.
core::Scene importBaseScene();

// Reads the flame `options` picks from `path` and makes `scene` from `base` (its mesh, camera and
// render settings) with that flame as its only layer (import_command.cpp). Throws core::Error.
core::FlameFileContents importFlameScene(const std::filesystem::path& path, const core::Scene& base,
                                         const core::FlameImportOptions& options, core::Scene& scene);

// The preset named by the first positional argument, or the embedded default when none.
core::Scene sceneFromArgument(const std::vector<std::string>& positional);

// From now on Ctrl-C and SIGTERM only raise the returned flag (cleared here): a render stops at
// its next check and leaves no half-written file behind.
const std::atomic<bool>& catchInterrupts();

// "42s", "3m07s", "1h05m".
std::string formatDuration(double seconds);

}  // namespace voxflame::app
