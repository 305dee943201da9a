#include "file_output.h"

#include "error.h"

namespace voxflame::core {

void moveIntoPlace(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (!ec) return;
  std::error_code ignored;
  std::filesystem::remove(temporary, ignored);
  throw Error("cannot write '" + path.string() + "': could not move it into place (" + ec.message() + ")");
}

}  // namespace voxflame::core
