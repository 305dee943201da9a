#include "cli.h"

#include <cmath>
#include <cstdint>
#include <functional>
#include <initializer_list>
#include <iostream>
#include <memory>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "bench.h"
#include "commands.h"
#include "core/error.h"
#include "core/grid.h"
#include "core/keyframes.h"
#include "core/mesh.h"
#include "explorer.h"
#include "usage_error.h"
#include "version.h"

namespace voxflame::cli {

namespace {

using app::UsageError;

// What a parsed command line runs.
using Run = std::function<int()>;

// CLI::Range, and text that is no number, or NaN (which every comparison lets through), refused
// with a message of its own. --help shows the range as "INT:[1 - 4]", like a choice's "TEXT:{a,b}".
template <typename T>
CLI::Validator within(T min, T max) {
  const CLI::Range range(min, max);
  const std::string description = range.get_description();  // "INT in [1 - 4]"
  return CLI::Validator(
      [range](std::string& text) -> std::string {
        T value{};
        if (!CLI::detail::lexical_cast(text, value))
          return "'" + text + "' is not " + (std::is_integral_v<T> ? "a whole number" : "a number");
        if constexpr (std::is_floating_point_v<T>)
          if (std::isnan(value)) return "'" + text + "' is not a number";
        return range(text);
      },
      description.substr(description.find('[')));
}

CLI::Validator finite() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value))
          return "'" + text + "' is not a finite number";
        return "";
      },
      "FINITE");
}

// An option that names one of `values` (--help lists the names) and sets `target` to it.
template <typename Enum, typename Target, typename NameOf>
CLI::Option* addChoice(CLI::App& command, const std::string& option, Target& target,
                       std::initializer_list<Enum> choices, NameOf nameOf, const std::string& help) {
  const std::vector<Enum> values(choices);
  std::vector<std::string> names;
  for (const Enum value : values) names.emplace_back(nameOf(value));
  const auto set = [&target, values, nameOf](const std::string& text) {
    for (const Enum value : values)
      if (text == nameOf(value)) target = value;
  };
  return command.add_option_function<std::string>(option, set, help)->check(CLI::IsMember(names));
}

// --backend of render and animate.
CLI::Option* addBackendChoice(CLI::App& command, app::BackendChoice& target) {
  return addChoice(
      command, "--backend", target, {app::BackendChoice::Cpu, app::BackendChoice::Gpu, app::BackendChoice::Auto},
      [](app::BackendChoice c) { return app::toString(c); },
      "What refines the volume: cpu (every core), gpu (compute shaders; attractor and quaternion Julia layers, "
      "flame layers of the variations it has; under the points method it projects the points too), "
      "auto (the GPU where it is a hardware one and runs the pattern, else the CPU). Default: cpu. A render's "
      "chunks all come from one backend");
}

std::vector<std::string> renderMethodNames() {
  return {std::string(core::toString(core::RenderMethod::Volume)),
          std::string(core::toString(core::RenderMethod::Points))};
}

