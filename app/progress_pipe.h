// Machine-readable progress of `voxflame render --progress-fd N`: one line per report on file
// descriptor N, for a parent process (the explorer's export job) to parse:
//
//   progress <stage> <fraction>      stage: loading, accumulating, rendering, writing;
//                                    fraction in [0, 1], rising within a stage
//
// Human-readable messages stay on stdout ("wrote ...") and stderr ("voxflame: ...").
#pragma once

#include <atomic>
#include <string_view>

namespace voxflame::app {

class ProgressPipe {
 public:
  // fd < 0: inactive, report() does nothing. A reader that goes away (the parent died or closed
  // the pipe) raises `gone`, which the render treats as an interruption: nothing is written.
  // SIGPIPE is ignored while a pipe is active so that this is a failed write, not a killed
  // process.
  ProgressPipe(int fd, std::atomic<bool>& gone);

  bool active() const { return fd_ >= 0; }
  void report(std::string_view stage, double fraction);

 private:
  int fd_;
  std::atomic<bool>& gone_;
};

// Checks that `fd` is an open descriptor; throws UsageError naming --progress-fd otherwise.
void checkProgressFd(int fd);

}  // namespace voxflame::app
