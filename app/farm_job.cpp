#include "farm_job.h"

#include <fstream>
#include <sstream>

#include "programs.h"

namespace voxflame::app {

namespace {

constexpr const char* kRecordPrefix = "# voxflame-farm frames=";

std::filesystem::path scriptFolder(const FarmJob& job) {
  return frameFolder(job.pattern, 0);
}

// Slurm expands %j, %A, %a ... in --output paths and has no escape for a literal %, so the logs of
// frames in a folder with % in its name go to the working directory instead.
std::string logPath(const FarmJob& job, const std::string& name) {
  const std::string folder = scriptFolder(job).string();
  if (folder.empty() || folder.find('%') != std::string::npos) return name;
  return (std::filesystem::path(folder) / name).string();
}

std::string header(const FarmJob& job, const std::string& name, const std::string& log) {
  std::string text = "#SBATCH --job-name=" + name + "\n";
  if (!job.partition.empty()) text += "#SBATCH --partition=" + job.partition + "\n";
  text += "#SBATCH --chdir=" + job.workingDirectory + "\n";
  text += "#SBATCH --output=" + log + "\n";
  text += "#SBATCH --ntasks=1\n";
  return text;
}

std::vector<std::string> animateCommand(const FarmJob& job) {
  std::vector<std::string> command = {job.binary, "animate"};
  if (job.preset) command.push_back(*job.preset);
  return command;
}

}  // namespace

std::vector<FrameRange> splitFrames(const FrameRange& frames, int tasks) {
  const int count = frames.count();
  const int used = std::max(1, std::min(tasks, count));
  std::vector<FrameRange> ranges;
  int first = frames.first;
  for (int i = 0; i < used; ++i) {
    const int size = count / used + (i < count % used ? 1 : 0);
    ranges.push_back({first, first + size - 1});
    first += size;
  }
  return ranges;
}

std::filesystem::path renderScriptPath(const FarmJob& job) {
  return scriptFolder(job) / "farm-render.sbatch";
}

std::filesystem::path finishScriptPath(const FarmJob& job) {
  return scriptFolder(job) / "farm-finish.sbatch";
}

std::string renderJobScript(const FarmJob& job) {
  const std::vector<FrameRange> ranges = splitFrames(job.frames, job.tasks);
  const int tasks = static_cast<int>(ranges.size());
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by voxflame animate --farm slurm. Each of the " << tasks << " array tasks renders one\n"
    << "# contiguous range of frames " << job.frames.first << "-" << job.frames.last
    << " with the same fit (locked to time 0) and the preset's seed,\n"
    << "# so the frames are the files one local run would write. Re-run a failed task alone with\n"
    << "# sbatch --array=TASK " << renderScriptPath(job).string()
    << " (voxflame animate --status lists the missing frames).\n"
    << header(job, "voxflame-render", logPath(job, "farm-render-%A_%a.log")) << "#SBATCH --array=0-" << tasks - 1
    << "\n"
    << kRecordPrefix << job.frames.first << "-" << job.frames.last << " tasks=" << tasks << "\n"
    << "set -euo pipefail\n"
    << "ranges=(";
  for (int i = 0; i < tasks; ++i)
    s << (i ? " " : "") << ranges[static_cast<std::size_t>(i)].first << "-" << ranges[static_cast<std::size_t>(i)].last;
  std::vector<std::string> command = animateCommand(job);
  command.insert(command.end(), {"-o", job.pattern});
  command.insert(command.end(), job.options.begin(), job.options.end());
  s << ")\n"
    << "task=\"${SLURM_ARRAY_TASK_ID:?this script runs as a Slurm array task (sbatch --array)}\"\n"
    << "exec " << shellQuoted(command) << " --frames \"${ranges[$task]}\"\n";
  return s.str();
}

std::string finishJobScript(const FarmJob& job) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by voxflame animate --farm slurm: runs when every task of the render job has ended\n"
    << "# (sbatch --dependency=afterany:JOB), checks that every frame exists";
  s << (job.videoCommand.empty() ? ".\n" : " and encodes the video.\n")
    << header(job, "voxflame-finish", logPath(job, "farm-finish-%j.log")) << "set -euo pipefail\n";
  std::vector<std::string> status = animateCommand(job);
  status.insert(status.end(), {"--status", job.pattern, "--frames",
                               std::to_string(job.frames.first) + "-" + std::to_string(job.frames.last)});
  // The frame numbers of the range depend on the rate.
  for (std::size_t i = 0; i + 1 < job.options.size(); ++i)
    if (job.options[i] == "--fps") status.insert(status.end(), {"--fps", job.options[i + 1]});
  s << shellQuoted(status) << "\n";
  if (!job.videoCommand.empty()) {
    const std::string video = shellQuoted(job.videoCommand);
    s << "if ! command -v ffmpeg >/dev/null; then\n"
      << "  echo \"ffmpeg is not installed on $(hostname); the frames are complete. Encode them with:\" >&2\n"
      << "  echo " << shellQuoted({video}) << " >&2\n"
      << "  exit 3\n"
      << "fi\n"
      << video << "\n";
  }
  return s.str();
}

std::optional<FarmRecord> readFarmRecord(const std::filesystem::path& renderScript) {
  std::ifstream in(renderScript);
  const std::string prefix = kRecordPrefix;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) != 0) continue;
    FarmRecord record;
    char dash = 0;
    std::istringstream fields(line.substr(prefix.size()));
    std::string tasks;
    if (!(fields >> record.frames.first >> dash >> record.frames.last >> tasks) || dash != '-' ||
        tasks.rfind("tasks=", 0) != 0)
      return std::nullopt;
    try {
      record.tasks = std::stoi(tasks.substr(6));
    } catch (const std::exception&) {
      return std::nullopt;
    }
    if (record.tasks < 1 || record.frames.first < 0 || record.frames.last < record.frames.first) return std::nullopt;
    return record;
  }
  return std::nullopt;
}

}  // namespace voxflame::app
