#include "grid.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "error.h"

namespace voxflame::core {

double physicalMemoryBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES);
  const long pageSize = sysconf(_SC_PAGE_SIZE);
  if (pages <= 0 || pageSize <= 0) return 0.0;
  return static_cast<double>(pages) * static_cast<double>(pageSize);
}

namespace {
std::string gibibytes(double bytes) {
  std::ostringstream text;
  text.precision(bytes < 1024.0 * 1024.0 * 1024.0 ? 2 : 1);
  text << std::fixed << bytes / (1024.0 * 1024.0 * 1024.0) << " GiB";
  return text.str();
}
}  // namespace

void checkGridFitsInMemory(const GridGeometry& grid, double bytesPerVoxel, double availableBytes) {
  const double physical = physicalMemoryBytes();
  if (availableBytes <= 0.0) availableBytes = 0.75 * physical;
  if (availableBytes <= 0.0) return;  // unknown: let the allocation decide
  const double needed = bytesPerVoxel * static_cast<double>(grid.voxelCount());
  if (needed > availableBytes)
    throw Error("a grid of " + std::to_string(grid.size.x) + "×" + std::to_string(grid.size.y) + "×" +
                std::to_string(grid.size.z) + " voxels needs about " + gibibytes(needed) +
                " of memory, more than this machine can spare (" + gibibytes(availableBytes) +
                "); choose a smaller grid resolution");
}

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
