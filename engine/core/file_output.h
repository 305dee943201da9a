// Output files are written to a temporary beside their final path and moved into place when
// complete, so an interrupted or failed write never leaves a half-written file under the name
// the user asked for.
#pragma once

#include <filesystem>

namespace voxflame::core {

// Renames the finished `temporary` to `path`; on failure removes the temporary and throws
// core::Error naming `path`.
void moveIntoPlace(const std::filesystem::path& temporary, const std::filesystem::path& path);

}  // namespace voxflame::core
