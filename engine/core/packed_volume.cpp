#include "packed_volume.h"

#include <Imath/half.h>

#include <algorithm>

namespace voxflame::core {

std::uint16_t floatToHalf(float value) {
  return Imath::half(value).bits();
}

float halfToFloat(std::uint16_t bits) {
  Imath::half half;
  half.setBits(bits);
  return static_cast<float>(half);
}

namespace {

// Half floats end at 65504; a voxel that much denser than the mean is saturated, not infinite.
constexpr float kLargestHalf = 65504.0f;

// Sizes the buffers of `out` for a grid and clears the occupancy.
void prepare(PackedVolume& out, const GridGeometry& g, const ColourLayout& colour) {
  out.geometry = g;
  out.colour = colour;
  out.density.resize(g.voxelCount());
  out.colours.resize(4 * colour.cellCount());
  out.brickCount = (g.size + (kBrickSize - 1)) / kBrickSize;
  out.occupancy.assign(static_cast<std::size_t>(out.brickCount.x) * out.brickCount.y * out.brickCount.z, 0);
}

// A voxel's density reaches samples up to one voxel away (trilinear filtering), so every brick
// within one voxel of it must be marched.
void markBricks(PackedVolume& out, int i, int j, int k) {
  const GridGeometry& g = out.geometry;
  const int i0 = std::max(0, i - 1) / kBrickSize, i1 = std::min(g.size.x - 1, i + 1) / kBrickSize;
  const int j0 = std::max(0, j - 1) / kBrickSize, j1 = std::min(g.size.y - 1, j + 1) / kBrickSize;
  const int k0 = std::max(0, k - 1) / kBrickSize, k1 = std::min(g.size.z - 1, k + 1) / kBrickSize;
  for (int bk = k0; bk <= k1; ++bk)
    for (int bj = j0; bj <= j1; ++bj)
      for (int bi = i0; bi <= i1; ++bi)
        out.occupancy[static_cast<std::size_t>(bi) + static_cast<std::size_t>(out.brickCount.x) *
                                                         (bj + static_cast<std::size_t>(out.brickCount.y) * bk)] = 1;
}

// The empty distances from the occupancy: a forward and a backward raster pass over the bricks,
// each taking one more than the least distance among the 13 neighbours it has already visited.
// With every neighbour of the 3×3×3 block one step away, the two passes give the exact Chebyshev
// distance (a chamfer transform), in time linear in the bricks (128³ of them at 512³).
void finishOccupancy(PackedVolume& out) {
  const glm::ivec3 n = out.brickCount;
  const std::size_t count = out.occupancy.size();
  out.emptyDistance.resize(count);
  for (std::size_t b = 0; b < count; ++b) out.emptyDistance[b] = out.occupancy[b] ? 0 : kMaxEmptyDistance;
  const std::ptrdiff_t strideY = n.x, strideZ = static_cast<std::ptrdiff_t>(n.x) * n.y;
  auto pass = [&](int direction) {
    const int startX = direction > 0 ? 0 : n.x - 1, startY = direction > 0 ? 0 : n.y - 1,
              startZ = direction > 0 ? 0 : n.z - 1;
    for (int k = startZ; k >= 0 && k < n.z; k += direction)
      for (int j = startY; j >= 0 && j < n.y; j += direction)
        for (int i = startX; i >= 0 && i < n.x; i += direction) {
          const std::ptrdiff_t here = i + strideY * j + strideZ * k;
          std::uint8_t& distance = out.emptyDistance[static_cast<std::size_t>(here)];
          if (distance == 0) continue;
          int nearest = distance;
          // The visited neighbours: the whole slice behind (dz = −direction), the row behind in
          // this slice (dy = −direction), and the voxel behind in this row.
          for (int dz = -1; dz <= 0; ++dz)
            for (int dy = -1; dy <= 1; ++dy)
              for (int dx = -1; dx <= 1; ++dx) {
                if (dz == 0 && (dy > 0 || (dy == 0 && dx >= 0))) continue;
                const int x = i + dx * direction, y = j + dy * direction, z = k + dz * direction;
                if (x < 0 || y < 0 || z < 0 || x >= n.x || y >= n.y || z >= n.z) continue;
                nearest =
                    std::min(nearest, out.emptyDistance[static_cast<std::size_t>(x + strideY * y + strideZ * z)] + 1);
              }
          distance = static_cast<std::uint8_t>(std::min(nearest, kMaxEmptyDistance));
        }
  };
  pass(+1);
  pass(-1);
}

void writeColour(std::uint16_t* texel, float weight, float red, float green, float blue) {
  texel[0] = floatToHalf(weight * red);
  texel[1] = floatToHalf(weight * green);
  texel[2] = floatToHalf(weight * blue);
  texel[3] = floatToHalf(weight);
}

}  // namespace

std::size_t packedVolumeBytes(const GridGeometry& grid) {
  const ColourLayout colour = ColourLayout::of(grid);
  // Bricks hold an occupancy and an empty distance byte each.
  return grid.voxelCount() * sizeof(std::uint16_t) + colour.cellCount() * 4 * sizeof(std::uint16_t) +
         2 * grid.voxelCount() / (kBrickSize * kBrickSize * kBrickSize);
}

void packVolume(const VolumeSnapshot& snapshot, PackedVolume& out) {
  const GridGeometry& g = snapshot.geometry;
  ColourLayout perVoxel;
  perVoxel.size = g.size;
  prepare(out, g, perVoxel);
  out.device.reset();
  out.packedFromGrid = 0;
  out.version = snapshot.version;
  out.generation = snapshot.generation;
  out.points = snapshot.points;
  out.maxDensity = snapshot.maxDensity;
  // The mean over the inside voxels first: it is the normalisation of every texel.
  double densitySum = 0.0;
  std::size_t occupied = 0;
  for (const float density : snapshot.density)
    if (density > 0.0f) {
      densitySum += density;
      ++occupied;
    }
  out.meanDensity = occupied ? static_cast<float>(densitySum / static_cast<double>(occupied)) : 0.0f;
  out.insideVoxels = static_cast<double>(snapshot.insideVoxels ? snapshot.insideVoxels : occupied);
  out.referenceDensity = out.insideVoxels > 0.0 && densitySum > 0.0 ? densitySum / out.insideVoxels : 1.0;
  out.texelDensity = static_cast<float>(out.referenceDensity);
  const float inverseScale = 1.0f / out.texelDensity;
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j)
      for (int i = 0; i < g.size.x; ++i) {
        const std::size_t v = g.index(i, j, k);
        std::uint16_t* texel = &out.colours[4 * v];
        const float density = snapshot.density[v];
        if (density <= 0.0f) {
          texel[0] = texel[1] = texel[2] = texel[3] = 0;
          out.density[v] = 0;
          continue;
        }
        const float weight = std::min(density * inverseScale, kLargestHalf);
        const std::uint8_t* rgba = &snapshot.rgba[4 * v];
        constexpr float kByte = 1.0f / 255.0f;
        writeColour(texel, weight, rgba[0] * kByte, rgba[1] * kByte, rgba[2] * kByte);
        out.density[v] = texel[3];
        markBricks(out, i, j, k);
      }
  finishOccupancy(out);
}

