// Output files are written to a temporary in the same folder, flushed to disk (fsync) and renamed
// over their final path only when complete: a reader never sees half a file, and an interrupted
// write, a crash or a power cut leaves either the old file or the new one under the name the user
// asked for. This is the one place in voxflame that replaces a file; every writer goes through it.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <functional>
#include <string>
#include <string_view>

namespace voxflame::core {

struct AtomicWriteOptions {
  mode_t mode = 0644;                 // permissions of the new file, less the umask
  bool createFolder = false;          // create the file's folder (and its parents) first
  std::string what = "cannot write";  // how an error message starts: "<what> '<path>': <reason>"
};

// Makes `bytes` the whole content of `path`. On failure throws core::Error
// "<what> '<path>': <reason>"; the temporary is removed and `path` is left as it was.
void writeFileAtomically(const std::filesystem::path& path, std::string_view bytes,
                         const AtomicWriteOptions& options = {});

// For writers that open the file themselves (libpng, OpenEXR, OpenVDB): `write` is given the
// path of a fresh, empty temporary beside `path`, must write the complete file there, and throws
// when it cannot. Its core::Error passes through unchanged; any other exception becomes
// core::Error "<what> '<path>': <its message>". Either way the temporary is removed.
using WriteToPath = std::function<void(const std::filesystem::path& temporary)>;
void writeFileAtomicallyWith(const std::filesystem::path& path, const WriteToPath& write,
                             const AtomicWriteOptions& options = {});

// A process killed mid-write leaves its temporary behind. When `fileName` is the name of a
// temporary those functions create, the name of the file it was going to become; otherwise empty.
// A folder's owner uses it to clear what a crashed process left.
std::string atomicTemporaryTarget(std::string_view fileName);
// Removes the temporaries of `path` that process `writer` left (e.g. a child killed while
// writing it). Never throws.
void removeAtomicTemporaries(const std::filesystem::path& path, pid_t writer);

}  // namespace voxflame::core
