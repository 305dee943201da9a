// Replacing a small file so that a crash or power cut leaves either the old file or the new one,
// never a truncated one: write a temporary beside it, fsync, rename over it.
#pragma once

#include <sys/types.h>

#include <filesystem>
#include <string>

namespace voxflame::app {

// Writes `text` to `file` atomically (creating its folder) with permissions `mode`, through the
// temporary `file` + `temporarySuffix`. Throws core::Error "<what> '<file>': <reason>" when it
// cannot.
void writeFileAtomically(const std::filesystem::path& file, const std::string& text, mode_t mode,
                         const std::string& temporarySuffix, const std::string& what);

}  // namespace voxflame::app
