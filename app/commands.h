// The headless subcommands of the voxflame binary. Each lives in its own file and takes its
// options as a plain struct; the command line (cli/cli.cpp, target voxflame_cli) parses argv into
// these structs, checks every range and choice, and writes the --help text. A command still
// throws UsageError for what only it can judge (a missing output, an option that does not fit
// the preset) and core::Error for what goes wrong while it runs.
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/attractor.h"
#include "core/flame/xml.h"
#include "core/inside_mask.h"
#include "core/scene.h"
#include "refinement_backends.h"

namespace voxflame::app {

// An unset std::optional is an option that was not given: the preset's own value stays.
struct RenderArguments {
  std::optional<std::string> preset;  // PRESET.json, IMAGE.png, FILE.flame or a mesh; none: the default
  std::optional<std::string> output;  // OUT.png, OUT.exr, OUT.vdb or OUT.nrrd
  int width = 1280, height = 720;
  std::uint64_t points = 0;  // 0: the preset's
  int threads = 0;           // 0: all cores
  // What refines the volume (refinement_backends.h). The CPU until the GPU backend has been measured
  // on a hardware GPU; `auto` and `gpu` are the user's to ask for.
  BackendChoice backend = BackendChoice::Cpu;
  std::optional<double> untilNoisePercent;  // stop at this estimated noise (percent), --points a cap
  std::optional<int> samples, grid, oversample;
  std::optional<double> cameraAzimuthDeg, cameraElevationDeg, time;
  int bitDepth = 8;
  int progressFd = -1;  // -1: no progress lines
  std::optional<core::RenderMethod> method;
  bool stats = false;
  // --flat: the flame layer in 2D as flam3 frames it (flame/flat_render.h); the size defaults to the
  // flame's, so the command line says whether --width and --height were given.
  bool flat = false;
  bool widthGiven = false, heightGiven = false;
  std::optional<double> quality;  // --flat: samples per pixel (default: the flame's)
  std::uint64_t seed = 1;         // --flat: the chaos game's seed
  // A still split into chunks (pipeline.h ChunkPlan): how many, a checkpoint folder that keeps
  // each finished chunk, and for a farm task the range of chunks it renders (no image).
  std::optional<int> chunks;
  std::optional<std::string> checkpoint;
  std::optional<std::string> chunkRange;  // "A-B"
  std::optional<std::string> farm;        // "slurm"
  std::optional<int> tasks;
  std::optional<std::string> partition;
  bool submit = false;
  std::optional<std::string> statusOutput;  // --status OUT: list the chunks still missing
  // The render options as given ("--width", "640", ...): a farm task passes them on unchanged.
  std::vector<std::string> taskOptions;
};
int renderCommand(const RenderArguments& arguments);  // render_command.cpp

struct AnimateArguments {
  std::optional<std::string> preset;
  std::optional<std::string> output;         // the frame pattern, frames/%04d.png
  std::optional<std::string> statusPattern;  // --status PATTERN: list missing frames instead
  std::optional<std::string> frames;         // "A-B" or "N"
  int width = 1280, height = 720;
  std::optional<double> fps;
  int motionBlur = 1;
  double shutter = 0.5;
  std::optional<std::string> video;
  std::optional<int> samples, grid;
  std::uint64_t points = 0;
  int threads = 0;
  BackendChoice backend = BackendChoice::Cpu;  // what refines each frame's volume (as render's)
  std::optional<std::string> farm;             // "slurm"
  std::optional<int> tasks;
  std::optional<std::string> partition;
  bool submit = false;
  // The render options as given ("--width", "640", ...): a farm task passes them on unchanged.
  std::vector<std::string> taskOptions;
};
int animateCommand(const AnimateArguments& arguments);  // animate_command.cpp

struct ListArguments {
  bool json = false, variations = false, markdown = false;
};
int listCommand(const ListArguments& arguments);  // catalogue_commands.cpp

// One attractor parameter set for `info` and `search`: a preset's first layer, or --attractor ID
// with its defaults, then --set NAME, --param NAME=VALUE..., --integrator, --step.
struct OrbitArguments {
  std::optional<std::string> preset;
  std::optional<std::string> attractor, set;
  std::vector<std::string> params;  // NAME=VALUE, in command-line order
  std::optional<core::Integrator> integrator;
  std::optional<double> step;
  bool json = false;
};
int infoCommand(const OrbitArguments& arguments);  // catalogue_commands.cpp

struct SearchArguments {
  OrbitArguments orbit;
  std::uint64_t seed = 1;
  int count = 5;
  double strength = 0.1;
  bool random = false;                // flame and quaternion Julia presets only
  std::optional<std::string> output;  // writes the best as a preset (same)
};
int searchCommand(const SearchArguments& arguments);  // catalogue_commands.cpp

struct MaskArguments {
  std::optional<std::string> mesh;
  std::optional<std::string> output;  // OUT.nrrd
  int grid = 256;
  bool stats = false;
  core::MaskMethod method = core::MaskMethod::WindingNumber;
};
int maskCommand(const MaskArguments& arguments);  // mask_command.cpp

struct ImportArguments {
  std::optional<std::string> flameFile;
  std::optional<std::string> output;  // PRESET.json
  std::optional<std::string> mesh;
  double depth = core::kDefaultFlameDepth;
  std::optional<int> index;  // from 1
  std::optional<std::string> name;
};
int importCommand(const ImportArguments& arguments);  // import_command.cpp

// Points of a still for an imported flame: a chaos game's dust needs fewer than a smooth attractor
// to look clean, and flames are sampled at well over a million points a second.
inline constexpr std::uint64_t kImportedFlamePoints = 60'000'000;

// The scene an imported flame goes into when there is no current one: the default preset's mesh
// and camera, kImportedFlamePoints (the points method comes with core::sceneFromImportedFlame).
core::Scene importBaseScene();

// Reads the flame `options` picks from `path` and makes `scene` from `base` (its mesh, camera and
// render settings) with that flame as its only layer (import_command.cpp). Throws core::Error.
core::FlameFileContents importFlameScene(const std::filesystem::path& path, const core::Scene& base,
                                         const core::FlameImportOptions& options, core::Scene& scene);

// The scene of a command's file argument (sceneFromFile), or the embedded default when none.
core::Scene sceneFromArgument(const std::optional<std::string>& file);

// From now on Ctrl-C and SIGTERM only raise the returned flag (cleared here): a render stops at
// its next check and leaves no half-written file behind.
const std::atomic<bool>& catchInterrupts();

// "42s", "3m07s", "1h05m".
std::string formatDuration(double seconds);

}  // namespace voxflame::app
