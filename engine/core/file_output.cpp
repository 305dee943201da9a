#include "file_output.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <vector>

#include "error.h"

namespace voxflame::core {

namespace {

// "<name>.<pid>-<n>.part": unique among processes and threads writing the same file at once, so
// each writes a whole file of its own and the last rename wins.
constexpr std::string_view kTemporarySuffix = ".part";

std::atomic<unsigned> temporaryCounter{0};

Error failure(const std::filesystem::path& path, const AtomicWriteOptions& options, const std::string& reason) {
  return Error(options.what + " '" + path.string() + "': " + reason);
}

std::string reasonFor(int error) {
  if (error == ENOENT) return "the folder is missing";
  if (error == EACCES || error == EROFS) return "the folder is not writable";
  if (error == ENOSPC || error == EDQUOT) return "the disk is full";
  return std::strerror(error);
}

// Creates the temporary (empty, exclusively ours) and returns its open descriptor.
int createTemporary(const std::filesystem::path& path, const AtomicWriteOptions& options,
                    std::filesystem::path& temporary) {
  if (options.createFolder && path.has_parent_path()) {
    std::error_code ec;
    std::filesystem::create_directories(path.parent_path(), ec);
  }
  for (int attempt = 0;; ++attempt) {
    // Appended piece by piece: one long concatenation trips GCC 12's false -Wrestrict (bug 105329).
    std::string tag = ".";
    tag += std::to_string(::getpid());
    tag += '-';
    tag += std::to_string(temporaryCounter.fetch_add(1));
    tag += kTemporarySuffix;
    temporary = path;
    temporary += tag;
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, options.mode);
    if (fd >= 0) return fd;
    if (errno != EEXIST || attempt >= 100) throw failure(path, options, reasonFor(errno));
  }
}

void removeQuietly(const std::filesystem::path& temporary) {
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
}

// Flushes the finished temporary to disk and renames it over `path`; removes it on failure.
void commit(const std::filesystem::path& temporary, int fd, const std::filesystem::path& path,
            const AtomicWriteOptions& options) {
  // Durable before the rename, so a power cut leaves the old file or the new one, never an empty one.
  const bool synced = ::fsync(fd) == 0;
  const int syncError = errno;
  const bool closed = ::close(fd) == 0;
  const int closeError = errno;
  if (!synced || !closed) {
    removeQuietly(temporary);
    throw failure(path, options, reasonFor(synced ? closeError : syncError));
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    removeQuietly(temporary);
    throw failure(path, options, "could not move it into place (" + ec.message() + ")");
  }
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes, const AtomicWriteOptions& options) {
  std::filesystem::path temporary;
  const int fd = createTemporary(path, options, temporary);
  std::size_t written = 0;
  while (written < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      const int error = n < 0 ? errno : ENOSPC;
      ::close(fd);
      removeQuietly(temporary);
      throw failure(path, options, reasonFor(error));
    }
    written += static_cast<std::size_t>(n);
  }
  commit(temporary, fd, path, options);
}

void writeFileAtomicallyWith(const std::filesystem::path& path, const WriteToPath& write,
                             const AtomicWriteOptions& options) {
  std::filesystem::path temporary;
  ::close(createTemporary(path, options, temporary));
  try {
    write(temporary);
  } catch (const Error&) {
    removeQuietly(temporary);
    throw;
  } catch (const std::exception& e) {
    removeQuietly(temporary);
    throw failure(path, options, e.what());
  }
  // The writer has closed its own handle; fsync through a new one reaches the same file's data.
  const int fd = ::open(temporary.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    removeQuietly(temporary);
    throw failure(path, options, reasonFor(error));
  }
  commit(temporary, fd, path, options);
}

std::string atomicTemporaryTarget(std::string_view fileName) {
  if (!fileName.ends_with(kTemporarySuffix)) return {};
  const std::string_view stem = fileName.substr(0, fileName.size() - kTemporarySuffix.size());
  const std::size_t dot = stem.rfind('.');
  if (dot == std::string_view::npos || dot == 0) return {};
  const std::string_view tag = stem.substr(dot + 1);  // "<pid>-<n>"
  const std::size_t dash = tag.find('-');
  const auto digits = [](std::string_view s) {
    return !s.empty() && s.find_first_not_of("0123456789") == std::string_view::npos;
  };
  if (dash == std::string_view::npos || !digits(tag.substr(0, dash)) || !digits(tag.substr(dash + 1))) return {};
  return std::string(stem.substr(0, dot));
}

void removeAtomicTemporaries(const std::filesystem::path& path, pid_t writer) {
  const std::string name = path.filename().string();
  std::string prefix = name;
  prefix += '.';
  prefix += std::to_string(writer);
  prefix += '-';
  std::error_code ec;
  const std::filesystem::path folder = path.has_parent_path() ? path.parent_path() : std::filesystem::path(".");
  std::vector<std::filesystem::path> left;
  for (const auto& item : std::filesystem::directory_iterator(folder, ec)) {
    const std::string candidate = item.path().filename().string();
    if (candidate.starts_with(prefix) && atomicTemporaryTarget(candidate) == name) left.push_back(item.path());
  }
  for (const auto& temporary : left) removeQuietly(temporary);
}

}  // namespace voxflame::core
