// The voxel lattice over a mesh: cubic voxels, indexed x fastest, in the mesh file's coordinates.
// Every grid in voxflame (inside mask, accumulation, textures) shares one GridGeometry so that
// voxel (i, j, k) means the same place everywhere.
#pragma once

#include <cstddef>

#include <glm/vec3.hpp>

#include "mesh.h"

namespace voxflame::core {

inline constexpr int kMinGridResolution = 32;
inline constexpr int kMaxGridResolution = 1024;

struct GridGeometry {
  glm::ivec3 size{0};      // voxels along x, y, z
  glm::dvec3 origin{0.0};  // corner of voxel (0, 0, 0)
  double voxelSize = 1.0;  // edge of a (cubic) voxel

  std::size_t voxelCount() const {
    return static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * static_cast<std::size_t>(size.z);
  }
  std::size_t index(int i, int j, int k) const {
    return static_cast<std::size_t>(i) +
           static_cast<std::size_t>(size.x) *
               (static_cast<std::size_t>(j) + static_cast<std::size_t>(size.y) * static_cast<std::size_t>(k));
  }
  glm::dvec3 voxelCenter(int i, int j, int k) const { return origin + voxelSize * (glm::dvec3(i, j, k) + 0.5); }
  Box box() const { return {origin, origin + voxelSize * glm::dvec3(size)}; }
};

// Bytes of physical memory on this machine; 0 when it cannot be told.
double physicalMemoryBytes();

// Refuses, before anything is allocated, a grid whose buffers (bytesPerVoxel for every voxel)
// would not fit: core::Error says how much it would need. availableBytes 0 means three quarters
// of this machine's physical memory.
void checkGridFitsInMemory(const GridGeometry& grid, double bytesPerVoxel, double availableBytes = 0.0);

// A grid whose longest axis has `resolution` voxels, covering `box` plus `marginVoxels` on every
// side. Throws core::Error when resolution is outside [kMinGridResolution, kMaxGridResolution].
GridGeometry gridOverBox(const Box& box, int resolution, int marginVoxels = 1);

}  // namespace voxflame::core
