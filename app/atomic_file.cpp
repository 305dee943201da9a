#include "atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "core/error.h"

namespace voxflame::app {

void writeFileAtomically(const std::filesystem::path& file, const std::string& text, mode_t mode,
                         const std::string& temporarySuffix, const std::string& what) {
  std::error_code ec;
  std::filesystem::create_directories(file.parent_path(), ec);
  const std::filesystem::path temporary = file.string() + temporarySuffix;
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, mode);
  if (fd < 0) throw core::Error(what + " '" + temporary.string() + "': " + std::strerror(errno));
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  // Durable before the rename, so a power cut leaves the old file or the new one, never an empty one.
  const bool ok = written == text.size() && ::fsync(fd) == 0;
  const std::string reason = std::strerror(errno);
  ::close(fd);
  ec.clear();
  if (ok) std::filesystem::rename(temporary, file, ec);
  if (!ok || ec) {
    std::filesystem::remove(temporary, ec);
    throw core::Error(what + " '" + file.string() + "': " + (ok ? ec.message() : reason));
  }
}

}  // namespace voxflame::app
