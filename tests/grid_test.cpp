#include <gtest/gtest.h>

#include "core/error.h"
#include "core/grid.h"
#include "core/inside_mask.h"

using namespace voxflame::core;

TEST(Grid, LongestAxisHasRequestedResolutionAndCubicVoxels) {
  const Box box{{0.0, 0.0, 0.0}, {2.0, 1.0, 0.5}};
  const GridGeometry grid = gridOverBox(box, 64);
  EXPECT_EQ(grid.size.x, 64);
  EXPECT_LE(grid.size.y, 64);
  EXPECT_NEAR(grid.voxelSize, 2.0 / 62.0, 1e-12);
  // The box sits inside the grid with at least one voxel of margin on every side.
  const Box covered = grid.box();
  for (int a = 0; a < 3; ++a) {
    EXPECT_LE(covered.min[a], box.min[a] - grid.voxelSize * 0.999);
    EXPECT_GE(covered.max[a], box.max[a] + grid.voxelSize * 0.999);
  }
}

TEST(Grid, RefusesResolutionOutOfRange) {
  const Box box{{0.0, 0.0, 0.0}, {1.0, 1.0, 1.0}};
  EXPECT_THROW(gridOverBox(box, 4), Error);
  EXPECT_THROW(gridOverBox(box, 5000), Error);
}

namespace {
// A closed axis-aligned cube [lo, hi]^3 as twelve outward-facing triangles.
TriangleMesh cube(float lo, float hi) {
  TriangleMesh mesh;
  for (int i = 0; i < 8; ++i) mesh.vertices.emplace_back((i & 1) ? hi : lo, (i & 2) ? hi : lo, (i & 4) ? hi : lo);
  mesh.triangles = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                    {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  return mesh;
}
}  // namespace

TEST(InsideMask, CubeFillsExactlyItsVoxels) {
  const TriangleMesh mesh = cube(0.0f, 1.0f);
  const GridGeometry grid = gridOverBox(mesh.bounds(), 34);  // 32 voxels across the cube
  const InsideMask mask = buildInsideMask(mesh, grid);
  std::size_t inside = 0;
  for (int k = 0; k < grid.size.z; ++k)
    for (int j = 0; j < grid.size.y; ++j)
      for (int i = 0; i < grid.size.x; ++i) {
        const glm::dvec3 c = grid.voxelCenter(i, j, k);
        const bool expected = c.x > 0 && c.x < 1 && c.y > 0 && c.y < 1 && c.z > 0 && c.z < 1;
        EXPECT_EQ(mask.at(i, j, k), expected) << i << " " << j << " " << k;
        inside += mask.at(i, j, k);
      }
  EXPECT_EQ(inside, 32u * 32u * 32u);
}
