#include "xdg_paths.h"

#include <cstdlib>

namespace voxflame::core {

std::filesystem::path xdgFolder(XdgKind kind) {
  const char* variable = "XDG_CACHE_HOME";
  std::filesystem::path fallback = ".cache";
  switch (kind) {
    case XdgKind::Cache:
      break;
    case XdgKind::Config:
      variable = "XDG_CONFIG_HOME";
      fallback = ".config";
      break;
    case XdgKind::State:
      variable = "XDG_STATE_HOME";
      fallback = std::filesystem::path(".local") / "state";
      break;
    case XdgKind::Data:
      variable = "XDG_DATA_HOME";
      fallback = std::filesystem::path(".local") / "share";
      break;
  }
  if (const char* xdg = std::getenv(variable); xdg && *xdg == '/') return std::filesystem::path(xdg) / "voxflame";
  if (const char* home = std::getenv("HOME"); home && *home) return std::filesystem::path(home) / fallback / "voxflame";
  return {};
}

}  // namespace voxflame::core
