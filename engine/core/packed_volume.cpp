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

void finishOccupancy(PackedVolume& out) {
  out.coarseCount = (out.brickCount + (kCoarseBricks - 1)) / kCoarseBricks;
  out.coarseOccupancy.assign(static_cast<std::size_t>(out.coarseCount.x) * out.coarseCount.y * out.coarseCount.z, 0);
  for (int k = 0; k < out.brickCount.z; ++k)
    for (int j = 0; j < out.brickCount.y; ++j)
      for (int i = 0; i < out.brickCount.x; ++i)
        if (out.occupancy[static_cast<std::size_t>(i) + static_cast<std::size_t>(out.brickCount.x) *
                                                            (j + static_cast<std::size_t>(out.brickCount.y) * k)])
          out.coarseOccupancy[static_cast<std::size_t>(i / kCoarseBricks) +
                              static_cast<std::size_t>(out.coarseCount.x) *
                                  (j / kCoarseBricks +
                                   static_cast<std::size_t>(out.coarseCount.y) * (k / kCoarseBricks))] = 1;
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
  return grid.voxelCount() * sizeof(std::uint16_t) + colour.cellCount() * 4 * sizeof(std::uint16_t) +
         grid.voxelCount() / (kBrickSize * kBrickSize * kBrickSize);
}

void packVolume(const VolumeSnapshot& snapshot, PackedVolume& out) {
  const GridGeometry& g = snapshot.geometry;
  ColourLayout perVoxel;
  perVoxel.size = g.size;
  prepare(out, g, perVoxel);
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

bool packVolume(const Accumulator& accumulator, PackedVolume& out, const std::atomic<bool>* cancel) {
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
