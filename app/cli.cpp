#include "cli.h"

#include <unistd.h>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "arguments.h"
#include "commands.h"
#include "core/error.h"
#include "core/scene_io.h"
#include "explorer.h"
#include "pipeline.h"
#include "version.h"

namespace voxflame::app {

namespace {

constexpr const char* kUsage = R"(voxflame — strange attractors filling the volume of a mesh

usage:
  voxflame [PRESET.json] [--screenshot FILE --frames N]
      Open the explorer on a preset (the built-in default when none is given).
  voxflame render [PRESET.json] -o OUT.png [--width W] [--height H] [--points N]
                  [--bit-depth 8|16] [--threads T]
      Render a still headless (no display needed); the PNG carries the preset.
  voxflame mask MESH -o OUT.nrrd [--grid N] [--stats]
                [--method winding-number|exact-winding-number|parity]
      Write the mesh's inside mask (N voxels along its longest axis, 32-1024, default 256)
      as an NRRD volume in the mesh's own coordinates.
  voxflame bench [accumulate|mask|raymarch|export] [--json]
      Measure performance (Release build).
  voxflame --help | --version
)";

}  // namespace

core::Scene sceneFromArgument(const std::vector<std::string>& positional) {
  if (positional.empty()) return core::defaultScene();
  return core::loadScene(positional.front());
}

int renderCommand(const std::vector<std::string>& args) {
  Arguments arguments(args, 2);
  const auto output = arguments.take("-o", "--output");
  StillOptions options;
  options.width = static_cast<int>(arguments.integer("--width", 1280, 1, 16384));
  options.height = static_cast<int>(arguments.integer("--height", 720, 1, 16384));
  options.points = static_cast<std::uint64_t>(arguments.integer("--points", 0, 0, 1LL << 40));
  options.threads = static_cast<int>(arguments.integer("--threads", 0, 0, 1024));
  const int bitDepth = static_cast<int>(arguments.integer("--bit-depth", 8, 8, 16));
  if (bitDepth != 8 && bitDepth != 16) throw UsageError("--bit-depth must be 8 or 16");
  arguments.finish(1);
  if (!output) throw UsageError("render needs an output file: -o OUT.png");
  if (std::filesystem::path(*output).extension() != ".png")
    throw UsageError("output '" + *output + "' must end in .png");

  core::Scene scene = sceneFromArgument(arguments.positional());
  const bool interactive = isatty(fileno(stderr));
  options.progress = [interactive](const core::AccumulatorStats& stats, std::uint64_t target) {
    if (!interactive) return;
    const double percent =
        target ? 100.0 * static_cast<double>(std::min(stats.points, target)) / static_cast<double>(target) : 0.0;
    std::fprintf(stderr, "\raccumulating %5.1f%%  %.1f M points/s   ", percent, stats.pointsPerSecond * 1e-6);
  };
  const StillResult result = renderStill(scene, options);
  if (interactive) std::fprintf(stderr, "\n");
  if (!result.warning.empty()) std::cerr << "voxflame: warning: " << result.warning << "\n";
  core::writePng(*output, result.image, bitDepth, stillMetadata(scene, result));
  std::printf("wrote %s (%d×%d, %llu points inside, %.2f s accumulating, %.2f s rendering on %s)\n", output->c_str(),
              options.width, options.height, static_cast<unsigned long long>(result.stats.points),
              result.accumulateSeconds, result.renderSeconds, result.renderer.c_str());
  return 0;
}

namespace {

int explorerCommand(const std::vector<std::string>& args) {
  Arguments arguments(args, 1);
  ExplorerOptions options;
  if (const auto screenshot = arguments.take("--screenshot")) options.screenshotPath = *screenshot;
  options.frames = static_cast<int>(arguments.integer("--frames", 0, 0, 1'000'000));
  arguments.finish(1);
  if (!options.screenshotPath.empty() && options.frames == 0) options.frames = 60;
  return runExplorer(sceneFromArgument(arguments.positional()), options);
}

}  // namespace

int runCommandLine(const std::vector<std::string>& args) {
  try {
    const std::string command = args.size() > 1 ? args[1] : "";
    if (command == "--help" || command == "-h" || command == "help") {
      std::cout << kUsage;
      return 0;
    }
    if (command == "--version") {
      std::cout << "voxflame " << kVersion << "\n";
      return 0;
    }
    for (const Subcommand& subcommand : subcommands())
      if (command == subcommand.name) return subcommand.run(args);
    return explorerCommand(args);
  } catch (const UsageError& e) {
    std::cerr << "voxflame: " << e.what() << "\n\n" << kUsage;
    return 2;
  } catch (const core::Error& e) {
    std::cerr << "voxflame: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "voxflame: out of memory; try a smaller grid or image\n";
    return 1;
  }
}

}  // namespace voxflame::app

namespace voxflame::app {

const std::vector<Subcommand>& subcommands() {
  static const std::vector<Subcommand> table = {
      {"render", &renderCommand},
      {"bench", &benchCommand},
      {"mask", &maskCommand},
  };
  return table;
}

}  // namespace voxflame::app
