#include "chunk_sums.h"

#include <algorithm>

#include "error.h"
#include "scene_schema.h"

namespace voxflame::core {

void GridSums::reset(const GridGeometry& grid, const ColourLayout& layout) {
  geometry = grid;
  colour = layout;
  hits.assign(grid.voxelCount(), 0u);
  for (auto* sums : {&red, &green, &blue, &colourPoints}) sums->assign(layout.cellCount(), 0u);
  points = iterations = insideVoxels = 0;
}

void GridSums::add(const GridSums& other) {
  if (other.geometry.size != geometry.size || other.colour.shift != colour.shift || other.hits.size() != hits.size() ||
      other.red.size() != red.size())
    throw Error("cannot add a chunk of another grid");
  // Hit counts carry the mask's flag in their top bit in the accumulator, so a voxel holds at most
  // 2^31 - 1 points; the sums saturate there rather than wrap.
  constexpr std::uint32_t kMaxHits = 0x7fffffffu;
  for (std::size_t v = 0; v < hits.size(); ++v)
    hits[v] = static_cast<std::uint32_t>(
        std::min<std::uint64_t>(kMaxHits, static_cast<std::uint64_t>(hits[v]) + other.hits[v]));
  for (std::size_t c = 0; c < red.size(); ++c) {
    red[c] += other.red[c];
    green[c] += other.green[c];
    blue[c] += other.blue[c];
    colourPoints[c] += other.colourPoints[c];
  }
  points += other.points;
  iterations += other.iterations;
  insideVoxels = std::max(insideVoxels, other.insideVoxels);
}

GridSums readGridSums(const RefinementBackend& accumulator, const AccumulatorStats& stats) {
  GridSums sums;
  const GridGeometry& g = accumulator.mask().geometry;
  const ColourLayout colour = accumulator.colourLayout();
  sums.reset(g, colour);
  const std::size_t sliceCells = static_cast<std::size_t>(colour.size.x) * colour.size.y;
  GridReading reading;
  accumulator.readSlabs(reading, [&](const GridSlabView& slab) {
    if (slab.empty) return;
    for (int k = slab.firstZ; k < slab.endZ; ++k) {
      const std::uint32_t* hits = slab.hits + g.index(0, 0, k - slab.firstZ) * slab.hitsStride;
      std::uint32_t* out = &sums.hits[g.index(0, 0, k)];
      const std::size_t slice = static_cast<std::size_t>(g.size.x) * g.size.y;
      for (std::size_t v = 0; v < slice; ++v) out[v] = hits[v * slab.hitsStride] & ~detail::kOutsideBit;
    }
    for (int c = slab.firstColourZ; c < slab.endColourZ; ++c) {
      const detail::ColourCell* cells = slab.colours + sliceCells * static_cast<std::size_t>(c - slab.firstColourZ);
      const std::size_t base = sliceCells * static_cast<std::size_t>(c);
      for (std::size_t i = 0; i < sliceCells; ++i) {
        sums.red[base + i] = cells[i].red;
        sums.green[base + i] = cells[i].green;
        sums.blue[base + i] = cells[i].blue;
        sums.colourPoints[base + i] = detail::colourPoints(cells[i]);
      }
    }
  });
  sums.points = stats.points;
  sums.iterations = stats.iterations;
  sums.insideVoxels = reading.insideVoxels;
  return sums;
}

void snapshotFromSums(const GridSums& sums, VolumeSnapshot& out) {
  const GridGeometry& g = sums.geometry;
  const ColourLayout& colour = sums.colour;
  out.geometry = g;
  out.density.resize(g.voxelCount());
  out.rgba.resize(4 * g.voxelCount());
  float maxDensity = 0.0f;
  for (int k = 0; k < g.size.z; ++k)
    for (int j = 0; j < g.size.y; ++j) {
      const std::size_t row = g.index(0, j, k);
      const std::size_t cellRow = static_cast<std::size_t>(colour.size.x) *
                                  ((j >> colour.shift) + static_cast<std::size_t>(colour.size.y) * (k >> colour.shift));
      for (int i = 0; i < g.size.x; ++i) {
        const std::uint32_t count = sums.hits[row + i];
        out.density[row + i] = static_cast<float>(count);
        maxDensity = std::max(maxDensity, out.density[row + i]);
        const std::size_t cell = cellRow + static_cast<std::size_t>(i >> colour.shift);
        const std::uint64_t points = sums.colourPoints[cell];
        std::uint8_t* rgba = &out.rgba[4 * (row + i)];
        // As Accumulator::snapshot: the mean colour of the points the cell's sums hold.
        if (count == 0 || points == 0) {
          rgba[0] = rgba[1] = rgba[2] = 0;
        } else {
          rgba[0] = static_cast<std::uint8_t>(std::min<std::uint64_t>(255u, sums.red[cell] / points));
          rgba[1] = static_cast<std::uint8_t>(std::min<std::uint64_t>(255u, sums.green[cell] / points));
          rgba[2] = static_cast<std::uint8_t>(std::min<std::uint64_t>(255u, sums.blue[cell] / points));
        }
        rgba[3] = 255;
      }
    }
  out.maxDensity = maxDensity;
  out.points = sums.points;
  out.insideVoxels = sums.insideVoxels;
  out.version = 1;
  out.generation = 1;
}

void ImageSums::reset(int newWidth, int newHeight, double newUnit) {
  width = newWidth;
  height = newHeight;
  unit = newUnit;
  counts.assign(4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0u);
  points = iterations = 0;
}

void ImageSums::add(const ImageSums& other) {
  if (other.width != width || other.height != height || other.counts.size() != counts.size() || other.unit != unit)
    throw Error("cannot add a chunk of another image");
  for (std::size_t i = 0; i < counts.size(); ++i) counts[i] = saturatingAdd(counts[i], other.counts[i]);
  points += other.points;
  iterations += other.iterations;
}

std::string describeLabelDifference(const ChunkLabel& expected, const ChunkLabel& found) {
  if (found.chunks != expected.chunks)
    return "it is one of " + std::to_string(found.chunks) + " chunks, this render has " +
           std::to_string(expected.chunks) + " (--chunks)";
  if (found.backend != expected.backend)
    return "it was refined by the " + found.backend + " backend, this render uses the " + expected.backend +
           " backend (--backend): one render's chunks all come from one backend";
  if (found.width != expected.width || found.height != expected.height)
    return "it was rendered at " + std::to_string(found.width) + "×" + std::to_string(found.height) +
           ", this render is " + std::to_string(expected.width) + "×" + std::to_string(expected.height);
  if (found.presetJson == expected.presetJson) return "";
  // Name what differs, as the explorer's undo names an edit.
  try {
    const SceneDiff difference =
        diff(sceneFromJson(found.presetJson, "(checkpoint)"), sceneFromJson(expected.presetJson, "(this render)"));
    if (!difference.empty()) {
      std::string paths;
      for (std::size_t i = 0; i < difference.paths.size() && i < 6; ++i) paths += (i ? ", " : "") + difference.paths[i];
      if (difference.paths.size() > 6) paths += ", …";
      return "it was rendered from another preset (differing in " + paths + ")";
    }
  } catch (const Error&) {
  }
  return "it was rendered from another preset";
}

}  // namespace voxflame::core