bool packVolume(const RefinementBackend& accumulator, PackedVolume& out, const std::atomic<bool>* cancel) {
  if (accumulator.packOnDevice(out)) return true;
  return packVolumeOnHost(accumulator, out, cancel);
}

bool packVolumeOnHost(const RefinementBackend& accumulator, PackedVolume& out, const std::atomic<bool>* cancel) {
  out.device.reset();
  const GridGeometry& g = accumulator.mask().geometry;
  const ColourLayout& colour = accumulator.colourLayout();
  prepare(out, g, colour);
  const std::uint64_t packedBefore = out.packedFromGrid;
  out.packedFromGrid = 0;  // until this pack is complete
  GridReading reading;
  float inverseScale = 1.0f;
  bool first = true;
  double densitySum = 0.0;
  std::size_t occupied = 0;
  float maxDensity = 0.0f;
  std::vector<float> cellWeights;
  const std::size_t sliceCells = static_cast<std::size_t>(colour.size.x) * colour.size.y;
  const int span = 1 << colour.shift;
  const float inverseCellVoxels = 1.0f / static_cast<float>(span * span * span);
  constexpr float kByte = 1.0f / 255.0f;
  bool cancelled = false;
  accumulator.readSlabs(reading, [&](const GridSlabView& slab) {
    if (cancelled || (cancel && cancel->load(std::memory_order_relaxed))) {
      cancelled = true;
      return;
    }
    if (first) {
      // Texels hold density relative to the mesh's mean: the hits the grid holds (its points
      // when the reading began; the few added while it runs change the picture by a hair) over
      // the voxels inside the mesh.
      const double inside = static_cast<double>(std::max<std::uint64_t>(reading.insideVoxels, 1));
      out.referenceDensity = reading.points > 0 ? static_cast<double>(reading.points) / inside : 1.0;
      out.insideVoxels = inside;
      out.texelDensity = static_cast<float>(out.referenceDensity);
      inverseScale = 1.0f / out.texelDensity;
      first = false;
    }
    // Rows with no voxel inside the mesh never hold density; a buffer this grid packed before
    // holds their zeros already.
    const bool outsideRowsAreZero = packedBefore == reading.gridId;
    const int cellSlices = slab.endColourZ - slab.firstColourZ;
    cellWeights.assign(sliceCells * static_cast<std::size_t>(cellSlices), 0.0f);
    for (int k = slab.firstZ; k < slab.endZ; ++k)
      for (int j = 0; j < g.size.y; ++j) {
        const std::uint32_t* hits = slab.hits + g.index(0, j, k - slab.firstZ) * slab.hitsStride;
        std::uint16_t* density = &out.density[g.index(0, j, k)];
        float* weights = &cellWeights[static_cast<std::size_t>(colour.size.x) *
                                      ((j >> colour.shift) + static_cast<std::size_t>(colour.size.y) *
                                                                 ((k >> colour.shift) - slab.firstColourZ))];
        const bool inside =
            slab.rowInside[static_cast<std::size_t>(j) + static_cast<std::size_t>(g.size.y) * (k - slab.firstZ)] != 0;
        if (!inside && outsideRowsAreZero) continue;
        if (slab.empty || !inside) {
          std::fill(density, density + g.size.x, std::uint16_t{0});
          continue;
        }
        for (int i = 0; i < g.size.x; ++i) {
          const std::uint32_t count = hits[i * slab.hitsStride] & ~detail::kOutsideBit;
          if (count == 0) {
            density[i] = 0;
            continue;
          }
          const float weight = std::min(static_cast<float>(count) * inverseScale, kLargestHalf);
          density[i] = floatToHalf(weight);
          weights[i >> colour.shift] += weight;
          densitySum += count;
          ++occupied;
          maxDensity = std::max(maxDensity, static_cast<float>(count));
          markBricks(out, i, j, k);
        }
      }
    std::uint16_t* texels = &out.colours[4 * sliceCells * static_cast<std::size_t>(slab.firstColourZ)];
    for (std::size_t c = 0; c < cellWeights.size(); ++c) {
      const detail::ColourCell& cell = slab.colours[c];
      // The cell's weight is its voxels' mean density: what the trilinear blend between
      // neighbouring cells weighs their colours by.
      const float weight = std::min(cellWeights[c] * inverseCellVoxels, kLargestHalf);
      const std::uint32_t points = detail::colourPoints(cell);
      if (weight <= 0.0f || points == 0) {
        std::fill(texels + 4 * c, texels + 4 * c + 4, std::uint16_t{0});
        continue;
      }
      const float toMean = kByte / static_cast<float>(points);
      writeColour(texels + 4 * c, weight, static_cast<float>(cell.red) * toMean,
                  static_cast<float>(cell.green) * toMean, static_cast<float>(cell.blue) * toMean);
    }
  });
  if (cancelled) {
    // The rows this grid leaves outside its mask are only ever zeros, so a buffer it packed
    // before still holds zeros there; any other buffer holds, in the slabs skipped, another grid's.
    out.packedFromGrid = packedBefore == reading.gridId ? packedBefore : 0;
    return false;
  }
  out.version = reading.version;
  out.generation = reading.generation;
  out.points = reading.points;
  out.packedFromGrid = reading.gridId;
  out.maxDensity = maxDensity;
  out.meanDensity = occupied ? static_cast<float>(densitySum / static_cast<double>(occupied)) : 0.0f;
  finishOccupancy(out);
  return true;
}

}  // namespace voxflame::core
