#include "grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "error.h"

namespace voxflame::core {

GridGeometry gridOverBox(const Box& box, int resolution, int marginVoxels) {
  if (resolution < kMinGridResolution || resolution > kMaxGridResolution)
    throw Error("grid resolution " + std::to_string(resolution) + " is outside the allowed range " +
                std::to_string(kMinGridResolution) + "–" + std::to_string(kMaxGridResolution));
  const glm::dvec3 extent = box.extent();
  const double longest = std::max({extent.x, extent.y, extent.z});
  if (!(longest > 0.0) || !std::isfinite(longest)) throw Error("cannot fit a grid to an empty box");
  GridGeometry grid;
  grid.voxelSize = longest / static_cast<double>(resolution - 2 * marginVoxels);
  for (int axis = 0; axis < 3; ++axis) {
    const int inner = std::max(1, static_cast<int>(std::ceil(extent[axis] / grid.voxelSize - 1e-9)));
    grid.size[axis] = std::min(resolution, inner + 2 * marginVoxels);
    // Centre the box inside the voxels it occupies.
    const double covered = grid.voxelSize * grid.size[axis];
    grid.origin[axis] = box.center()[axis] - 0.5 * covered;
  }
  return grid;
}

}  // namespace voxflame::core
