#include "progress_pipe.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <string>

#include "usage_error.h"

namespace voxflame::app {

ProgressPipe::ProgressPipe(int fd, std::atomic<bool>& gone) : fd_(fd), gone_(gone) {
  if (fd_ >= 0) ::signal(SIGPIPE, SIG_IGN);
}

void ProgressPipe::report(std::string_view stage, double fraction) {
  if (fd_ < 0) return;
  char line[96];
  const int length = std::snprintf(line, sizeof line, "progress %.*s %.4f\n", static_cast<int>(stage.size()),
                                   stage.data(), std::clamp(fraction, 0.0, 1.0));
  if (length <= 0) return;
  std::size_t written = 0;
  const auto size = static_cast<std::size_t>(std::min<int>(length, static_cast<int>(sizeof line) - 1));
  while (written < size) {
    const ssize_t n = ::write(fd_, line + written, size - written);
    if (n > 0) {
      written += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;  // a signal (Ctrl-C) arrived; its handler has done what it must
    } else {
      // The reader is gone: nobody wants this render any more, and writing on would be
      // working for no one.
      gone_.store(true);
      fd_ = -1;
      return;
    }
  }
}

void checkProgressFd(int fd) {
  if (fd >= 0 && ::fcntl(fd, F_GETFD) < 0)
    throw UsageError("--progress-fd " + std::to_string(fd) + " is not an open file descriptor");
}

}  // namespace voxflame::app
