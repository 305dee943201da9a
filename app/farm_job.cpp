#include "farm_job.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>

#include "core/error.h"
#include "core/file_output.h"
#include "programs.h"
#include "usage_error.h"

namespace voxflame::app {

namespace {

constexpr const char* kRecordPrefix = "# voxflame-farm frames=";

std::filesystem::path scriptFolder(const FarmJob& job) {
  return job.folder.empty() ? frameFolder(job.pattern, 0) : job.folder;
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
  std::vector<std::string> command = {job.binary, job.subcommand};
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
    << "# Written by voxflame " << job.subcommand << " --farm slurm. Each of the " << tasks
    << " array tasks renders one\n"
    << "# contiguous range of " << job.what << " " << job.frames.first << "-" << job.frames.last
    << (job.subcommand == "render"
            ? " into the checkpoint folder, each chunk with its own seed streams,\n"
              "# so the sum is the image one local run would make. Re-run a failed task alone with\n"
            : " with the same fit (locked to time 0) and the preset's seed,\n"
              "# so the frames are the files one local run would write. Re-run a failed task "
              "alone with\n")
    << "# sbatch --array=TASK " << renderScriptPath(job).string() << " (voxflame " << job.subcommand
    << " --status lists the missing " << job.what << ").\n"
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
    << "exec " << shellQuoted(command) << " " << job.rangeOption << " \"${ranges[$task]}\"\n";
  return s.str();
}

std::string finishJobScript(const FarmJob& job) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
    << "# Written by voxflame " << job.subcommand << " --farm slurm: runs when every task of the render job has ended\n"
    << "# (sbatch --dependency=afterany:JOB), checks that every " << (job.what == "chunks" ? "chunk" : "frame")
    << " exists";
  s << (!job.finishCommand.empty() ? ", sums the chunks and writes the image.\n"
        : job.videoCommand.empty() ? ".\n"
                                   : " and encodes the video.\n")
    << header(job, "voxflame-finish", logPath(job, "farm-finish-%j.log")) << "set -euo pipefail\n";
  std::vector<std::string> status = animateCommand(job);
  if (!job.statusArguments.empty()) {
    status.insert(status.end(), job.statusArguments.begin(), job.statusArguments.end());
  } else {
    status.insert(status.end(), {"--status", job.pattern, "--frames",
                                 std::to_string(job.frames.first) + "-" + std::to_string(job.frames.last)});
    // The frame numbers of the range depend on the rate.
    for (std::size_t i = 0; i + 1 < job.options.size(); ++i)
      if (job.options[i] == "--fps") status.insert(status.end(), {"--fps", job.options[i + 1]});
  }
  s << shellQuoted(status) << "\n";
  if (!job.finishCommand.empty()) s << shellQuoted(job.finishCommand) << "\n";
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

void printRerunAdvice(const FarmRecord& record, const std::vector<int>& missing,
                      const std::filesystem::path& renderScript) {
  // The tasks whose ranges hold a missing item: running them again alone fills the gaps.
  const std::vector<FrameRange> ranges = splitFrames(record.frames, record.tasks);
  std::vector<int> tasks;
  for (int item : missing)
    for (std::size_t task = 0; task < ranges.size(); ++task)
      if (item >= ranges[task].first && item <= ranges[task].last) tasks.push_back(static_cast<int>(task));
  if (tasks.empty()) return;
  std::string taskList = describeFrames(tasks);
  taskList.erase(std::remove(taskList.begin(), taskList.end(), ' '), taskList.end());
  std::printf("render them again with: sbatch --array=%s %s\n", taskList.c_str(),
              shellQuoted({renderScript.string()}).c_str());
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

// A partition name goes into a #SBATCH line: one word of the characters Slurm allows.
void checkPartition(const std::string& partition) {
  const bool plain = !partition.empty() && std::all_of(partition.begin(), partition.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.' || c == ',';
  });
  if (!plain)
    throw UsageError("--partition '" + partition + "' is not a Slurm partition name (letters, digits, _ - . ,)");
}

// Submits the render job, then the finish job to start when every render task has ended; returns
// the job ids. Throws core::Error when sbatch refuses.
namespace {

std::pair<std::string, std::string> submitFarmJob(const std::string& sbatch, const FarmJob& job) {
  const auto submit = [&](std::vector<std::string> arguments) {
    std::string output;
    const int status = runProgram(sbatch, arguments, &output);
    std::string id = output.substr(0, output.find_first_of(";\n"));
    if (status != 0 || id.empty() ||
        !std::all_of(id.begin(), id.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); }))
      throw core::Error("sbatch failed (exit status " + std::to_string(status) + ") submitting '" + arguments.back() +
                        "'" + (output.empty() ? "" : ": " + output));
    return id;
  };
  const std::string render = submit({"sbatch", "--parsable", renderScriptPath(job).string()});
  const std::string finish =
      submit({"sbatch", "--parsable", "--dependency=afterany:" + render, finishScriptPath(job).string()});
  return {render, finish};
}

}  // namespace

int writeFarmJob(const FarmJob& job, bool submit) {
  const std::vector<FrameRange> ranges = splitFrames(job.frames, job.tasks);
  const std::filesystem::path render = renderScriptPath(job);
  const std::filesystem::path finish = finishScriptPath(job);
  const core::AtomicWriteOptions script{.mode = 0755, .createFolder = true, .what = "cannot write the job script"};
  core::writeFileAtomically(render, renderJobScript(job), script);
  core::writeFileAtomically(finish, finishJobScript(job), script);
  std::string split;
  for (const FrameRange& range : ranges)
    split += (split.empty() ? "" : ", ") + std::to_string(range.first) + "-" + std::to_string(range.last);
  std::printf("wrote %s (%zu tasks: %s %s) and %s\n", render.c_str(), ranges.size(), job.what.c_str(), split.c_str(),
              finish.c_str());
  if (static_cast<int>(ranges.size()) < job.tasks)
    std::printf("(%d %s make %zu tasks, not %d)\n", job.frames.count(), job.what.c_str(), ranges.size(), job.tasks);
  const std::string by = "job=$(sbatch --parsable " + shellQuoted({render.string()}) +
                         ") && sbatch --dependency=afterany:${job%%;*} " + shellQuoted({finish.string()});
  if (!submit) {
    std::printf("submit them with:\n  %s\n", by.c_str());
    return 0;
  }
  const auto sbatch = findOnPath("sbatch");
  if (!sbatch) {
    std::cerr << "voxflame: --submit: sbatch is not installed (not found on PATH), so nothing was submitted; the job "
                 "scripts are written. On a machine of the cluster run:\n  "
              << by << "\n";
    return kFarmNotSubmittedStatus;
  }
  const auto [renderId, finishId] = submitFarmJob(*sbatch, job);
  std::printf("submitted job %s (%zu tasks) and job %s (after every task of %s has ended); logs go beside the %s\n",
              renderId.c_str(), ranges.size(), finishId.c_str(), renderId.c_str(),
              job.subcommand == "render" ? "chunks" : "frames");
  std::printf("see what is missing with: voxflame %s --status %s\n", job.subcommand.c_str(),
              shellQuoted({job.pattern}).c_str());
  return 0;
}

}  // namespace voxflame::app
