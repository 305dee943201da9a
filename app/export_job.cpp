#include "export_job.h"

#include <fcntl.h>
#include <signal.h>
#include <poll.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <utility>
#include <vector>

#include "core/error.h"
#include "core/file_output.h"

extern char** environ;

namespace voxflame::app {

namespace {

// The child's descriptor for progress lines (after stdin, stdout and stderr).
constexpr int kChildProgressFd = 3;
// How long a cancelled child may take to stop before it is killed: it checks its flag every
// quarter second while accumulating and after each sub-sample while rendering.
constexpr auto kCancelGrace = std::chrono::seconds(2);
// The destructor waits less: the explorer is closing and the export's result is not wanted.
constexpr auto kDestructorGrace = std::chrono::milliseconds(1000);
// The child's stdout and stderr are kept up to this size (a usage text is about 2 kB).
constexpr std::size_t kMaxOutputText = 64 * 1024;

struct StageWeight {
  const char* name;
  double start, end;
};
// Rough shares of a typical export's time, for one progress bar over all stages.
constexpr std::array<StageWeight, 5> kStageWeights = {{{"starting", 0.0, 0.0},
                                                       {"loading", 0.0, 0.05},
                                                       {"accumulating", 0.05, 0.85},
                                                       {"rendering", 0.85, 0.98},
                                                       {"writing", 0.98, 1.0}}};

double overallFraction(const std::string& stage, double fraction) {
  for (const auto& weight : kStageWeights)
    if (stage == weight.name) return weight.start + (weight.end - weight.start) * std::clamp(fraction, 0.0, 1.0);
  return 0.0;
}

void closeFd(int& fd) {
  if (fd >= 0) ::close(fd);
  fd = -1;
}

std::string trimLine(std::string line) {
  while (!line.empty() && (line.back() == '\r' || line.back() == ' ')) line.pop_back();
  // The CLI's interactive progress rewrites one line with '\r'; keep what came last.
  if (const auto cr = line.rfind('\r'); cr != std::string::npos) line.erase(0, cr + 1);
  return line;
}

std::vector<std::string> linesOf(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(trimLine(line));
  return lines;
}

std::string signalName(int signal) {
  const char* name = ::strsignal(signal);
  return name ? std::string(name) : "signal " + std::to_string(signal);
}

// Reads what is there without waiting; false at end of file or on an error.
bool drain(int fd, std::string& into, std::size_t limit) {
  if (fd < 0) return false;
  std::array<char, 4096> buffer{};
  for (;;) {
    const ssize_t n = ::read(fd, buffer.data(), buffer.size());
    if (n > 0) {
      if (into.size() < limit) into.append(buffer.data(), std::min(static_cast<std::size_t>(n), limit - into.size()));
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    return n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK);
  }
}

void checkRange(const char* what, long long value, long long min, long long max) {
  if (value < min || value > max)
    throw core::Error(std::string("export ") + what + " is " + std::to_string(value) +
                      "; allowed: " + std::to_string(min) + " to " + std::to_string(max));
}

}  // namespace

const char* toString(ExportFormat format) {
  switch (format) {
    case ExportFormat::Png8:
      return "png8";
    case ExportFormat::Png16:
      return "png16";
    case ExportFormat::Exr:
      return "exr";
  }
  return "png8";
}

bool exportFormatFromString(const std::string& name, ExportFormat& format) {
  for (const ExportFormat candidate : {ExportFormat::Png8, ExportFormat::Png16, ExportFormat::Exr})
    if (name == toString(candidate)) {
      format = candidate;
      return true;
    }
  return false;
}

const char* extensionOf(ExportFormat format) {
  return format == ExportFormat::Exr ? ".exr" : ".png";
}

std::filesystem::path withExtensionFor(const std::filesystem::path& path, ExportFormat format) {
  std::filesystem::path result = path;
  result.replace_extension(extensionOf(format));
  return result;
}

const char* toString(ExportState state) {
  switch (state) {
    case ExportState::Idle:
      return "idle";
    case ExportState::Running:
      return "running";
    case ExportState::Done:
      return "done";
    case ExportState::Failed:
      return "failed";
    case ExportState::Cancelled:
      return "cancelled";
  }
  return "idle";
}

ExportJob::~ExportJob() {
  if (pid_ > 0) {
    ::kill(pid_, SIGINT);
    const auto deadline = std::chrono::steady_clock::now() + kDestructorGrace;
    int waitStatus = 0;
    pid_t reaped = 0;
    while ((reaped = ::waitpid(pid_, &waitStatus, WNOHANG)) == 0) {
      const auto left =
          std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
      if (left.count() <= 0) break;
      waitForExit(left);
    }
    if (reaped == 0) {
      ::kill(pid_, SIGKILL);
      while (::waitpid(pid_, &waitStatus, 0) < 0 && errno == EINTR) {
      }
      // Killed while writing, it may have left its temporary beside the output.
      core::removeAtomicTemporaries(status_.output, pid_);
    }
    pid_ = -1;
  }
  closeAll();
}

void ExportJob::waitForExit(std::chrono::milliseconds timeout) {
  if (pidFd_ < 0) {
    // No pidfd (a kernel before 5.3): nothing to wait on but time. The pipes are no help: they
    // read as closed (ready) for good once the child has shut them.
    ::poll(nullptr, 0, static_cast<int>(std::min<long long>(timeout.count(), 10)));
    return;
  }
  pollfd exit{pidFd_, POLLIN, 0};
  while (::poll(&exit, 1, static_cast<int>(timeout.count())) < 0 && errno == EINTR) {
  }
}

bool ExportJob::waitForChange(std::chrono::milliseconds timeout) {
  if (pid_ <= 0) return false;
  std::array<pollfd, 3> fds{};
  nfds_t count = 0;
  for (const int fd : {pidFd_, progressFd_, outputFd_})
    if (fd >= 0) fds[count++] = pollfd{fd, POLLIN, 0};
  int ready = 0;
  while ((ready = ::poll(fds.data(), count, static_cast<int>(timeout.count()))) < 0 && errno == EINTR) {
  }
  return ready > 0;
}

void ExportJob::closeAll() {
  closeFd(pidFd_);
  closeFd(progressFd_);
  closeFd(outputFd_);
  if (!presetFile_.empty()) {
    std::error_code ec;
    std::filesystem::remove(presetFile_, ec);
    presetFile_.clear();
  }
}

void ExportJob::start(const ExportRequest& request) {
  if (pid_ > 0) throw core::Error("an export is already running; cancel it or wait for it to finish");
  const ExportSettings& settings = request.settings;
  checkRange("width", settings.width, 1, 65536);
  checkRange("height", settings.height, 1, 65536);
  checkRange("samples", settings.samples, 1, 1024);
  checkRange("threads", settings.threads, 0, 1024);
  if (settings.points > (std::uint64_t{1} << 40))
    throw core::Error("export points is " + std::to_string(settings.points) + "; allowed: 0 to 2^40");
  if (request.output.empty()) throw core::Error("the export needs an output file");
  if (request.output.extension() != extensionOf(settings.format))
    throw core::Error("export file '" + request.output.string() + "' must end in " + extensionOf(settings.format) +
                      " for " + toString(settings.format));

  // A preset file in the temporary folder: its mesh path must not depend on where it lies.
  core::Scene scene = request.scene;
  if (!scene.embedded) scene.meshPath = std::filesystem::absolute(scene.resolvedMeshPath()).lexically_normal().string();
  const std::string json = core::sceneToJson(scene);
  std::string presetTemplate = (std::filesystem::temp_directory_path() / "voxflame-export-XXXXXX.json").string();
  const int presetFd = ::mkstemps(presetTemplate.data(), 5);
  if (presetFd < 0)
    throw core::Error("cannot create a temporary preset for the export in '" +
                      std::filesystem::temp_directory_path().string() + "': " + std::strerror(errno));
  std::size_t written = 0;
  while (written < json.size()) {
    const ssize_t n = ::write(presetFd, json.data() + written, json.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  ::close(presetFd);
  closeAll();
  presetFile_ = presetTemplate;
  if (written != json.size()) {
    closeAll();
    throw core::Error("cannot write the temporary preset '" + presetTemplate + "' for the export");
  }

  // Pipes are close-on-exec, so no other child (nor this one, but for the ends it is given) keeps them open.
  int progressPipe[2] = {-1, -1}, outputPipe[2] = {-1, -1};
  if (::pipe2(progressPipe, O_CLOEXEC) != 0 || ::pipe2(outputPipe, O_CLOEXEC) != 0) {
    const std::string reason = std::strerror(errno);
    for (int fd : {progressPipe[0], progressPipe[1], outputPipe[0], outputPipe[1]})
      if (fd >= 0) ::close(fd);
    closeAll();
    throw core::Error("cannot start the export: " + reason);
  }
  // Above the child's 0–3, so that none of the dup2s below is onto itself (that would keep
  // close-on-exec set).
  const auto lift = [](int& fd) {
    const int high = ::fcntl(fd, F_DUPFD_CLOEXEC, 10);
    if (high >= 0) {
      ::close(fd);
      fd = high;
    }
  };
  lift(progressPipe[1]);
  lift(outputPipe[1]);

  const std::filesystem::path executable = request.executable.empty() ? "/proc/self/exe" : request.executable;
  std::vector<std::string> args = {executable.string(),
                                   "render",
                                   presetFile_.string(),
                                   "-o",
                                   request.output.string(),
                                   "--width",
                                   std::to_string(settings.width),
                                   "--height",
                                   std::to_string(settings.height),
                                   "--samples",
                                   std::to_string(settings.samples),
                                   "--threads",
                                   std::to_string(settings.threads),
                                   "--progress-fd",
                                   std::to_string(kChildProgressFd)};
  if (settings.points) {
    args.push_back("--points");
    args.push_back(std::to_string(settings.points));
  }
  if (settings.format != ExportFormat::Exr) {
    args.push_back("--bit-depth");
    args.push_back(settings.format == ExportFormat::Png16 ? "16" : "8");
  }
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  // posix_spawn (vfork-like) rather than fork: the explorer may hold gigabytes of grid, whose
  // page tables a fork would copy on the UI thread.
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_adddup2(&actions, outputPipe[1], 1);
  posix_spawn_file_actions_adddup2(&actions, outputPipe[1], 2);
  posix_spawn_file_actions_adddup2(&actions, progressPipe[1], kChildProgressFd);
#if defined(__GLIBC__) && (__GLIBC__ > 2 || (__GLIBC__ == 2 && __GLIBC_MINOR__ >= 34))
  // Descriptors the explorer opened without close-on-exec (drivers, libraries) stay behind.
  posix_spawn_file_actions_addclosefrom_np(&actions, kChildProgressFd + 1);
#endif
  posix_spawnattr_t attributes;
  posix_spawnattr_init(&attributes);
  sigset_t none, defaults;
  sigemptyset(&none);
  sigemptyset(&defaults);
  for (int signal : {SIGINT, SIGTERM, SIGPIPE, SIGCHLD}) sigaddset(&defaults, signal);
  posix_spawnattr_setsigmask(&attributes, &none);
  posix_spawnattr_setsigdefault(&attributes, &defaults);
  posix_spawnattr_setflags(&attributes, POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
  pid_t pid = -1;
  const int spawned = ::posix_spawn(&pid, executable.c_str(), &actions, &attributes, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  posix_spawnattr_destroy(&attributes);
  ::close(progressPipe[1]);
  ::close(outputPipe[1]);
  if (spawned != 0) {
    ::close(progressPipe[0]);
    ::close(outputPipe[0]);
    closeAll();
    throw core::Error("cannot start the export with '" + executable.string() + "': " + std::strerror(spawned));
  }
  pid_ = pid;
  // Our own child, not yet reaped: its pid cannot have been reused.
  pidFd_ = static_cast<int>(::syscall(SYS_pidfd_open, pid, 0));  // close-on-exec by itself
  progressFd_ = progressPipe[0];
  outputFd_ = outputPipe[0];
  ::fcntl(progressFd_, F_SETFL, ::fcntl(progressFd_, F_GETFL) | O_NONBLOCK);
  ::fcntl(outputFd_, F_SETFL, ::fcntl(outputFd_, F_GETFL) | O_NONBLOCK);
  progressText_.clear();
  outputText_.clear();
  cancelRequested_ = false;
  status_ = ExportStatus{};
  status_.state = ExportState::Running;
  status_.stage = "starting";
  status_.output = request.output;
}

void ExportJob::readPipes() {
  drain(outputFd_, outputText_, kMaxOutputText);
  drain(progressFd_, progressText_, kMaxOutputText);
  std::size_t newline = 0;
  while ((newline = progressText_.find('\n')) != std::string::npos) {
    const std::string line = progressText_.substr(0, newline);
    progressText_.erase(0, newline + 1);
    std::istringstream in(line);
    std::string word, stage;
    double fraction = 0.0;
    if (!(in >> word >> stage >> fraction) || word != "progress") continue;
    status_.stage = stage;
    status_.fraction = std::clamp(fraction, 0.0, 1.0);
    // Never backwards, even if a stage's fraction is reported again.
    status_.overall = std::max(status_.overall, overallFraction(stage, status_.fraction));
  }
}

ExportStatus ExportJob::poll() {
  if (pid_ <= 0) return status_;
  readPipes();
  int waitStatus = 0;
  const pid_t reaped = ::waitpid(pid_, &waitStatus, WNOHANG);
  if (reaped == pid_) {
    finish(waitStatus);
  } else if (reaped < 0 && errno == ECHILD) {
    // Someone reaped it for us (SIGCHLD ignored): its output alone tells how it ended.
    finish(std::nullopt);
  } else if (cancelRequested_ && std::chrono::steady_clock::now() - cancelTime_ > kCancelGrace) {
    ::kill(pid_, SIGKILL);
  }
  return status_;
}

void ExportJob::finish(std::optional<int> waitStatus) {
  const pid_t child = std::exchange(pid_, -1);
  // The child has gone, so its ends of the pipes are closed: what is left can be read whole.
  readPipes();
  std::string summary, error, warning;
  for (const std::string& line : linesOf(outputText_)) {
    if (line.rfind("wrote ", 0) == 0) summary = line;
    constexpr std::string_view kWarning = "voxflame: warning: ";
    constexpr std::string_view kError = "voxflame: ";
    if (line.rfind(kWarning, 0) == 0)
      warning = line.substr(kWarning.size());
    else if (line.rfind(kError, 0) == 0 && error.empty())
      error = line.substr(kError.size());
  }
  const bool exited = waitStatus ? WIFEXITED(*waitStatus) : true;
  const int code = waitStatus ? (exited ? WEXITSTATUS(*waitStatus) : -1) : (summary.empty() ? 1 : 0);
  const int signal = waitStatus && WIFSIGNALED(*waitStatus) ? WTERMSIG(*waitStatus) : 0;
  if (exited && code == 0) {
    status_.state = ExportState::Done;
    status_.stage = "writing";
    status_.fraction = 1.0;
    status_.overall = 1.0;
    status_.summary = summary;
    status_.warning = warning;
  } else if (cancelRequested_ || (exited && code == 130) || signal == SIGINT || signal == SIGTERM) {
    status_.state = ExportState::Cancelled;
    if (signal == SIGKILL) core::removeAtomicTemporaries(status_.output, child);
  } else {
    status_.state = ExportState::Failed;
    if (!error.empty())
      status_.error = error;
    else if (signal)
      status_.error = "the export process died (" + signalName(signal) + ")";
    else
      status_.error = "the export process stopped with status " + std::to_string(code);
  }
  closeAll();
}

void ExportJob::cancel() {
  if (pid_ <= 0 || cancelRequested_) return;
  cancelRequested_ = true;
  cancelTime_ = std::chrono::steady_clock::now();
  ::kill(pid_, SIGINT);
}

}  // namespace voxflame::app
