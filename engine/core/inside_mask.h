// The inside mask says, per voxel of a GridGeometry, whether the voxel centre lies inside the
// mesh. Patterns are only ever accumulated where the mask is set, so the mask *is* the shape the
// user sees. Computed once per (mesh, grid) and shared read-only by every worker thread.
#pragma once

#include <cstdint>
#include <vector>

#include "grid.h"
#include "mesh.h"

namespace voxflame::core {

enum class MaskMethod {
  Parity,  // crossings counted along +z columns; exact on closed meshes, wrong where they have holes
};

struct InsideMask {
  GridGeometry geometry;
  std::vector<std::uint8_t> inside;  // 1 inside, 0 outside; geometry.index order

  bool at(int i, int j, int k) const { return inside[geometry.index(i, j, k)] != 0; }
  double insideFraction() const;
};

InsideMask buildInsideMask(const TriangleMesh& mesh, const GridGeometry& grid, MaskMethod method = MaskMethod::Parity);

}  // namespace voxflame::core
