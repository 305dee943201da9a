// `voxflame animate --farm slurm`: an animation rendered by a Slurm array job. Each task renders
// one contiguous range of frames with `voxflame animate --frames A-B`; since animate locks every
// layer's fit to time 0 of the whole animation and renders every frame with the preset's seed,
// the frames are the same files one local run would write. A second job, started when every task
// has ended, checks that each frame exists (`voxflame animate --status`) and encodes the video.
//
// The job scripts go beside the frames (farm-render.sbatch, farm-finish.sbatch); the render
// script records the frames and tasks on a `# voxflame-farm` line, so --status can name the tasks
// to run again.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "frame_pattern.h"

namespace voxflame::app {

// The range split into `tasks` contiguous, ordered ranges whose sizes differ by at most one (the
// larger ones first); fewer when there are fewer frames than tasks. tasks must be at least 1.
std::vector<FrameRange> splitFrames(const FrameRange& frames, int tasks);

struct FarmJob {
  std::string binary;                     // absolute path of voxflame on the nodes
  std::string workingDirectory;           // where the jobs run (absolute); other paths are relative to it
  std::optional<std::string> preset;      // as given on the command line; none: the built-in default
  std::string pattern;                    // the frames' printf pattern
  FrameRange frames;                      // every frame the job renders
  int tasks = 1;                          // array tasks asked for (splitFrames may use fewer)
  std::string partition;                  // "" for the cluster's default
  std::vector<std::string> options;       // further animate options for each task (--width 640 ...)
  std::vector<std::string> videoCommand;  // the ffmpeg command of --video; empty without --video
  // A still split into chunks (`render --farm slurm`) instead of frames: the tasks run
  // `voxflame render ... --chunk-range A-B` into the checkpoint folder, which holds the scripts.
  std::string subcommand = "animate";
  std::string rangeOption = "--frames";
  std::string what = "frames";
  std::filesystem::path folder;              // the scripts' and logs' folder (empty: the frames')
  std::vector<std::string> statusArguments;  // the finish job's check after the subcommand (empty: frames')
  std::vector<std::string> finishCommand;    // the finish job's last command (a still: the sum), or empty
};

// Exit status when the farm's job scripts were written but could not be submitted (no sbatch).
inline constexpr int kFarmNotSubmittedStatus = 3;

// A partition name goes into a #SBATCH line: throws UsageError unless it is one word of the
// characters Slurm allows.
void checkPartition(const std::string& partition);

// Writes the job scripts (and submits them with sbatch when `submit`): the render array job, then
// the finish job to start when every task has ended. Returns the command's exit status.
int writeFarmJob(const FarmJob& job, bool submit);

// The job scripts' paths: in the folder of the frames (of frame 0, should the folder hold the number).
std::filesystem::path renderScriptPath(const FarmJob& job);
std::filesystem::path finishScriptPath(const FarmJob& job);

// The array job: task i renders splitFrames(job.frames, job.tasks)[i].
std::string renderJobScript(const FarmJob& job);
// The job run after the array job (sbatch --dependency=afterany:ID): --status, then the video.
std::string finishJobScript(const FarmJob& job);

// What a render script records about itself: the frames and how many tasks split them.
struct FarmRecord {
  FrameRange frames;
  int tasks = 1;
};
// The record of the render script in the pattern's folder, if there is one that reads.
std::optional<FarmRecord> readFarmRecord(const std::filesystem::path& renderScript);

// Prints "render them again with: sbatch --array=TASKS SCRIPT" for the tasks of `record` whose
// ranges hold one of `missing` (frames or chunks); nothing when none does.
void printRerunAdvice(const FarmRecord& record, const std::vector<int>& missing,
                      const std::filesystem::path& renderScript);

}  // namespace voxflame::app
