// The explorer's export: a still rendered by a child process, the same binary's `render`
// subcommand, so the explorer's GL context, memory and frame rate are untouched and a crash or an
// out-of-memory in the export cannot take the explorer (and the user's scene) down with it.
//
// The scene goes to the child as a temporary preset (a relative mesh path made absolute, so it
// still finds its mesh; the embedded default stays embedded). The child reports progress through
// `render --progress-fd` on a pipe; its stdout carries the summary line, its stderr the error.
// Every call returns at once: the UI thread calls poll() once a frame and draws the result.
// One ExportJob runs one child at a time and belongs to one thread (the UI's).
#pragma once

#include <sys/types.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/scene.h"

namespace voxflame::app {

enum class ExportFormat { Png8, Png16, Exr };
const char* toString(ExportFormat format);                                   // "png8", "png16", "exr"
bool exportFormatFromString(const std::string& name, ExportFormat& format);  // false if unknown
const char* extensionOf(ExportFormat format);                                // ".png" or ".exr"
// `path` with the extension its format needs (replaced when it has another one).
std::filesystem::path withExtensionFor(const std::filesystem::path& path, ExportFormat format);

// What the export panel edits (and the settings file remembers).
struct ExportSettings {
  int width = 1920;          // 1–65536
  int height = 1080;         // 1–65536
  int samples = 4;           // jittered sub-samples per pixel, 1–1024
  std::uint64_t points = 0;  // points to accumulate; 0: the scene's own count
  ExportFormat format = ExportFormat::Png8;
  int threads = 0;  // accumulation threads in the child; 0: all hardware threads
};

struct ExportRequest {
  core::Scene scene;
  std::filesystem::path output;  // its extension must match settings.format (withExtensionFor)
  ExportSettings settings;
  // The voxflame binary to run; empty: this process's own (/proc/self/exe). Tests pass the
  // built binary.
  std::filesystem::path executable;
};

enum class ExportState { Idle, Running, Done, Failed, Cancelled };
const char* toString(ExportState state);

struct ExportStatus {
  ExportState state = ExportState::Idle;
  std::string stage;             // Running: "starting", "loading", "accumulating", "rendering", "writing"
  double fraction = 0.0;         // Running: done within the stage, 0–1
  double overall = 0.0;          // 0–1 over the whole export (fixed stage weights: a progress bar)
  std::filesystem::path output;  // the image's path
  std::string summary;           // Done: the child's "wrote ..." line
  std::string warning;           // Done: e.g. fewer points landed inside the mesh than asked
  std::string error;             // Failed: the child's message (or how it died)
};

class ExportJob {
 public:
  ExportJob() = default;
  ~ExportJob();  // cancels a running export and reaps the child (at most about a second)
  ExportJob(const ExportJob&) = delete;
  ExportJob& operator=(const ExportJob&) = delete;

  // Starts the child and returns at once. Throws core::Error when the request is invalid (a value
  // out of range, an extension that does not match the format), when an export is already
  // running, or when the child cannot be started.
  void start(const ExportRequest& request);

  // Never blocks: reads what the child wrote since the last call and reaps it when it ended.
  // After Done, Failed or Cancelled the status stays until the next start().
  ExportStatus poll();

  // Asks the child to stop (SIGINT: it writes nothing) and returns at once; poll() reports
  // Cancelled when it has gone. A child that finished before the signal reached it reports
  // Done: its file is complete. One that ignores the signal is killed after a grace period.
  void cancel();

  // Blocks up to `timeout` until the child writes something or ends; returns whether it did (then
  // poll() has news). The child's end is seen through its pidfd, so it wakes at once even while a
  // grandchild keeps the pipes open. For callers with nothing else to wait for; the UI thread calls
  // poll() once a frame instead.
  bool waitForChange(std::chrono::milliseconds timeout);

  bool running() const { return pid_ > 0; }
  pid_t processId() const { return pid_; }  // the child's, while running; for diagnostics and tests

 private:
  void readPipes();
  void finish(std::optional<int> waitStatus);  // nullopt: the exit status is unknown
  void closeAll();
  void waitForExit(std::chrono::milliseconds timeout);  // the pidfd, up to `timeout`

  pid_t pid_ = -1;
  int pidFd_ = -1;  // readable once the child has ended (pidfd_open); -1 on kernels before 5.3
  int progressFd_ = -1;
  int outputFd_ = -1;
  std::filesystem::path presetFile_;
  std::string progressText_;  // bytes from the progress pipe not yet ending in a newline
  std::string outputText_;    // the child's stdout and stderr
  bool cancelRequested_ = false;
  std::chrono::steady_clock::time_point cancelTime_;
  ExportStatus status_;
};

}  // namespace voxflame::app
