#include "core/refinement/refinement_backend.h"

#include <atomic>
#include <optional>
#include <string>

#include "core/enum_names.h"
#include "core/error.h"

namespace voxflame::core {

ColourLayout ColourLayout::of(const GridGeometry& grid) {
  ColourLayout layout;
  layout.shift = grid.voxelCount() > kFullColourVoxels ? 1 : 0;
  const int span = 1 << layout.shift;
  layout.size = (grid.size + (span - 1)) / span;
  return layout;
}

std::uint64_t nextGridId() {
  static std::atomic<std::uint64_t> lastGridId{0};
  return ++lastGridId;
}

std::string_view toString(BackendKind kind) {
  return enumName(kBackendKindNames, kind);
}

BackendKind backendKindFromString(std::string_view name) {
  if (const std::optional<BackendKind> kind = enumFromName<BackendKind>(kBackendKindNames, name)) return *kind;
  std::string message = "unknown refinement backend '";
  message.append(name).append("' (expected ").append(quotedChoices(kBackendKindNames)).append(")");
  throw Error(message);
}

}  // namespace voxflame::core