// `voxflame [FILE]`: the options of the explorer are the top level's own. Defined after the
// subcommands, which would inherit the footer.
Run defineExplorer(CLI::App& root) {
  struct Arguments {
    std::optional<std::string> file;
    std::string screenshot;  // a std::filesystem::path would parse as a list (CLI11 2.1 sees a container)
    app::ExplorerOptions options;
  };
  auto a = std::make_shared<Arguments>();
  app::ExplorerOptions* options = &a->options;
  root.add_option("file", a->file, "PRESET.json, IMAGE.png, FILE.flame or MESH (default: the built-in preset)")
      ->type_name("FILE");
  root.add_option("--screenshot", a->screenshot,
                  "Save the window to FILE after --frames frames that show the volume, then exit")
      ->type_name("FILE");
  root.add_option("--frames", options->frames, "Frames before the screenshot (default 60 with --screenshot)")
      ->check(within(0, 1'000'000));
  root.add_option("--ui-scale", options->uiScale, "Panel and font scale (default: the monitor's)")
      ->check(within(0.5f, 4.0f));
  root.add_option("--width", options->width, "Window width (default: as last time)")->check(within(320, 16384));
  root.add_option("--height", options->height, "Window height (default: as last time)")->check(within(240, 16384));
  root.add_option("--min-frame-ms", options->minFrameMs,
                  "Make each frame last at least MS milliseconds, as on a slow machine (for testing input)")
      ->type_name("MS")
      ->check(within(0, 10'000));
  root.add_option("--input-log", options->inputLog,
                  "Append each change to a text field, with the time it was shown, to FILE (for measuring input)")
      ->type_name("FILE");
  root.footer(
      "Without a subcommand voxflame opens the explorer on FILE: a preset, the preset stored in a PNG\n"
      "rendered by voxflame, the first flame of a flame file (imported as by `voxflame import`), or a mesh\n"
      "filled with the default pattern. With no display (no DISPLAY or WAYLAND_DISPLAY) it says so and\n"
      "renders the preset to voxflame-preview.png instead.\n"
      "`voxflame SUBCOMMAND --help` shows the options of a subcommand.");
  return [a] {
    app::ExplorerOptions explorer = a->options;
    explorer.screenshotPath = a->screenshot;
    if (!explorer.screenshotPath.empty() && explorer.frames == 0) explorer.frames = 60;
    return app::runExplorer(app::sceneFromArgument(a->file), explorer);
  };
}

Run defineRender(CLI::App& command) {
  auto a = std::make_shared<app::RenderArguments>();
  command.add_option("preset", a->preset, "The preset: PRESET.json, or a PNG rendered by voxflame (default: built in)")
      ->type_name("PRESET.json|IMAGE.png");
  command
      .add_option("-o,--output", a->output,
                  "The file to write (required): OUT.png or OUT.exr (an image), OUT.vdb or OUT.nrrd (the volume)")
      ->type_name("OUT");
  CLI::Option* width = command.add_option("--width", a->width, "Image width in pixels (--flat: the flame's)")
                           ->check(within(1, 65536))
                           ->capture_default_str();
  CLI::Option* height = command.add_option("--height", a->height, "Image height in pixels (--flat: the flame's)")
                            ->check(within(1, 65536))
                            ->capture_default_str();
  command.add_flag("--flat", a->flat,
                   "Render the flame layer in 2D as flam3 frames it (the flame file's size, centre, scale, zoom, "
                   "rotate, quality, filter and tone): no mesh, no depth; for comparing with flam3-render");
  command.add_option("--quality", a->quality, "--flat: samples per output pixel (default: the flame's quality)")
      ->check(within(1e-3, 1e6));
  command.add_option("--seed", a->seed, "--flat: the chaos game's seed")->capture_default_str();
  command.add_option("--samples", a->samples, "Jittered sub-samples per pixel (default: the preset's)")
      ->check(within(1, 1024));
  command.add_option("--points", a->points, "Points to accumulate (0: the preset's)")
      ->check(within<std::uint64_t>(0, std::uint64_t{1} << 40));
  command.add_option("--grid", a->grid, "Voxels along the mesh's longest side (default: the preset's)")
      ->check(within(16, 1024));
  command
      .add_option("--until-noise", a->untilNoisePercent,
                  "Accumulate until the volume's estimated noise is this many PERCENT (0.5 = 0.5%: the RMS error of "
                  "the voxel densities relative to their RMS), instead of to a point count; --points, when given, "
                  "caps it. Volume method only")
      ->type_name("PERCENT")
      ->check(within(0.001, 100.0));
  command.add_option("--bit-depth", a->bitDepth, "Bits per channel of a PNG")
      ->check(CLI::IsMember({8, 16}))
      ->capture_default_str();
  command.add_option("--time", a->time, "The moment of an animated preset, in seconds (default: its animation.time)")
      ->check(within(0.0, core::kMaxAnimationSeconds));
  command.add_option("--camera-azimuth", a->cameraAzimuthDeg, "Camera azimuth in degrees (default: the preset's)")
      ->check(within(-3600.0, 3600.0));
  command
      .add_option("--camera-elevation", a->cameraElevationDeg, "Camera elevation in degrees (default: the preset's)")
      ->check(within(-360.0, 360.0));
  command.add_option("--threads", a->threads, "Accumulation threads (0: all cores)")->check(within(0, 1024));
  addBackendChoice(command, a->backend);
  command
      .add_option("--progress-fd", a->progressFd,
                  "Write lines \"progress STAGE FRACTION\" to this open file descriptor, for a parent process")
      ->check(within(0, 1 << 20));
  addChoice(
      command, "--method", a->method, {core::RenderMethod::Volume, core::RenderMethod::Points},
      [](core::RenderMethod m) { return core::toString(m); },
      "volume: ray-march the voxel grid; points: project every point, the way flam3 makes a flame "
      "(default: the preset's render.method)");
  command.add_option("--oversample", a->oversample, "Supersampling of the points method (default: the preset's)")
      ->check(within(1, 4));
  command.add_flag("--stats", a->stats,
                   "Print the render statistics as JSON too (\"noise\": the final noise estimate, a fraction)");
  command
      .add_option("--chunks", a->chunks,
                  "Split the points into K chunks, each with its own seed streams (default 64): the image depends "
                  "only on the preset, the size and K, wherever and however the chunks are rendered")
      ->type_name("K")
      ->check(within(1, 100000));
  command
      .add_option("--checkpoint", a->checkpoint,
                  "Keep each finished chunk in DIR (EXR or VDB); run the same command again to render only the "
                  "missing chunks and finish")
      ->type_name("DIR");
  command
      .add_option("--chunk-range", a->chunkRange,
                  "Render only chunks A-B into the --checkpoint folder and make no image (a farm task)")
      ->type_name("A-B");
  command.add_option("--farm", a->farm, "Write a job for this scheduler instead of rendering")
      ->check(CLI::IsMember({"slurm"}));
  command.add_option("--tasks", a->tasks, "Tasks of the farm job, each rendering one contiguous range of chunks")
      ->check(within(1, 100000));
  command.add_option("--partition", a->partition, "Slurm partition of the farm job");
  command.add_flag("--submit", a->submit, "Submit the farm job with sbatch");
  command
      .add_option("--status", a->statusOutput,
                  "List the chunks of OUT still missing from its checkpoint folder (exit status 1 when any is) and "
                  "the farm tasks that render them, instead of rendering")
      ->type_name("OUT");
  command.footer(
      "Renders headless (no display needed). A PNG carries its preset: rendering it again reproduces it.\n"
      "EXR is linear 32-bit float. VDB and NRRD hold the volume itself (normalised density and colour, in\n"
      "the mesh's coordinates) for other renderers. Ctrl-C stops cleanly and writes nothing (with\n"
      "--checkpoint, the finished chunks stay). With --farm slurm, writes a Slurm array job whose tasks\n"
      "render ranges of chunks into OUT.chunks/ (or --checkpoint) and a job that sums them into OUT.");
  // What a farm task renders with: the options that shape the image, as given.
  const std::vector<std::string> passedOnNames = {
      "--width",          "--height",           "--samples", "--points", "--grid",       "--bit-depth", "--time",
      "--camera-azimuth", "--camera-elevation", "--threads", "--method", "--oversample", "--backend"};
  return [a, width, height, passedOnNames, &command] {
    a->widthGiven = width->count() > 0;
    a->heightGiven = height->count() > 0;
    a->taskOptions.clear();
    for (const std::string& name : passedOnNames) {
      const CLI::Option* option = command.get_option_no_throw(name);
      if (option && option->count() > 0) a->taskOptions.insert(a->taskOptions.end(), {name, option->results().back()});
    }
    return app::renderCommand(*a);
  };
}

Run defineAnimate(CLI::App& command) {
  auto a = std::make_shared<app::AnimateArguments>();
  command
      .add_option("preset", a->preset, "The preset: PRESET.json, or a frame rendered by voxflame (default: built in)")
      ->type_name("PRESET.json|FRAME.png");
  command.add_option("-o,--output", a->output, "printf pattern of the PNG frames, e.g. frames/%04d.png (required)")
      ->type_name("PATTERN");
  command
      .add_option("--status", a->statusPattern,
                  "List the frames of PATTERN still missing (exit status 1 when any is) and the farm tasks that "
                  "render them, instead of rendering")
      ->type_name("PATTERN");
  command.add_option("--frames", a->frames, "Render part of the animation: A-B (inclusive) or N, from 0")
      ->type_name("A-B");
  // The options a farm task passes on as they were given.
  const std::vector<CLI::Option*> passedOn = {
      command.add_option("--width", a->width, "Frame width in pixels")->check(within(1, 16384))->capture_default_str(),
      command.add_option("--height", a->height, "Frame height in pixels")
          ->check(within(1, 16384))
          ->capture_default_str(),
      command.add_option("--fps", a->fps, "Frames per second (default: the preset's)")->check(within(0.01, 1000.0)),
      command.add_option("--motion-blur", a->motionBlur, "Sub-frames averaged over the shutter")
          ->check(within(1, 256))
          ->capture_default_str(),
      command.add_option("--shutter", a->shutter, "Shutter as a fraction of the frame interval")
          ->check(within(0.0, 1.0))
          ->capture_default_str(),
      command.add_option("--samples", a->samples, "Sub-samples per pixel (default: the preset's)")
          ->check(within(1, 1024)),
      command.add_option("--points", a->points, "Points per frame (0: the preset's)")
          ->check(within<std::uint64_t>(0, std::uint64_t{1} << 40)),
      command.add_option("--grid", a->grid, "Voxels along the mesh's longest side (default: the preset's)")
          ->check(within(16, 1024)),
      command.add_option("--threads", a->threads, "Accumulation threads (0: all cores)")->check(within(0, 1024)),
      addBackendChoice(command, a->backend),
  };
  command.add_option("--video", a->video, "Encode the frames to this file with ffmpeg when it is installed")
      ->type_name("OUT.mp4");
  command.add_option("--farm", a->farm, "Write a job for this scheduler instead of rendering")
      ->check(CLI::IsMember({"slurm"}));
  command.add_option("--tasks", a->tasks, "Tasks of the farm job, each rendering one contiguous range (default 1)")
      ->check(within(1, 100000));
  command.add_option("--partition", a->partition, "Slurm partition of the farm job");
  command.add_flag("--submit", a->submit, "Submit the farm job with sbatch");
  command.footer(
      "Renders the preset's keyframed animation to PNG frames named by a printf pattern; frames split across\n"
      "machines agree. With --farm slurm, writes a Slurm array job beside the frames (farm-render.sbatch)\n"
      "and a job that checks every frame and makes the video when they have ended (farm-finish.sbatch).");
  return [a, passedOn] {
    a->taskOptions.clear();
    for (const CLI::Option* option : passedOn)
      if (option->count() > 0)
        a->taskOptions.insert(a->taskOptions.end(), {option->get_name(), option->results().back()});
    return app::animateCommand(*a);
  };
}

Run defineList(CLI::App& command) {
  auto a = std::make_shared<app::ListArguments>();
  command.add_flag("--json", a->json, "As JSON");
  command.add_flag("--variations", a->variations,
                   "The flame variation catalogue (names, 2D/3D, parameters with defaults, formulas) instead");
  command.add_flag("--markdown", a->markdown, "With --variations: as Markdown (presets/VARIATIONS.md)");
  return [a] { return app::listCommand(*a); };
}

// The options `info` and `search` share: which attractor parameter set.
void addOrbitOptions(CLI::App& command, app::OrbitArguments& a) {
  command.add_option("preset", a.preset, "A preset: its first layer (a flame or quaternion Julia preset: its fill)")
      ->type_name("PRESET.json");
  command.add_option("--attractor", a.attractor, "An attractor of the catalogue (`voxflame list`) with its defaults")
      ->type_name("ID");
  command.add_option("--set", a.set, "One of the attractor's named parameter sets");
  command.add_option("--param", a.params, "Set one parameter; repeatable")
      ->type_name("NAME=VALUE")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
      ->allow_extra_args(false);
  addChoice(
      command, "--integrator", a.integrator, {core::Integrator::Euler, core::Integrator::RK4},
      [](core::Integrator i) { return core::toString(i); }, "Integrator of a flow");
  command.add_option("--step", a.step, "Integration step of a flow")->check(finite());
  command.add_flag("--json", a.json, "As JSON");
}

Run defineInfo(CLI::App& command) {
  auto a = std::make_shared<app::OrbitArguments>();
  addOrbitOptions(command, *a);
  return [a] { return app::infoCommand(*a); };
}

Run defineSearch(CLI::App& command) {
  auto a = std::make_shared<app::SearchArguments>();
  addOrbitOptions(command, a->orbit);
  command.add_option("--seed", a->seed, "Seed of the search")
      ->check(within<std::uint64_t>(0, std::uint64_t{1} << 53))
      ->capture_default_str();
  command.add_option("--count", a->count, "How many sets to find")->check(within(1, 1000))->capture_default_str();
  command.add_option("--strength", a->strength, "How far to move from the start")
      ->check(within(1e-6, 10.0))
      ->capture_default_str();
  command.add_flag("--random", a->random, "Flame and quaternion Julia presets: new random ones, not mutations");
  command.add_option("-o,--output", a->output, "Flame and quaternion Julia presets: write the best as a preset")
      ->type_name("OUT.json");
  command.footer(
      "On a flame or quaternion Julia preset: K mutations of it that fill their box (--random: new random\n"
      "ones), best first.");
  return [a] { return app::searchCommand(*a); };
}

Run defineMask(CLI::App& command) {
  auto a = std::make_shared<app::MaskArguments>();
  command.add_option("mesh", a->mesh, "The mesh file")->type_name("MESH");
  command.add_option("-o,--output", a->output, "The NRRD file to write (required)")->type_name("OUT.nrrd");
  command.add_option("--grid", a->grid, "Voxels along the mesh's longest axis")
      ->check(within(core::kMinGridResolution, core::kMaxGridResolution))
      ->capture_default_str();
  command.add_flag("--stats", a->stats, "Print triangles, grid, inside fraction and seconds");
  addChoice(command, "--method", a->method,
            {core::MaskMethod::WindingNumber, core::MaskMethod::ExactWindingNumber, core::MaskMethod::Parity},
            core::maskMethodName, "How inside is decided")
      ->default_str(core::maskMethodName(a->method));
  command.footer("The inside mask is written in the mesh's own coordinates.");
  return [a] { return app::maskCommand(*a); };
}

Run defineImport(CLI::App& command) {
  auto a = std::make_shared<app::ImportArguments>();
  command.add_option("flame", a->flameFile, "The flame file (flam3, Apophysis, Fractorium, JWildfire)")
      ->type_name("FILE.flame|FILE.flam3");
  command.add_option("-o,--output", a->output, "The preset to write (required)")->type_name("PRESET.json");
  command.add_option("--mesh", a->mesh, "The mesh to fill (default builtin:meshes/bunny.obj)");
  command.add_option("--depth", a->depth, "Depth a flat flame gains (0 keeps it flat)")
      ->check(within(0.0, core::kMaxFlameDepth))
      ->capture_default_str();
  command.add_option("--index", a->index, "Which flame of a file that holds several, from 1 (default the first)")
      ->check(within(1, 1'000'000));
  command.add_option("--name", a->name, "Which flame of a file that holds several, by name");
  command.footer(
      "Imports transforms, the variations voxflame knows (others are named in a warning), the final\n"
      "transform, symmetry, palette and tone.");
  return [a] { return app::importCommand(*a); };
}

Run defineBench(CLI::App& command) {
  auto options = std::make_shared<bench::BenchOptions>();
  auto which = std::make_shared<std::string>();
  std::vector<std::string> names;
  std::string list;
  for (const bench::Benchmark& benchmark : bench::benchmarks()) {
    names.emplace_back(benchmark.name);
    list += std::string("\n  ") + benchmark.name + ": " + benchmark.description;
  }
  command.add_option("benchmark", *which, "The benchmark to run (default: all)")->check(CLI::IsMember(names));
  command.add_option("--method", options->method, "The render method of `export` and `quality` (default: both)")
      ->check(CLI::IsMember(renderMethodNames()));
  command
      .add_option("--grid", options->grids,
                  "The grids `explorer` runs at (default: 192 256 512); `raymarch` runs only its cases at these grids "
                  "(256 and 512)")
      ->check(within(core::kMinGridResolution, core::kMaxGridResolution));
  command.add_option("presets", options->presets,
                     "`rest` and `view`: the presets to open (files, or shipped names such as default); default: every "
                     "shipped preset. `fidelity`: the flame files to compare with flam3-render");
  command.add_flag("--print", options->print,
                   "`export`: the 16K print instead (15360×8640, points method, 20 points a pixel), rendered by a "
                   "`voxflame render` of its own: seconds and peak resident memory");
  command
      .add_option("--backend", options->backend,
                  "The refinement backend to measure, cpu (the default) or gpu: `accumulate` runs the GPU backend "
                  "at 256³ and 512³; `explorer`, `rest` and `view` set the explorer's \"refine on\" to it")
      ->check(CLI::IsMember({"cpu", "gpu"}));
  command.add_flag("--json", options->json, "One JSON object a line");
  command.footer("Measure performance (Release build). The benchmarks:" + list);
  return [options, which] { return bench::runBenchmarks(*options, *which); };
}

// `voxflame help [SUBCOMMAND]`: the same as --help.
Run defineHelp(CLI::App& command) {
  auto topic = std::make_shared<std::optional<std::string>>();
  const CLI::App* root = command.get_parent();
  std::vector<std::string> names;
  for (const CLI::App* subcommand : root->get_subcommands({})) names.push_back(subcommand->get_name());
  command.add_option("subcommand", *topic, "The subcommand whose help to print")->check(CLI::IsMember(names));
  return [root, topic] {
    // root->help() would describe `help` itself, the subcommand this command line selected.
    const CLI::App* about = *topic ? root->get_subcommand(**topic) : nullptr;
    std::cout << (about ? about->help(root->get_name())
                        : root->get_formatter()->make_help(root, root->get_name(), CLI::AppFormatMode::Normal));
    return 0;
  };
}

// `voxflame __import-mesh -- FILE NAME`: the child process that imports a mesh for its parent
// (core/mesh.h); NAME is what its messages call the mesh.
Run defineMeshImportChild(CLI::App& command) {
  auto file = std::make_shared<std::string>();
  auto name = std::make_shared<std::string>();
  command.add_option("file", *file, "The mesh file")->required();
  command.add_option("name", *name, "What messages call the mesh")->required();
  return [file, name]() -> int { core::runMeshImportChild(*file, *name); };
}

constexpr bool kHidden = true;

// The subcommands, in the order --help lists them. A hidden one (for voxflame's own use, e.g. a
// child process it starts) is one more line with kHidden: it parses as any other but --help
// leaves it out (CLI11's empty group).
struct Subcommand {
  const char* name;
  const char* summary;  // the line `voxflame --help` shows
  Run (*define)(CLI::App& command);
  bool hidden = false;
};
const Subcommand kSubcommands[] = {
    {"render", "Render a still headless to PNG or EXR, or the volume to VDB or NRRD", &defineRender},
    {"animate", "Render a keyframed animation to PNG frames, or a Slurm farm job for it", &defineAnimate},
    {"list", "The attractor catalogue, or the flame variation catalogue", &defineList},
    {"info", "Boundedness, Lyapunov exponents and dimension of one parameter set; a flame's fill", &defineInfo},
    {"search", "Find nearby parameter sets that are bounded, chaotic and fill a volume", &defineSearch},
    {"mask", "Write a mesh's inside mask as an NRRD volume", &defineMask},
    {"import", "Turn a flame file into a preset", &defineImport},
    {"bench", "Measure performance", &defineBench},
    {"help", "Print the help of voxflame or of one subcommand", &defineHelp, kHidden},
    {core::kMeshImportSubcommand, "Import a mesh for the parent process", &defineMeshImportChild, kHidden},
};

class CommandLine {
 public:
  CommandLine() : root_("voxflame — strange attractors filling the volume of a mesh", "voxflame") {
    // An option given twice keeps its last value; a repeatable one says so itself.
    root_.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
    root_.set_version_flag("--version", std::string("voxflame ") + app::kVersion);
    root_.require_subcommand(0, 1);
    for (const Subcommand& subcommand : kSubcommands) {
      CLI::App* command = root_.add_subcommand(subcommand.name, subcommand.summary);
      if (subcommand.hidden) command->group("");
      commands_.emplace_back(command, subcommand.define(*command));
    }
    explorer_ = defineExplorer(root_);
  }

  // Throws CLI::ParseError (also for --help and --version, exit code 0) or UsageError.
  void parse(const std::vector<std::string>& args) {
    root_.parse(std::vector<std::string>(args.rbegin(), args.rend() - (args.empty() ? 0 : 1)));
    const CLI::App* chosen = command();
    if (!chosen) return;
    // `voxflame --width 800 render ...`: the explorer's options do not reach the subcommand.
    for (const CLI::Option* option : root_.get_options())
      if (option->count() > 0)
        throw UsageError(
            std::string(option->get_positional() ? "'" + option->as<std::string>() + "'" : option->get_name()) +
            " goes with the explorer, not with " + chosen->get_name() +
            "; put the subcommand first and its options after it");
  }

  // The subcommand chosen, or nullptr for the explorer.
  const CLI::App* command() const {
    const auto chosen = root_.get_subcommands();
    return chosen.empty() ? nullptr : chosen.front();
  }

  int run() const {
    const CLI::App* chosen = command();
    for (const auto& [subcommand, runSubcommand] : commands_)
      if (subcommand == chosen) return runSubcommand();
    return explorer_();
  }

  // A parse error as one line: unknown options and extra arguments by name.
  std::string message(const CLI::ParseError& error) const {
    if (dynamic_cast<const CLI::ExtrasError*>(&error)) {
      const CLI::App* chosen = command();
      const std::vector<std::string> extras = (chosen ? *chosen : root_).remaining();
      for (const std::string& extra : extras)
        if (extra.size() > 1 && extra[0] == '-') return "unknown option " + extra.substr(0, extra.find('='));
      if (!extras.empty()) return "unexpected argument '" + extras.front() + "'";
    }
    return error.what();
  }

  // Where to read about what went wrong.
  std::string helpPointer() const {
    const CLI::App* chosen = command();
    return "see 'voxflame " + (chosen ? chosen->get_name() + " " : std::string()) + "--help'";
  }

  int exit(const CLI::ParseError& success) { return root_.exit(success); }

 private:
  CLI::App root_;
  Run explorer_;
  std::vector<std::pair<const CLI::App*, Run>> commands_;
};

int usageError(const CommandLine& line, const std::string& message) {
  std::cerr << "voxflame: " << message << "\n" << line.helpPointer() << "\n";
  return 2;
}

}  // namespace

int runCommandLine(const std::vector<std::string>& args) {
  CommandLine line;
  try {
    line.parse(args);
    return line.run();
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == static_cast<int>(CLI::ExitCodes::Success)) return line.exit(e);  // --help, --version
    return usageError(line, line.message(e));
  } catch (const UsageError& e) {
    return usageError(line, e.what());
  } catch (const core::Error& e) {
    std::cerr << "voxflame: " << e.what() << "\n";
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "voxflame: out of memory; try a smaller grid or image\n";
    return 1;
  }
}

std::string usageErrorOf(const std::vector<std::string>& args) {
  CommandLine line;
  try {
    line.parse(args);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() != static_cast<int>(CLI::ExitCodes::Success)) return line.message(e);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

}  // namespace voxflame::cli
