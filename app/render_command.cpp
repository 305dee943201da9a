// `voxflame render`: a still, headless, to PNG or EXR, or the accumulated volume to VDB or NRRD;
// and the helpers the subcommands share (their file argument, Ctrl-C, durations).
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>

#include <cctype>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

#include "commands.h"
#include "core/chunk_io.h"
#include "core/chunk_sums.h"
#include "core/error.h"
#include "core/flame/flat_render.h"
#include "core/image_io.h"
#include "core/keyframes.h"
#include "core/scene_io.h"
#include "core/volume_export.h"
#include "farm_job.h"
#include "frame_pattern.h"
#include "pipeline.h"
#include "programs.h"
#include "progress_pipe.h"
#include "usage_error.h"

namespace voxflame::app {

core::Scene sceneFromArgument(const std::optional<std::string>& file) {
  return file ? sceneFromFile(*file) : core::defaultScene();
}

namespace {

constexpr int kDefaultChunks = 64;

std::atomic<bool> gInterrupted{false};
extern "C" void onInterrupt(int) {
  gInterrupted.store(true);
}

}  // namespace

const std::atomic<bool>& catchInterrupts() {
  gInterrupted = false;
  struct sigaction action {};
  action.sa_handler = onInterrupt;
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
  return gInterrupted;
}

std::string formatDuration(double seconds) {
  char text[32];
  if (seconds >= 3600.0)
    std::snprintf(text, sizeof text, "%dh%02dm", static_cast<int>(seconds / 3600.0),
                  static_cast<int>(seconds / 60.0) % 60);
  else if (seconds >= 60.0)
    std::snprintf(text, sizeof text, "%dm%02ds", static_cast<int>(seconds / 60.0), static_cast<int>(seconds) % 60);
  else
    std::snprintf(text, sizeof text, "%.0fs", seconds);
  return text;
}

namespace {

// `render -o OUT.vdb|OUT.nrrd`: accumulates as for a still and writes the grid instead of an image.
int writeVolume(const core::Scene& scene, const StillOptions& options, const std::string& output, bool vdb,
                bool interactive) {
  AccumulatedVolume volume;
  try {
    const SceneShape shape = buildSceneShape(scene);
    volume = accumulateVolume(scene, shape, options);
  } catch (const RenderCancelled&) {
    if (interactive) std::fprintf(stderr, "\n");
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  if (interactive) std::fprintf(stderr, "\n");
  if (!volume.warning.empty()) std::cerr << "voxflame: warning: " << volume.warning << "\n";
  StillResult stats;
  stats.stats = volume.stats;
  const std::string preset = stillMetadata(scene, stats).at(kPresetChunkKey);
  const auto start = std::chrono::steady_clock::now();
  if (vdb)
    core::writeVdbVolume(output, volume.snapshot, preset);
  else
    core::writeNrrdVolume(output, volume.snapshot, preset);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t active = 0;
  for (float hits : volume.snapshot.density) active += hits > 0.0f;
  const glm::ivec3 size = volume.snapshot.geometry.size;
  std::printf("wrote %s (%d×%d×%d voxels, %zu with density, %llu points inside, %.2f s accumulating, %.2f s writing)\n",
              output.c_str(), size.x, size.y, size.z, active, static_cast<unsigned long long>(volume.stats.points),
              volume.seconds, seconds);
  return 0;
}

// `render --flat`: the flame layer in 2D, framed as flam3 frames it (core/flame/flat_render.h).
int renderFlatCommand(const RenderArguments& arguments, const std::string& output) {
  if (std::filesystem::path(output).extension() != ".png")
    throw UsageError("render --flat writes a PNG: -o OUT.png, not '" + output + "'");
  if (arguments.method || arguments.samples || arguments.grid || arguments.points || arguments.untilNoisePercent ||
      arguments.oversample || arguments.cameraAzimuthDeg || arguments.cameraElevationDeg)
    throw UsageError(
        "render --flat has no mesh, camera or grid: leave out --method, --samples, --points, --grid, --until-noise, "
        "--oversample and the camera options");
  core::Scene scene = sceneFromArgument(arguments.preset);
  scene = core::sceneAtTime(scene, arguments.time.value_or(scene.animation.time));
  core::FlatRenderOptions options;
  options.width = arguments.widthGiven ? arguments.width : 0;
  options.height = arguments.heightGiven ? arguments.height : 0;
  options.quality = arguments.quality;
  options.seed = arguments.seed;
  options.bitDepth = arguments.bitDepth;
  options.cancel = &catchInterrupts();
  const auto start = std::chrono::steady_clock::now();
  core::FlatRenderResult result;
  try {
    result = core::renderFlat(scene, options);
  } catch (const core::FlatRenderCancelled&) {
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  core::writePng(output, result.image, arguments.bitDepth, {{kPresetChunkKey, core::sceneToJson(scene)}});
  std::printf("wrote %s (%d×%d, flat, quality %g, %llu samples, %.2f s)\n", output.c_str(), result.image.width,
              result.image.height, result.quality, static_cast<unsigned long long>(result.samples), seconds);
  return 0;
}

// ---------------------------------------------------------------------------------------------
// Chunks and checkpoints (pipeline.h ChunkPlan): a folder holds chunk-NNNN.exr (the points
// method's screen sums) or chunk-NNNN.vdb (the volume method's grid sums), each labelled with the
// preset, the size and the chunk count it belongs to.

std::filesystem::path defaultCheckpoint(const std::string& output) {
  return output + ".chunks";
}

std::filesystem::path chunkPath(const std::filesystem::path& folder, int chunk, const char* extension) {
  char name[32];
  std::snprintf(name, sizeof name, "chunk-%04d%s", chunk, extension);
  return folder / name;
}

// "A-B" or "N" of chunks 0..chunks-1.
FrameRange parseChunkRange(const std::string& text, int chunks) {
  const auto number = [&](const std::string& part) {
    if (part.empty() || part.size() > 9 ||
        !std::all_of(part.begin(), part.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      throw UsageError("--chunk-range expects A-B or N (chunk numbers from 0), not '" + text + "'");
    return std::stoi(part);
  };
  const std::size_t dash = text.find('-');
  FrameRange range;
  range.first = number(text.substr(0, dash));
  range.last = dash == std::string::npos ? range.first : number(text.substr(dash + 1));
  if (range.first > range.last) throw UsageError("--chunk-range " + text + ": the first chunk comes after the last");
  if (range.last >= chunks)
    throw UsageError("--chunk-range " + text + ": the render has " + std::to_string(chunks) + " chunks (0-" +
                     std::to_string(chunks - 1) + ")");
  return range;
}

// The chunk files a folder holds, by index (either kind).
std::vector<std::pair<int, std::filesystem::path>> chunkFiles(const std::filesystem::path& folder) {
  std::vector<std::pair<int, std::filesystem::path>> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(folder, ec)) {
    const std::string name = entry.path().filename().string();
    const std::string extension = entry.path().extension().string();
    if (name.rfind("chunk-", 0) != 0 || (extension != ".exr" && extension != ".vdb")) continue;
    const std::string digits = name.substr(6, name.size() - 6 - extension.size());
    if (digits.empty() || digits.size() > 9 ||
        !std::all_of(digits.begin(), digits.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      continue;
    files.emplace_back(std::stoi(digits), entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

// `render --status OUT`: the chunks missing from OUT's checkpoint folder, and the farm tasks that
// render them again.
int chunkStatus(const RenderArguments& arguments) {
  const std::string& output = *arguments.statusOutput;
  const std::filesystem::path folder =
      arguments.checkpoint ? std::filesystem::path(*arguments.checkpoint) : defaultCheckpoint(output);
  const std::filesystem::path renderScript = folder / "farm-render.sbatch";
  const std::optional<FarmRecord> record = readFarmRecord(renderScript);
  int chunks = 0;
  if (arguments.chunks)
    chunks = *arguments.chunks;
  else if (record)
    chunks = record->frames.last + 1;
  else
    throw UsageError("--status needs to know how many chunks to expect: give --chunks K (no farm job is recorded in '" +
                     folder.string() + "')");
  std::vector<bool> present(static_cast<std::size_t>(chunks), false);
  for (const auto& [chunk, path] : chunkFiles(folder))
    if (chunk < chunks) present[static_cast<std::size_t>(chunk)] = true;
  std::vector<int> missing;
  for (int chunk = 0; chunk < chunks; ++chunk)
    if (!present[static_cast<std::size_t>(chunk)]) missing.push_back(chunk);
  if (missing.empty()) {
    std::printf("%s: all %d chunks are in %s\n", output.c_str(), chunks, folder.c_str());
    return 0;
  }
  std::printf("%s: %d of %d chunks are in %s; missing %zu: %s\n", output.c_str(),
              chunks - static_cast<int>(missing.size()), chunks, folder.c_str(), missing.size(),
              describeFrames(missing).c_str());
  if (record) printRerunAdvice(*record, missing, renderScript);
  return 1;
}

// Reads what a checkpoint folder holds for this render into `plan` (the chunks to render, the sums of
// those already there) and makes the plan write each new chunk there. Refuses, naming the file and
// what differs, a folder that holds chunks of another render.
struct Checkpoint {
  std::filesystem::path folder;
  core::ChunkLabel label;
  bool points = false;
  std::vector<int> present;
  core::GridSums earlierGrid;
  core::ImageSums earlierImage;
};

void openCheckpoint(Checkpoint& checkpoint, ChunkPlan& plan, const std::optional<FrameRange>& range) {
  const char* extension = checkpoint.points ? ".exr" : ".vdb";
  std::error_code ec;
  std::filesystem::create_directories(checkpoint.folder, ec);
  if (ec)
    throw core::Error("cannot create the checkpoint folder '" + checkpoint.folder.string() + "': " + ec.message());
  std::vector<bool> present(static_cast<std::size_t>(plan.chunks), false);
  for (const auto& [chunk, path] : chunkFiles(checkpoint.folder)) {
    if (path.extension() != extension)
      throw core::Error("'" + path.string() + "' belongs to another render: it is a chunk of the " +
                        (checkpoint.points ? "volume" : "points") + " method, this render uses the " +
                        (checkpoint.points ? "points" : "volume") +
                        " method. Use another --checkpoint folder, or delete this one to start again");
    const core::ChunkLabel found = core::readChunkLabel(path);
    const std::string difference = core::describeLabelDifference(checkpoint.label, found);
    if (!difference.empty())
      throw core::Error("'" + path.string() + "' belongs to another render: " + difference +
                        ". Use another --checkpoint folder, or delete this one to start again");
    if (found.chunk != chunk || chunk >= plan.chunks)
      throw core::Error("'" + path.string() + "' says it is chunk " + std::to_string(found.chunk) + " of " +
                        std::to_string(found.chunks) + "; its name says otherwise");
    present[static_cast<std::size_t>(chunk)] = true;
    checkpoint.present.push_back(chunk);
  }
  plan.render.emplace();
  const FrameRange all{0, plan.chunks - 1};
  const FrameRange wanted = range.value_or(all);
  for (int chunk = wanted.first; chunk <= wanted.last; ++chunk)
    if (!present[static_cast<std::size_t>(chunk)]) plan.render->push_back(chunk);
  plan.finish = !range;
  if (plan.finish && !checkpoint.present.empty()) {
    // The finished chunks' sums, added in chunk order (integers: any order gives the same).
    bool first = true;
    for (int chunk : checkpoint.present) {
      core::ChunkLabel label;
      const std::filesystem::path path = chunkPath(checkpoint.folder, chunk, extension);
      if (checkpoint.points) {
        core::ImageSums sums = core::readImageChunk(path, label);
        if (first)
          checkpoint.earlierImage = std::move(sums);
        else
          checkpoint.earlierImage.add(sums);
      } else {
        core::GridSums sums = core::readGridChunk(path, label);
        if (first)
          checkpoint.earlierGrid = std::move(sums);
        else
          checkpoint.earlierGrid.add(sums);
      }
      first = false;
    }
    if (checkpoint.points)
      plan.earlierImage = &checkpoint.earlierImage;
    else
      plan.earlierGrid = &checkpoint.earlierGrid;
  }
  // Each chunk is written as it finishes (through a temporary file, so Ctrl-C never leaves half
  // of one): whatever stops the render, the finished chunks stay.
  Checkpoint* state = &checkpoint;
  if (checkpoint.points)
    plan.imageDone = [state](int chunk, const core::ImageSums& sums) {
      core::ChunkLabel label = state->label;
      label.chunk = chunk;
      core::writeImageChunk(chunkPath(state->folder, chunk, ".exr"), sums, label);
    };
  else
    plan.gridDone = [state](int chunk, const core::GridSums& sums) {
      core::ChunkLabel label = state->label;
      label.chunk = chunk;
      core::writeGridChunk(chunkPath(state->folder, chunk, ".vdb"), sums, label);
    };
}

// `render --farm slurm`: the array job renders ranges of chunks into the checkpoint folder, the
// finish job checks them all and sums them into the image.
int writeStillFarmJob(const RenderArguments& arguments, int chunks, const std::filesystem::path& folder) {
  if (!arguments.output) throw UsageError("--farm needs the image to make: -o OUT.png or OUT.exr");
  FarmJob job;
  job.binary = currentExecutable();
  job.workingDirectory = std::filesystem::current_path().string();
  job.preset = arguments.preset;
  job.pattern = *arguments.output;
  job.frames = {0, chunks - 1};
  job.tasks = arguments.tasks.value_or(1);
  job.partition = arguments.partition.value_or("");
  job.subcommand = "render";
  job.rangeOption = "--chunk-range";
  job.what = "chunks";
  job.folder = folder;
  job.options = arguments.taskOptions;
  job.options.insert(job.options.end(), {"--chunks", std::to_string(chunks), "--checkpoint", folder.string()});
  job.statusArguments = {"--status", *arguments.output, "--checkpoint", folder.string()};
  job.finishCommand = {job.binary, "render"};
  if (job.preset) job.finishCommand.push_back(*job.preset);
  job.finishCommand.insert(job.finishCommand.end(), {"-o", *arguments.output});
  job.finishCommand.insert(job.finishCommand.end(), job.options.begin(), job.options.end());
  std::error_code ec;
  std::filesystem::create_directories(folder, ec);
  if (ec) throw core::Error("cannot create the checkpoint folder '" + folder.string() + "': " + ec.message());
  return writeFarmJob(job, arguments.submit);
}

}  // namespace

int renderCommand(const RenderArguments& arguments) {
  checkProgressFd(arguments.progressFd);
  if (arguments.statusOutput) {
    if (arguments.output || arguments.farm || arguments.chunkRange)
      throw UsageError("--status takes the image itself (--status OUT.png); leave out -o, --farm and --chunk-range");
    return chunkStatus(arguments);
  }
  if (!arguments.farm && (arguments.tasks || arguments.partition || arguments.submit))
    throw UsageError("--tasks, --partition and --submit go with --farm slurm");
  if (arguments.partition) checkPartition(*arguments.partition);
  if (arguments.chunkRange && !arguments.checkpoint)
    throw UsageError("--chunk-range renders chunks into a checkpoint folder: give --checkpoint DIR");
  if (arguments.chunkRange && arguments.farm)
    throw UsageError("--chunk-range is what a farm task runs; leave out --farm");
  if (!arguments.output) throw UsageError("render needs an output file: -o OUT.png, OUT.exr, OUT.vdb or OUT.nrrd");
  const bool chunkOptions = arguments.chunks || arguments.checkpoint || arguments.chunkRange || arguments.farm;
  if (arguments.flat) {
    if (chunkOptions)
      throw UsageError("render --flat is not split into chunks: leave out --chunks, --checkpoint and --farm");
    return renderFlatCommand(arguments, *arguments.output);
  }
  if (arguments.quality) throw UsageError("--quality is an option of render --flat");
  const std::string& output = *arguments.output;
  const std::string extension = std::filesystem::path(output).extension().string();
  const bool volumeOutput = extension == ".vdb" || extension == ".nrrd";
  if (extension != ".png" && extension != ".exr" && !volumeOutput)
    throw UsageError("output '" + output + "' must end in .png or .exr (an image) or .vdb or .nrrd (the volume)");
  StillOptions options;
  options.width = arguments.width;
  options.height = arguments.height;
  options.points = arguments.points;
  options.threads = arguments.threads;
  if (static_cast<double>(options.width) * options.height > 1.5e9)
    throw core::Error("an image of " + std::to_string(options.width) + "×" + std::to_string(options.height) +
                      " pixels is too large to hold in memory");

  // Command-line settings go into the scene, so the preset stored in the image reproduces it.
  core::Scene scene = sceneFromArgument(arguments.preset);
  // An animated preset renders the moment it names (a rendered frame stores its own time).
  scene = core::sceneAtTime(scene, arguments.time.value_or(scene.animation.time));
  if (options.points) scene.points = options.points;
  if (arguments.untilNoisePercent) options.untilNoise = 0.01 * *arguments.untilNoisePercent;
  if (arguments.samples) scene.render.samples = *arguments.samples;
  if (arguments.grid) scene.gridResolution = *arguments.grid;
  if (arguments.cameraAzimuthDeg) scene.camera.azimuthDeg = *arguments.cameraAzimuthDeg;
  if (arguments.cameraElevationDeg) scene.camera.elevationDeg = *arguments.cameraElevationDeg;
  if (arguments.method) scene.render.method = *arguments.method;
  if (arguments.oversample) scene.render.oversample = *arguments.oversample;
  if (options.untilNoise > 0.0 && scene.render.method == core::RenderMethod::Points)
    throw UsageError("--until-noise measures the voxel grid, which the points method does not show: use --points");
  if (options.untilNoise > 0.0 && chunkOptions)
    throw UsageError(
        "--until-noise stops when the grid is smooth enough, so its points are not known in advance to split into "
        "chunks: leave out --chunks, --checkpoint and --farm, or give --points");
  if ((arguments.checkpoint || arguments.farm) && volumeOutput)
    throw UsageError("--checkpoint and --farm make an image (OUT.png or OUT.exr), not a volume file");
  options.linearOutput = extension == ".exr";
  // Render exactly what the image will store: values pass through their JSON form first (colours
  // become hex), so rendering the image's preset again gives the same pixels.
  const bool embedded = scene.embedded;
  const std::filesystem::path baseDirectory = scene.baseDirectory;
  scene = core::sceneFromJson(core::sceneToJson(scene), "(command line)");
  scene.embedded = embedded;
  scene.baseDirectory = baseDirectory;
  options.backend = resolveBackend(arguments.backend, scene.layers);

  // Every still but one with a noise target is split into chunks: one code path, whether it runs
  // here at once, is resumed, or is spread over a farm.
  std::optional<Checkpoint> checkpoint;
  std::atomic<int> chunksDone{0};
  int chunksHere = 0;
  if (options.untilNoise <= 0.0) {
    ChunkPlan plan;
    plan.chunks = arguments.chunks.value_or(kDefaultChunks);
    const std::filesystem::path folder =
        arguments.checkpoint ? std::filesystem::path(*arguments.checkpoint) : defaultCheckpoint(output);
    if (arguments.farm) return writeStillFarmJob(arguments, plan.chunks, folder);
    if (arguments.checkpoint) {
      checkpoint.emplace();
      checkpoint->folder = folder;
      checkpoint->points = scene.render.method == core::RenderMethod::Points;
      checkpoint->label = {core::sceneToJson(scene), options.width, options.height, 0, plan.chunks};
      checkpoint->label.backend = std::string(core::toString(options.backend));
      std::optional<FrameRange> range;
      if (arguments.chunkRange) range = parseChunkRange(*arguments.chunkRange, plan.chunks);
      openCheckpoint(*checkpoint, plan, range);
      if (!checkpoint->present.empty())
        std::printf("%s holds %zu of the %d chunks; rendering %zu more\n", folder.c_str(), checkpoint->present.size(),
                    plan.chunks, plan.render->size());
      if (!plan.finish && plan.render->empty()) {
        std::printf("chunks %s are all in %s already\n", arguments.chunkRange->c_str(), folder.c_str());
        return 0;
      }
      chunksHere = static_cast<int>(plan.render->size());
    } else {
      chunksHere = plan.chunks;
    }
    plan.progress = [&chunksDone](int done) { chunksDone = done; };
    options.chunks = std::move(plan);
  }

  options.cancel = &catchInterrupts();
  const bool interactive = isatty(fileno(stderr));
  options.progress = [interactive, &chunksDone, chunksHere](const core::AccumulatorStats& stats, std::uint64_t target) {
    if (!interactive) return;
    const double done =
        target ? static_cast<double>(std::min(stats.points, target)) / static_cast<double>(target) : 0.0;
    const double insideRate = stats.pointsPerSecond * stats.insideFraction();
    const double left =
        insideRate > 0.0 ? static_cast<double>(target - std::min(stats.points, target)) / insideRate : 0.0;
    if (chunksHere > 0)
      std::fprintf(stderr, "\rchunk %d of %d  accumulating %5.1f%%  %6.1f M points/s  %s left   ",
                   std::min(chunksDone.load() + 1, chunksHere), chunksHere, 100.0 * done, stats.pointsPerSecond * 1e-6,
                   formatDuration(left).c_str());
    else
      std::fprintf(stderr, "\raccumulating %5.1f%%  %6.1f M points/s  %s left   ", 100.0 * done,
                   stats.pointsPerSecond * 1e-6, formatDuration(left).c_str());
    std::fflush(stderr);
  };
  ProgressPipe progressPipe(arguments.progressFd, gInterrupted);
  if (progressPipe.active())
    options.stage = [&progressPipe](StillStage stage, double fraction) {
      progressPipe.report(toString(stage), fraction);
    };
  if (volumeOutput) return writeVolume(scene, options, output, extension == ".vdb", interactive);
  StillResult result;
  try {
    result = renderStill(scene, options);
  } catch (const RenderCancelled&) {
    if (interactive) std::fprintf(stderr, "\n");
    if (checkpoint)
      std::cerr << "voxflame: interrupted; the finished chunks are kept in " << checkpoint->folder.string()
                << ": run the same command again to go on\n";
    else
      std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  if (options.chunks && !options.chunks->finish) {
    if (interactive) std::fprintf(stderr, "\n");
    std::printf("rendered chunks %s into %s (%.2f s)\n", arguments.chunkRange->c_str(), checkpoint->folder.c_str(),
                result.accumulateSeconds + result.renderSeconds);
    return 0;
  }
  if (interactive) std::fprintf(stderr, "\n");
  if (!result.warning.empty()) std::cerr << "voxflame: warning: " << result.warning << "\n";
  // The stored preset reproduces the image with the count the noise target came to.
  if (options.untilNoise > 0.0) scene.points = std::max<std::uint64_t>(result.stats.points, 1);
  progressPipe.report("writing", 0.0);
  if (gInterrupted) {
    std::cerr << "voxflame: interrupted; nothing was written\n";
    return 130;
  }
  // A still split into chunks is the same file wherever and however it was rendered: its
  // statistics leave out the times (they are printed below).
  const bool withTimes = !options.chunks;
  if (options.linearOutput)
    core::writeExr(output, result.image, stillMetadata(scene, result, withTimes));
  else
    core::writePng(output, result.image, arguments.bitDepth, stillMetadata(scene, result, withTimes));
  // The points method's own count is what the image shows; its grid (for depth) took fewer.
  const std::uint64_t shown = result.pointsProjected ? result.pointsProjected : result.stats.points;
  std::printf(
      "wrote %s (%d×%d, %s method, %d samples, %llu points inside, pattern covers %.0f%% of the mesh, %.2f s "
      "accumulating on the %s backend%s, %.2f s rendering on %s)\n",
      output.c_str(), options.width, options.height, std::string(core::toString(scene.render.method)).c_str(),
      scene.render.samples, static_cast<unsigned long long>(shown), 100.0 * result.coverage, result.accumulateSeconds,
      std::string(core::toString(result.backend)).c_str(), result.gridOnDevice ? " (the grid kept on the GPU)" : "",
      result.renderSeconds, result.renderer.c_str());
  if (arguments.stats) std::printf("stats %s\n", stillMetadata(scene, result).at("voxflame:stats").c_str());
  if (checkpoint)
    std::printf("the chunks stay in %s; delete it when the image is what you want\n", checkpoint->folder.c_str());
  // The image is complete on disk: an interruption that came too late to stop it is not a failure.
  return 0;
}

}  // namespace voxflame::app
