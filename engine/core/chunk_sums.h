// A still split into chunks (`voxflame render --chunks K`): each chunk iterates its own seed streams
// for its share of the points, and what it adds is kept as raw integer sums. Integers add exactly in
// any order, so the finished image depends only on the preset, the size and K, never on which
// machine rendered which chunk, how many threads it used, or whether the render was resumed.
//
// The volume method's sums are the voxel grid's hit counts and colour sums (GridSums); the points
// method's are the screen histogram in fixed-point units (ImageSums). A checkpoint folder holds one
// file per finished chunk (chunk_io.h), labelled with what it belongs to (ChunkLabel).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/refinement/refinement_backend.h"
#include "grid.h"

namespace voxflame::core {

// The volume method's sums: per voxel the points that landed there, per colour cell (ColourLayout)
// the sums of their palette colours (linear RGB8) and how many points those sums hold.
struct GridSums {
  GridGeometry geometry;
  ColourLayout colour;
  std::vector<std::uint32_t> hits;                                   // per voxel (no outside flag)
  std::vector<std::uint64_t> red, green, blue;                       // per colour cell
  std::vector<std::uint64_t> colourPoints;                           // per colour cell
  std::uint64_t points = 0;                                          // points inside the mask
  std::uint64_t iterations = 0;                                      // orbit steps taken, transients included
  std::uint64_t insideVoxels = 0;                                    // voxels inside the mask
  void reset(const GridGeometry& grid, const ColourLayout& layout);  // zeros of this shape
  void add(const GridSums& other);                                   // throws core::Error when the shapes differ
};

// What a backend's grid holds now (the workers should be idle: a chunk reached its target).
GridSums readGridSums(const RefinementBackend& accumulator, const AccumulatorStats& stats);

// The snapshot a renderer draws: density = hits, colour = the mean of the colour sums, as
// Accumulator::snapshot makes it from the live grid (the two agree exactly on the same sums).
void snapshotFromSums(const GridSums& sums, VolumeSnapshot& out);

// The points method's sums: per pixel of the (supersampled) image, red, green, blue and density in
// fixed-point units of `unit` (saturating at 2^32 - 1, which makes saturation independent of order).
struct ImageSums {
  int width = 0, height = 0;
  std::vector<std::uint32_t> counts;  // 4 per pixel: red, green, blue, density
  double unit = 0.0;                  // D one count stands for
  std::uint64_t points = 0;           // points projected
  std::uint64_t iterations = 0;
  void reset(int width, int height, double unit);
  void add(const ImageSums& other);  // saturating; throws core::Error when the shapes differ
};

inline std::uint32_t saturatingAdd(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t sum = a + b;
  return sum < a ? 0xffffffffu : sum;
}

// What a chunk file belongs to, stored in its metadata: resuming refuses a file whose label differs
// from the render's, naming what differs.
struct ChunkLabel {
  std::string presetJson;  // the scene as rendered (core::sceneToJson)
  int width = 0, height = 0;
  int chunk = 0, chunks = 0;  // this chunk's index, of how many
  // The refinement backend that made it ("cpu" or "gpu", core::toString(BackendKind)): a render
  // adds up the chunks of one backend only. Chunks written before backends existed are the CPU's.
  std::string backend = "cpu";
};

// "" when `found` belongs to the render `expected` describes (the chunk index aside), else what
// differs, e.g. "it was rendered at 640×360, this render is 1280×720".
std::string describeLabelDifference(const ChunkLabel& expected, const ChunkLabel& found);

}  // namespace voxflame::core
